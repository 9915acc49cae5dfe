// A step whose straight joint move from home is blocked by the extruder (the paper's cell as shipped; a flat
// square step) run on the simulated UR controller with the cell's bodies (UrController::watchCollisions,
// docs/hardware.md "UR controller"): the program with its via points runs to its end with no contact, and every
// tick of the arm's executed path, checked again with the tests' own geometry (support/joint_sweep_check.h),
// keeps the links and the platform clear; the same program without its via points drives the arm into the
// extruder and the simulator stops it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "multidir/robot/cell.h"
#include "sim/ur_controller.h"
#include "step_converter.h"
#include "support/joint_sweep_check.h"
#include "support/square_steps.h"

namespace {

namespace robot = multidir::robot;
namespace sim = multidir::hardware::sim;
using multidir::hardware::ur::UrProgramState;
using multidir::hardware::ur::UrSafetyMode;

// The program run on the cell's simulated arm from its home, the bodies watched; the executed ticks.
std::vector<sim::UrTraceSample> runOnTheCell(const robot::Cell& cell, const std::string& script,
                                             sim::UrController& controller) {
  controller.watchCollisions(cell);
  bool quit = false;
  controller.dashboard("power on", quit);
  for (int i = 0; i < 100; ++i) controller.tick();
  controller.dashboard("brake release", quit);
  controller.receiveProgram(script);
  std::vector<sim::UrTraceSample> trace;
  for (int i = 0; i < static_cast<int>(600.0 / sim::kUrTickSeconds); ++i) {
    controller.tick();
    for (sim::UrTraceSample& s : controller.takeTrace()) trace.push_back(std::move(s));
    if (controller.programState() == UrProgramState::Stopped && controller.atRest()) break;
  }
  return trace;
}

robot::detail::StepOutput squareStep(const robot::Cell& cell) {
  return robot::detail::convertStep(robot::detail::stepOf(robot::detail::squares(2), 30.0), cell,
                                    robot::detail::fixedRotation(), multidir::core::JobContext());
}

TEST(UrViaPointsRun, AStepWithViaPointsRunsOnTheShippedCellsSimulatedArmWithNoContact) {
  const robot::Cell cell = robot::detail::shippedCell();
  const robot::detail::StepOutput out = squareStep(cell);
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  ASSERT_GE(out.summary.viaPointsFromHome, 1);
  sim::UrController controller(cell.arm, cell.home);
  const std::vector<sim::UrTraceSample> trace = runOnTheCell(cell, out.script, controller);
  EXPECT_EQ(controller.lastFault(), "");
  EXPECT_EQ(controller.programsFinished(), 1u);
  double least = 1e9;
  std::string what;
  for (const sim::UrTraceSample& s : trace) {
    std::string here;
    if (const double c = multidir::test::sweepClearanceAt(cell, s.q, {}, here); c < least) {
      least = c;
      what = here;
    }
  }
  EXPECT_GT(least, 0.0) << what;
}

TEST(UrViaPointsRun, TheSameProgramWithoutItsViaPointsDrivesTheArmIntoTheExtruderAndTheSimulatorStopsIt) {
  const robot::Cell cell = robot::detail::shippedCell();
  const robot::detail::StepOutput out = squareStep(cell);
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  ASSERT_GE(out.summary.viaPointsFromHome, 1);
  // Drop the via points' movej lines on the way from home (they follow the comment that announces them).
  std::istringstream in(out.script);
  std::string line, straight;
  int skip = 0;
  while (std::getline(in, line)) {
    if (line.find("# from home to the step's first point:") != std::string::npos) {
      skip = out.summary.viaPointsFromHome;
      continue;
    }
    if (skip > 0 && line.find("movej(") != std::string::npos) {
      --skip;
      continue;
    }
    straight += line + "\n";
  }
  sim::UrController controller(cell.arm, cell.home);
  runOnTheCell(cell, straight, controller);
  EXPECT_EQ(controller.safetyMode(), UrSafetyMode::ProtectiveStop);
  EXPECT_NE(controller.lastFault().find("Protective stop: collision: the arm's "), std::string::npos)
      << controller.lastFault();
  EXPECT_EQ(controller.programsFinished(), 0u);
}

}  // namespace
