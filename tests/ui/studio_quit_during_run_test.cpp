// Quitting the studio while a print run is under way: the run is asked about first and the devices are stopped
// before anything else (the unsaved-changes question comes after), and Cancel keeps the window and the run.
#include <gtest/gtest.h>

#include <QMessageBox>
#include <QPushButton>
#include <QTest>
#include <memory>

#include "ui/device/connection_form.h"
#include "ui/device/device_link.h"
#include "ui/device/hardware_panel.h"
#include "ui/device/print_run_driver.h"
#include "ui/document/studio_document.h"
#include "ui/hardware_panel_fixture.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/project/project_session.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

// A studio window whose Hardware dock runs a three-region 4-DOF plan on the simulated rotary platform, the
// run waiting at its first region.
class StudioQuitDuringRun : public ::testing::Test {
 protected:
  void SetUp() override {
    test::resetStudioSettings();
    ASSERT_TRUE(sim.start().ok());
    core::MachineSpec profile;
    profile.kind = core::MachineKind::RotaryPlatform;
    profile.minAngleDegrees = -60.0;
    profile.maxAngleDegrees = 60.0;
    profile.angleStepDegrees = 1.0;
    window = std::make_unique<MainWindow>();
    // A model shown, so that there is a project whose changes can be unsaved.
    ASSERT_NO_FATAL_FAILURE(test::openSample(*window, QStringLiteral("snowman")));
    window->machinePanel()->setMachineSpec(profile);
    SearchRun run;
    run.plan = std::make_shared<const core::Decomposition>(planWithAngles({0.0, 10.0, 20.0}));
    window->document()->setPlan(run);
    panel = window->hardwarePanel();
    panel->connectionForm()->setKind(DeviceKind::RotaryPlatform);
    panel->connectionForm()->setSettings(fastSettings(sim.port()));
    panel->connectionForm()->setRotarySpeedDegreesPerSecond(60.0);
    hardware::PrintRunOptions runOptions;
    runOptions.settleTime = std::chrono::milliseconds(50);
    panel->setPrintRunOptions(runOptions);
    window->resize(1400, 900);
    window->show();

    press("connectButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->deviceLink()->snapshot().state == DeviceState::Connected; }, kWaitMs));
    press("enableButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->deviceLink()->snapshot().enabled; }, kWaitMs));
    press("homeButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->deviceLink()->snapshot().homed; }, kWaitMs));
    press("startRunButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->promptText().contains(QStringLiteral("region-01.stl")); }, kWaitMs))
        << panel->messageText().toStdString();
    ASSERT_TRUE(panel->isRunUnderWay());
  }

  void press(const char* name) {
    auto* button = panel->findChild<QPushButton*>(QString::fromLatin1(name));
    ASSERT_NE(button, nullptr) << name;
    ASSERT_TRUE(button->isEnabled()) << name << ": " << panel->messageText().toStdString();
    QTest::mouseClick(button, Qt::LeftButton);
  }

  hardware::DeviceSimulator sim;
  std::unique_ptr<MainWindow> window;
  HardwarePanel* panel = nullptr;
};

TEST_F(StudioQuitDuringRun, QuittingAsksAboutTheRunAndCancelKeepsTheWindowAndTheRun) {
  window->close();
  QMessageBox* box = test::waitForMessageBox(*window, QStringLiteral("printRunQuitBox"));
  ASSERT_NE(box, nullptr) << "quitting during a print run should ask about the run";
  EXPECT_TRUE(box->text().contains(QStringLiteral("1 of 3"))) << box->text().toStdString();
  box->button(QMessageBox::Cancel)->click();
  QTest::qWait(100);
  EXPECT_TRUE(window->isVisible());
  EXPECT_TRUE(panel->isRunUnderWay());
  EXPECT_EQ(panel->printRunDriver()->state(), hardware::PrintRunState::Printing);
}

TEST_F(StudioQuitDuringRun, QuittingStopsTheDevicesBeforeTheUnsavedChangesQuestion) {
  window->machinePanel()->setMachineSpec([] {
    core::MachineSpec wider;
    wider.kind = core::MachineKind::RotaryPlatform;
    wider.minAngleDegrees = -70.0;
    wider.maxAngleDegrees = 70.0;
    wider.angleStepDegrees = 1.0;
    return wider;
  }());
  ASSERT_TRUE(window->projectSession()->isModified()) << "the test needs a changed project";

  window->close();
  QMessageBox* box = test::waitForMessageBox(*window, QStringLiteral("printRunQuitBox"));
  ASSERT_NE(box, nullptr);
  auto* stop = box->findChild<QPushButton*>(QStringLiteral("stopDevicesAndQuit"));
  ASSERT_NE(stop, nullptr);
  stop->click();

  QMessageBox* unsaved = test::waitForMessageBox(*window, QStringLiteral("unsavedChangesBox"));
  ASSERT_NE(unsaved, nullptr) << "the unsaved-changes question should follow";
  // By then the run was aborted and the platform stopped: Discard can no longer drop a live run.
  EXPECT_FALSE(panel->isRunUnderWay());
  EXPECT_EQ(panel->printRunDriver()->state(), hardware::PrintRunState::Aborted);
  EXPECT_FALSE(sim.rotaryState().moving);
  unsaved->button(QMessageBox::Discard)->click();
  EXPECT_TRUE(QTest::qWaitFor([&] { return !window->isVisible(); }, kWaitMs));
}

}  // namespace
}  // namespace multidir::ui
