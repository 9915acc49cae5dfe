// Every dock shows the studio document (issue 29): after another model, no dock still holds the last model's
// plan, job, pose or plane values, and the Hardware dock connects exactly the device entered.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

#include "hardware/hardware_test_support.h"
#include "multidir/core/search/pose_search.h"
#include "multidir/hardware/device_simulator.h"
#include "support/test_models.h"
#include "ui/device/connection_form.h"
#include "ui/device/device_link.h"
#include "ui/device/hardware_panel.h"
#include "ui/device/print_run_driver.h"
#include "ui/document/studio_document.h"
#include "ui/edit/plan_editor.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/plane_edit_panel.h"
#include "ui/panels/pose_search_box.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

constexpr int kConnectMs = 5000;  // the simulator answers within milliseconds

QString bunnyPath() { return QString::fromStdString(test::sharedModelPath("bunny.off")); }

HardwarePanel* hardwareOf(const MainWindow& window) { return window.findChild<HardwarePanel*>(); }

template <typename Widget>
Widget* named(const QWidget& parent, const char* name) {
  auto* found = parent.findChild<Widget*>(QString::fromLatin1(name));
  EXPECT_NE(found, nullptr) << name;
  return found;
}

// Connects the window's Hardware dock to `sim` as the device the form shows, at unit `unit`.
void connectTo(HardwarePanel& panel, const hardware::DeviceSimulator& sim, int unit) {
  panel.connectionForm()->setSettings(hardware::test::fastSettings(sim.port(), unit));
  QPushButton* connect = named<QPushButton>(panel, "connectButton");
  ASSERT_NE(connect, nullptr);
  QTest::mouseClick(connect, Qt::LeftButton);
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.deviceLink()->snapshot().state == DeviceState::Connected; },
                              kConnectMs))
      << panel.messageText().toStdString();
}

TEST(StudioDocumentViews, AfterAModelWithoutAPlanTheHardwareDockHasNothingToRun) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  hardware::DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  HardwarePanel* panel = hardwareOf(window);
  ASSERT_NE(panel, nullptr);
  ASSERT_EQ(panel->connectionForm()->kind(), DeviceKind::RobotArm);  // the 5-DOF machine's device
  ASSERT_NO_FATAL_FAILURE(connectTo(*panel, sim, 255));
  QPushButton* startRun = named<QPushButton>(*panel, "startRunButton");
  ASSERT_NE(startRun, nullptr);
  ASSERT_TRUE(startRun->isEnabled());  // the snowman's plan is there to run

  ASSERT_NO_FATAL_FAILURE(test::openModelFile(window, bunnyPath()));
  EXPECT_FALSE(window.plan().has_value());
  EXPECT_EQ(panel->planRegionCount(), 0);
  EXPECT_FALSE(startRun->isEnabled());
  EXPECT_EQ(named<QLabel>(*panel, "planSummaryText")->text(),
            QStringLiteral("No plan: run a search or open a plan first."));
  QTest::mouseClick(startRun, Qt::LeftButton);
  EXPECT_FALSE(panel->printRunDriver()->hasRun());
}

TEST(StudioDocumentViews, ConnectConnectsTheDeviceAndUnitEnteredNotTheMachinesDefault) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  ASSERT_EQ(window.machinePanel()->kind(), core::MachineKind::TiltRotate);  // the machine stays 5-DOF
  hardware::DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  HardwarePanel* panel = hardwareOf(window);
  ASSERT_NE(panel, nullptr);
  auto* device = named<QComboBox>(*panel, "deviceKind");
  ASSERT_NE(device, nullptr);
  device->setCurrentIndex(device->findText(QStringLiteral("Rotary platform (4-DOF)")));
  ASSERT_NO_FATAL_FAILURE(connectTo(*panel, sim, 1));

  const DeviceLinkSettings& connected = panel->deviceLink()->settings();
  EXPECT_EQ(connected.kind, DeviceKind::RotaryPlatform);
  EXPECT_EQ(connected.connection.slaveId, 1);
  EXPECT_EQ(panel->connectionForm()->kind(), DeviceKind::RotaryPlatform);
  EXPECT_EQ(named<QSpinBox>(*panel, "tcpUnit")->value(), 1);
}

TEST(StudioDocumentViews, NextModelOpensWithoutTheLastModelsPoseAndWithTheAxisTurnedBack) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  ASSERT_NO_FATAL_FAILURE(test::openModelFile(window, bunnyPath()));
  core::MachineSpec rotary = window.machinePanel()->machineSpec(core::Vec3::UnitZ());
  rotary.kind = core::MachineKind::RotaryPlatform;
  rotary.rotationAxis = core::Vec3::UnitX();
  window.machinePanel()->setMachineSpec(rotary);
  ASSERT_TRUE(window.machinePanel()->errorText().isEmpty()) << window.machinePanel()->errorText().toStdString();
  // "Use this pose": the machine turned with the pose, the up the pose's.
  UpPose pose;
  pose.up = core::Vec3(0.6, 0.0, 0.8);
  pose.pose.platformUp = core::Vec3::UnitZ();
  pose.pose.source = "hull-face";
  window.machinePanel()->setMachineSpec(core::machineForPose(rotary, pose.up));
  window.setUpPose(pose);
  auto* upBox = window.findChild<QComboBox*>(QStringLiteral("upBox"));
  ASSERT_NE(upBox, nullptr);
  ASSERT_TRUE(upBox->currentText().startsWith(QStringLiteral("Pose"))) << upBox->currentText().toStdString();

  ASSERT_NO_FATAL_FAILURE(test::openModelFile(window, QString::fromStdString(test::sharedModelPath("fertility.off"))));
  EXPECT_FALSE(window.upPose().has_value());
  EXPECT_EQ(window.upDirection(), core::Vec3::UnitZ());
  EXPECT_EQ(upBox->currentText(), QStringLiteral("+Z"));
  for (int i = 0; i < upBox->count(); ++i) EXPECT_FALSE(upBox->itemText(i).startsWith(QStringLiteral("Pose"))) << i;
  EXPECT_TRUE(window.machinePanel()->errorText().isEmpty()) << window.machinePanel()->errorText().toStdString();
  const std::optional<core::Vec3> axis = window.machinePanel()->rotationAxis();
  ASSERT_TRUE(axis.has_value());
  EXPECT_LT((*axis - core::Vec3::UnitX()).norm(), 1e-3);
  EXPECT_TRUE(named<QPushButton>(*window.machinePanel()->poseBox(), "findBestPose")->isEnabled());
}

// The Machine panel and the Up box show the document's machine and up, whoever changed them: here the
// document itself, not the panel or the box.
TEST(StudioDocumentViews, MachineAndUpSetInTheDocumentAreShownByTheMachinePanelAndTheUpBox) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  StudioDocument& document = *window.document();
  document.setUp(core::Vec3::UnitY());
  auto* upBox = window.findChild<QComboBox*>(QStringLiteral("upBox"));
  ASSERT_NE(upBox, nullptr);
  EXPECT_EQ(upBox->currentText(), QStringLiteral("+Y"));

  core::MachineSpec rotary = document.machine();
  rotary.kind = core::MachineKind::RotaryPlatform;
  rotary.rotationAxis = core::Vec3::UnitX();  // in the platform plane of +Y
  rotary.minAngleDegrees = -45.0;
  rotary.maxAngleDegrees = 60.0;
  document.setMachine(rotary);
  auto* kind = named<QComboBox>(*window.machinePanel(), "machineKind");
  ASSERT_NE(kind, nullptr);
  EXPECT_EQ(kind->currentData().toInt(), static_cast<int>(core::MachineKind::RotaryPlatform));
  const std::optional<core::Vec3> axis = window.machinePanel()->rotationAxis();
  ASSERT_TRUE(axis.has_value());
  EXPECT_LT((*axis - core::Vec3::UnitX()).norm(), 1e-9);
  EXPECT_DOUBLE_EQ(named<QDoubleSpinBox>(*window.machinePanel(), "minAngle")->value(), -45.0);
  EXPECT_DOUBLE_EQ(named<QDoubleSpinBox>(*window.machinePanel(), "maxAngle")->value(), 60.0);
  EXPECT_TRUE(window.machinePanel()->errorText().isEmpty()) << window.machinePanel()->errorText().toStdString();
  // The panel's machine is the document's, with the document's up.
  EXPECT_EQ(window.machinePanel()->machineSpec(document.up()).kind, core::MachineKind::RotaryPlatform);
  EXPECT_EQ(document.machine().up, core::Vec3::UnitY());
}

TEST(StudioDocumentViews, EditPlanFieldsShowNothingOfTheLastModelsPlan) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  window.planEditor()->selectPlane(0);
  auto* offset = named<QDoubleSpinBox>(*window.planeEditPanel(), "planeOffset");
  ASSERT_NE(offset, nullptr);
  ASSERT_FALSE(offset->cleanText().isEmpty());

  ASSERT_NO_FATAL_FAILURE(test::openModelFile(window, bunnyPath()));
  EXPECT_FALSE(offset->isEnabled());
  EXPECT_EQ(offset->cleanText(), QString());
  for (const char* name : {"planeTilt", "planeAzimuth", "planeRotary"})
    EXPECT_EQ(named<QDoubleSpinBox>(*window.planeEditPanel(), name)->cleanText(), QString()) << name;
  EXPECT_EQ(named<QTableWidget>(*window.planeEditPanel(), "planeTable")->rowCount(), 0);
}

// Issue 29 [cosmetic]: the toolbar's E-STOP, shown once a device is connected, does not push the view down.
TEST(StudioEmergencyStopToolbar, ConnectingLeavesTheViewWhereItWas) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  hardware::DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  HardwarePanel* panel = hardwareOf(window);
  ASSERT_NE(panel, nullptr);
  QCoreApplication::processEvents();
  const QRect before = window.viewer()->geometry();
  ASSERT_NO_FATAL_FAILURE(connectTo(*panel, sim, 255));
  auto* estop = window.findChild<QPushButton*>(QStringLiteral("windowEstopButton"));
  ASSERT_NE(estop, nullptr);
  ASSERT_TRUE(test::waitUntil([&] { return estop->isVisible(); }));
  QCoreApplication::processEvents();
  EXPECT_EQ(window.viewer()->geometry().top(), before.top());
  EXPECT_EQ(window.viewer()->geometry().height(), before.height());
}

}  // namespace
}  // namespace multidir::ui
