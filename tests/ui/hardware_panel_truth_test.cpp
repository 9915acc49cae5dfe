// The Hardware panel tells the truth about the device: nothing made up before the first read, every value
// marked stale once the link is lost (and the print run paused), texts that fit the device at hand, and a
// plan refused for its real reason.
#include <gtest/gtest.h>

#include <QRegularExpression>
#include <QSignalSpy>

#include "multidir/core/common/units.h"
#include "ui/hardware_panel_fixture.h"

namespace multidir::ui {
namespace {

// The device fields of the Status group (State and Last problem describe the link, not the device).
const char* const kDeviceFields[] = {"enabledValue", "positionValue", "movingValue", "homedValue", "faultValue",
                                     "heartbeatValue"};

class HardwarePanelTruth : public HardwarePanelTest {
 protected:
  QLabel* labelWidget(const char* name) { return panel.findChild<QLabel*>(QString::fromLatin1(name)); }
  // A port on 127.0.0.1 where nothing listens: the simulator's, once it stopped.
  int deadPort() {
    hardware::DeviceSimulator gone;
    EXPECT_TRUE(gone.start().ok());
    const int port = gone.port();
    gone.stop();
    return port;
  }
  void runToPrinting(const char* regionFile) {
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.promptText().contains(QLatin1String(regionFile)); }, kWaitMs))
        << panel.messageText().toStdString();
    EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Printing);
  }
};

TEST_F(HardwarePanelTruth, LinkLostDuringARunMarksEveryFieldStalePausesTheRunAndSaysSoInABanner) {
  givePlan(planWithAngles({0.0, 10.0}));
  connectPanel();
  enableAndHome();
  // A first run to its end leaves its "finished" message; the second run must not show it.
  press("startRunButton");
  runToPrinting("region-01.stl");
  press("regionDoneButton");
  runToPrinting("region-02.stl");
  press("regionDoneButton");
  ASSERT_TRUE(panel.messageText().contains(QStringLiteral("finished"))) << panel.messageText().toStdString();
  press("startRunButton");
  EXPECT_FALSE(panel.messageText().contains(QStringLiteral("finished"))) << panel.messageText().toStdString();
  runToPrinting("region-01.stl");
  EXPECT_TRUE(panel.bannerText().isEmpty()) << panel.bannerText().toStdString();

  sim.stop();  // the simulator is killed while region 1 prints
  ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().staleSince.has_value(); }, kWaitMs));
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printRunDriver()->pausePending(); }, kWaitMs));

  const QRegularExpression staleText(QStringLiteral("^unknown since \\d\\d:\\d\\d:\\d\\d"));
  for (const char* field : kDeviceFields) {
    QLabel* value = labelWidget(field);
    ASSERT_NE(value, nullptr) << field;
    EXPECT_TRUE(staleText.match(value->text()).hasMatch()) << field << ": " << value->text().toStdString();
    EXPECT_TRUE(value->styleSheet().contains(QStringLiteral("#8a8a8a"))) << field << " is not greyed";
  }
  EXPECT_NE(label("linkProblemValue"), QStringLiteral("none"));
  EXPECT_TRUE(panel.bannerText().contains(QStringLiteral("was lost at"))) << panel.bannerText().toStdString();
  EXPECT_TRUE(panel.bannerText().contains(QStringLiteral("paused"))) << panel.bannerText().toStdString();
  EXPECT_TRUE(label("runStepText").contains(QStringLiteral("pausing after this region")))
      << label("runStepText").toStdString();
  // The banner is drawn in alarm red across the panel's top.
  QLabel* banner = labelWidget("linkBanner");
  ASSERT_NE(banner, nullptr);
  ASSERT_TRUE(banner->isVisible());
  EXPECT_LT(banner->mapTo(&panel, QPoint(0, 0)).y(), 10);
  const QImage picture = banner->grab().toImage();
  EXPECT_GT(pixelsNear(picture, QColor(0xc6, 0x28, 0x28)), picture.width() * picture.height() / 2);

  // Region 1 may finish printing; region 2 does not start.
  press("regionDoneButton");
  EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Paused);
  EXPECT_EQ(panel.printRunDriver()->currentStep(), 1u);
  EXPECT_FALSE(panel.messageText().contains(QStringLiteral("finished"))) << panel.messageText().toStdString();

  // The simulator comes back on the same port: the values are the device's again, the link problem is
  // resolved, and the banner only says that the run waits for Resume.
  hardware::SimulatorOptions options;
  options.port = sim.port();
  hardware::DeviceSimulator back(options);
  ASSERT_TRUE(back.start().ok());
  ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().isFresh(); }, kWaitMs));
  for (const char* field : kDeviceFields)
    EXPECT_FALSE(labelWidget(field)->text().startsWith(QStringLiteral("unknown"))) << field;
  EXPECT_EQ(label("linkProblemValue"), QStringLiteral("none"));
  EXPECT_FALSE(panel.bannerText().contains(QStringLiteral("was lost at"))) << panel.bannerText().toStdString();
  EXPECT_TRUE(panel.bannerText().contains(QStringLiteral("Resume"))) << panel.bannerText().toStdString();
  press("abortButton");
  EXPECT_TRUE(panel.bannerText().isEmpty()) << panel.bannerText().toStdString();
}

TEST_F(HardwarePanelTruth, NothingListeningShowsNoDeviceStateAndNamesTheRealCause) {
  for (const DeviceKind kind : {DeviceKind::RobotArm, DeviceKind::RotaryPlatform}) {
    panel.connectionForm()->setKind(kind);
    hardware::ConnectionSettings settings = fastSettings(deadPort());
    if (kind == DeviceKind::RobotArm) settings.slaveId = 255;
    panel.connectionForm()->setSettings(settings);
    QSignalSpy finished(panel.deviceLink(), &DeviceLink::connectFinished);
    press("connectButton");
    ASSERT_TRUE(finished.wait(kWaitMs));
    ASSERT_FALSE(finished.front().at(0).toBool());
    // Let the driver retry a few times: still nothing made up.
    QTest::qWait(100);

    for (const char* field : {"positionValue", "movingValue", "homedValue", "faultValue"})
      EXPECT_EQ(label(field), QStringLiteral("unknown: not read yet")) << field;
    EXPECT_FALSE(label("faultValue").contains(QStringLiteral("not running")));
    EXPECT_TRUE(label("stateValue").contains(QStringLiteral("Not reachable"))) << label("stateValue").toStdString();
    for (const QString& shown : {panel.messageText(), panel.bannerText(), label("linkProblemValue")})
      EXPECT_TRUE(shown.contains(QStringLiteral("Connection refused"))) << shown.toStdString();
    press("disconnectButton");
  }
}

TEST_F(HardwarePanelTruth, RotaryPlatformStatusShowsWhetherTheDriveIsEnabled) {
  connectPanel();
  QLabel* enabled = labelWidget("enabledValue");
  ASSERT_NE(enabled, nullptr);
  EXPECT_TRUE(enabled->isVisible());
  EXPECT_EQ(enabled->text(), QStringLiteral("no: press Enable"));
  press("enableButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return enabled->text() == QStringLiteral("yes"); }, kWaitMs))
      << enabled->text().toStdString();
  EXPECT_TRUE(buttonNamed("estopButton")->toolTip().contains(QStringLiteral("Enable and Home")));
}

TEST_F(HardwarePanelTruth, RobotArmEmergencyStopRecoveryAsksOnlyForWhatTheArmOffers) {
  panel.connectionForm()->setKind(DeviceKind::RobotArm);
  hardware::ConnectionSettings settings = fastSettings(sim.port());
  settings.slaveId = 255;
  panel.connectionForm()->setSettings(settings);
  connectPanel();
  EXPECT_FALSE(labelWidget("enabledValue")->isVisible());  // the robot program enables the arm itself

  press("estopButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().state == DeviceState::Fault; }, kWaitMs));
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.messageText().startsWith(QStringLiteral("E-STOP")); }, kWaitMs));
  const QString texts[] = {buttonNamed("estopButton")->toolTip(), buttonNamed("clearFaultButton")->toolTip(),
                           panel.messageText(), label("faultValue")};
  for (const QString& text : texts) {
    EXPECT_FALSE(text.contains(QStringLiteral("enable"), Qt::CaseInsensitive)) << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("home"), Qt::CaseInsensitive)) << text.toStdString();
  }
  EXPECT_TRUE(panel.messageText().contains(QStringLiteral("Clear fault"))) << panel.messageText().toStdString();
}

TEST_F(HardwarePanelTruth, DeviceFollowsTheMachineProfileWhileDisconnected) {
  core::MachineSpec arm;
  arm.kind = core::MachineKind::TiltRotate;
  document.setMachine(arm);
  EXPECT_EQ(panel.connectionForm()->kind(), DeviceKind::RobotArm);
  core::MachineSpec platform;
  platform.kind = core::MachineKind::RotaryPlatform;
  document.setMachine(platform);
  EXPECT_EQ(panel.connectionForm()->kind(), DeviceKind::RotaryPlatform);
}

TEST_F(HardwarePanelTruth, FiveDofPlanOnTheRotaryPlatformIsRefusedForItsTiltsFirst) {
  // A plan made for the 5-DOF arm: regions 2 and 3 tilt 65 and 71 degrees at azimuths off the platform's plane.
  core::MachineSpec arm;
  arm.kind = core::MachineKind::TiltRotate;
  core::Decomposition plan;
  const double tilts[] = {0.0, 65.0, 71.0};
  const double azimuths[] = {0.0, 33.0, -101.3};
  for (int i = 0; i < 3; ++i) {
    core::Region region;
    const double tilt = core::degToRad(tilts[i]);
    const double azimuth = core::degToRad(azimuths[i]);
    region.printingDirection = core::Vec3(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth),
                                          std::cos(tilt));
    region.angles = core::machineAnglesFor(arm, region.printingDirection);
    plan.regions.push_back(region);
  }
  givePlan(plan);
  connectPanel();
  press("startRunButton");
  EXPECT_TRUE(panel.messageIsError());
  const QString message = panel.messageText();
  EXPECT_TRUE(message.startsWith(QStringLiteral("Start run refused: the plan tilts region 2 by 65.0 degrees and "
                                                "region 3 by 71.0 degrees, beyond the rotary platform's range of "
                                                "-60.0 to 60.0 degrees")))
      << message.toStdString();
  EXPECT_FALSE(message.contains(QStringLiteral("stepper"))) << message.toStdString();
  EXPECT_FALSE(panel.printRunDriver()->hasRun());
}

}  // namespace
}  // namespace multidir::ui
