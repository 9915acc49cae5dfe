// The Hardware panel against the device simulator on 127.0.0.1 (ephemeral port): buttons pressed as an
// operator would, outcomes read from the panel's labels and the simulator's own state.
#include <gtest/gtest.h>

#include <QMessageBox>
#include <QSignalSpy>

#include "ui/hardware_panel_fixture.h"

namespace multidir::ui {
namespace {

TEST_F(HardwarePanelTest, HomeThenGoToShowsTheAngleReached) {
  connectPanel();
  enableAndHome();
  EXPECT_NEAR(sim.rotaryState().angleDegrees, 0.0, 1e-9);

  goTo(30.0);
  ASSERT_TRUE(QTest::qWaitFor(
      [&] { return snapshot().atTarget && !snapshot().moving && label("positionValue").startsWith(degreesText(30.0)); },
      kWaitMs))
      << label("positionValue").toStdString();
  EXPECT_EQ(label("movingValue"), QStringLiteral("no"));
  EXPECT_NEAR(sim.rotaryState().angleDegrees, 30.0, 1e-9);
  EXPECT_FALSE(panel.messageIsError()) << panel.messageText().toStdString();
  EXPECT_TRUE(QTest::qWaitFor([&] { return label("heartbeatValue").endsWith(QStringLiteral("s ago")); }, kWaitMs))
      << label("heartbeatValue").toStdString();
}

TEST_F(HardwarePanelTest, AngleOutsideTheProfileIsRefusedAndNothingIsSent) {
  connectPanel();
  enableAndHome();
  const std::uint64_t writesBefore = sim.commandWriteCount(hardware::SimulatedDevice::Rotary);

  goTo(75.0);
  // The refusal is shown before the click returns: nothing had to travel to the device.
  EXPECT_TRUE(panel.messageIsError());
  EXPECT_TRUE(panel.messageText().contains(QStringLiteral("refused"))) << panel.messageText().toStdString();
  EXPECT_TRUE(panel.messageText().contains(QStringLiteral("outside"))) << panel.messageText().toStdString();

  // Let the link run a few more polls: a command sent late would show up as a write by then.
  const std::uint64_t polls = snapshot().polls;
  ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().polls >= polls + 5; }, kWaitMs));
  EXPECT_EQ(sim.commandWriteCount(hardware::SimulatedDevice::Rotary), writesBefore);
  EXPECT_NEAR(sim.rotaryState().angleDegrees, 0.0, 1e-9);
}

TEST_F(HardwarePanelTest, EmergencyStopWhileMovingStopsTheMotion) {
  panel.connectionForm()->setRotarySpeedDegreesPerSecond(20.0);  // slow enough to be caught mid-way
  connectPanel();
  enableAndHome();

  goTo(60.0);
  ASSERT_TRUE(QTest::qWaitFor([&] { return sim.rotaryState().moving && snapshot().moving; }, kWaitMs));
  EXPECT_TRUE(buttonNamed("estopButton")->isEnabled());
  press("estopButton");

  ASSERT_TRUE(QTest::qWaitFor([&] { return !sim.rotaryState().moving; }, kWaitMs));
  const double stoppedAt = sim.rotaryState().angleDegrees;
  EXPECT_LT(stoppedAt, 60.0);
  EXPECT_EQ(sim.rotaryState().faultCode, 5);  // e-stop
  ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().state == DeviceState::Fault; }, kWaitMs));
  EXPECT_EQ(label("stateValue"), QStringLiteral("Fault"));
  EXPECT_TRUE(label("faultValue").contains(QStringLiteral("emergency stop"))) << label("faultValue").toStdString();
  EXPECT_FALSE(buttonNamed("goToButton")->isEnabled());
  EXPECT_TRUE(buttonNamed("estopButton")->isEnabled());
  // Still where it stopped a few polls later.
  const std::uint64_t polls = snapshot().polls;
  ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().polls >= polls + 5; }, kWaitMs));
  EXPECT_DOUBLE_EQ(sim.rotaryState().angleDegrees, stoppedAt);
}

TEST_F(HardwarePanelTest, TwoRegionPlanRunsToTheEndWithRegionDonePressed) {
  core::Decomposition plan;
  plan.regions.resize(2);
  plan.regions[0].angles.rotaryDegrees = 0.0;
  plan.regions[1].angles.rotaryDegrees = 10.0;
  givePlan(plan);
  EXPECT_EQ(panel.planRegionCount(), 2);
  QSignalSpy regions(&panel, &HardwarePanel::currentRegionChanged);

  connectPanel();
  enableAndHome();
  press("startRunButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.promptText().contains(QStringLiteral("region-01.stl")); }, kWaitMs))
      << panel.messageText().toStdString();
  EXPECT_TRUE(panel.promptText().startsWith(QStringLiteral("Print region 1 "))) << panel.promptText().toStdString();
  press("regionDoneButton");

  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.promptText().contains(QStringLiteral("region-02.stl")); }, kWaitMs))
      << panel.messageText().toStdString();
  EXPECT_NEAR(sim.rotaryState().angleDegrees, 10.0, 1e-9);
  press("regionDoneButton");

  EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Completed);
  EXPECT_TRUE(label("runStepText").contains(QStringLiteral("finished"))) << label("runStepText").toStdString();
  EXPECT_TRUE(panel.promptText().isEmpty());
  EXPECT_FALSE(buttonNamed("regionDoneButton")->isEnabled());
  ASSERT_GE(regions.count(), 3);
  EXPECT_EQ(regions.at(0).at(0).toInt(), 0);
  EXPECT_EQ(regions.at(regions.count() - 2).at(0).toInt(), 1);
  EXPECT_EQ(regions.last().at(0).toInt(), -1);
}

TEST_F(HardwarePanelTest, StartRunAfterAnAbortOffersToResumeFromTheFirstStepNotDoneOnceThePlatformIsClear) {
  givePlan(planWithAngles({0.0, 10.0, 20.0}));
  connectPanel();
  enableAndHome();
  press("startRunButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.promptText().contains(QStringLiteral("region-01.stl")); }, kWaitMs))
      << panel.messageText().toStdString();
  press("regionDoneButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.promptText().contains(QStringLiteral("region-02.stl")); }, kWaitMs))
      << panel.messageText().toStdString();
  press("abortButton");
  ASSERT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Aborted);

  auto restartBox = [this] {
    QMessageBox* box = nullptr;
    (void)QTest::qWaitFor([&] {
      box = panel.findChild<QMessageBox*>(QStringLiteral("restartRunBox"));
      return box != nullptr && box->isVisible();
    }, kWaitMs);
    return box;
  };
  // Start run asks first; nothing moves until the operator answers.
  press("startRunButton");
  QMessageBox* box = restartBox();
  ASSERT_NE(box, nullptr) << "Start run after an abort should ask where to go on from";
  EXPECT_TRUE(box->text().contains(QStringLiteral("step 2 of 3"))) << box->text().toStdString();
  EXPECT_TRUE(box->informativeText().contains(QStringLiteral("clear"))) << box->informativeText().toStdString();
  EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Aborted);
  box->button(QMessageBox::Cancel)->click();
  QTest::qWait(50);
  EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Aborted);

  press("startRunButton");
  box = restartBox();
  ASSERT_NE(box, nullptr);
  auto* resume = box->findChild<QPushButton*>(QStringLiteral("resumeFromStepButton"));
  ASSERT_NE(resume, nullptr);
  EXPECT_TRUE(resume->text().contains(QStringLiteral("Step 2"))) << resume->text().toStdString();
  resume->click();
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.promptText().contains(QStringLiteral("region-02.stl")); }, kWaitMs))
      << panel.messageText().toStdString();
  EXPECT_EQ(panel.printRunDriver()->currentStep(), 1u);
  EXPECT_NEAR(sim.rotaryState().angleDegrees, 10.0, 1e-9);
  EXPECT_TRUE(label("runStepText").startsWith(QStringLiteral("2 of 3"))) << label("runStepText").toStdString();
}

TEST_F(HardwarePanelTest, StartRunRefusalIsSaidRightUnderTheButton) {
  givePlan(planWithAngles({0.0, 70.0}));  // beyond the profile's 60 degrees
  connectPanel();
  enableAndHome();
  press("startRunButton");
  auto* refusal = panel.findChild<QLabel*>(QStringLiteral("startRunRefusal"));
  ASSERT_NE(refusal, nullptr);
  ASSERT_TRUE(refusal->isVisible()) << panel.messageText().toStdString();
  EXPECT_TRUE(refusal->text().startsWith(QStringLiteral("Start run refused"))) << refusal->text().toStdString();
  // Where the operator looks: just below the button, not the panel's message line far above it.
  QPushButton* start = buttonNamed("startRunButton");
  const QRect button(start->mapTo(&panel, QPoint(0, 0)), start->size());
  const QRect said(refusal->mapTo(&panel, QPoint(0, 0)), refusal->size());
  EXPECT_GE(said.top(), button.bottom());
  EXPECT_LE(said.top() - button.bottom(), 24) << "button bottom " << button.bottom() << ", refusal top " << said.top();
  EXPECT_FALSE(panel.printRunDriver()->isActive());
}

TEST_F(HardwarePanelTest, RobotArmTiltsThePlatformToTheOrientationAsked) {
  panel.connectionForm()->setKind(DeviceKind::RobotArm);
  hardware::ConnectionSettings settings = fastSettings(sim.port());
  settings.slaveId = 255;
  panel.connectionForm()->setSettings(settings);
  panel.connectionForm()->setRobotSpeedPercent(100);
  connectPanel();
  EXPECT_FALSE(buttonNamed("enableButton")->isVisible());  // the robot program enables the arm itself

  panel.findChild<QDoubleSpinBox*>(QStringLiteral("targetTilt"))->setValue(30.0);
  panel.findChild<QDoubleSpinBox*>(QStringLiteral("targetAzimuth"))->setValue(45.0);
  press("goToButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().atTarget && label("positionValue").contains(degreesText(30.0)); },
                              kWaitMs))
      << label("positionValue").toStdString() << " / " << panel.messageText().toStdString();
  EXPECT_EQ(label("positionValue"), QStringLiteral("tilt %1, azimuth %2").arg(degreesText(30.0), degreesText(45.0)));
  EXPECT_NEAR(sim.robotState().tiltDegrees, 30.0, 1e-9);
  EXPECT_NEAR(sim.robotState().azimuthDegrees, 45.0, 1e-9);
}

TEST_F(HardwarePanelTest, CommandsWithoutAConnectionAreRefusedInThePanel) {
  EXPECT_FALSE(buttonNamed("goToButton")->isEnabled());
  EXPECT_FALSE(buttonNamed("estopButton")->isEnabled());
  panel.deviceLink()->home();
  EXPECT_TRUE(panel.messageIsError());
  EXPECT_TRUE(panel.messageText().contains(QStringLiteral("not connected"))) << panel.messageText().toStdString();
  EXPECT_EQ(sim.commandWriteCount(hardware::SimulatedDevice::Rotary), 0u);
}

}  // namespace
}  // namespace multidir::ui
