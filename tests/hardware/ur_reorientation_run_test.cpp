// A step re-oriented at a travel move (docs/robot-cell.md, "Re-orientation within a step") run on the simulated
// UR controller of its cell, tick by tick: the program runs to its end within the cell's narrowed joint limits
// (a limit passed would be a protective stop), every tick the extruder runs puts the nozzle within 0.05 mm of one
// of the G-code's extrusion moves in the part's frame, and the extruder pushes the G-code's filament to 0.5 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "multidir/robot/cell.h"
#include "multidir/slicing/gcode_program.h"
#include "sim/ur_controller.h"
#include "step_converter.h"
#include "support/reorientation_step.h"

namespace {

namespace robot = multidir::robot;
namespace sim = multidir::hardware::sim;
using multidir::hardware::ur::UrProgramState;

double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

TEST(UrReorientationRun, AReorientedStepRunsOnTheSimulatedArmAlongTheGcodesExtrusionMoves) {
  const robot::Cell cell = multidir::test::narrowWrist3Cell();
  const multidir::test::IslandsProgram program = multidir::test::threeIslands(true);
  robot::detail::StepInput input;
  input.gcodeFile = "step-01.gcode";
  input.gcode = program.text();
  const robot::detail::StepOutput out =
      robot::detail::convertStep(input, cell, multidir::test::everyDegree(), multidir::core::JobContext());
  ASSERT_TRUE(out.refusals.empty()) << out.refusals.front();
  ASSERT_EQ(out.summary.reorientations.size(), 1u);

  sim::UrController controller(cell.arm, cell.home);
  bool quit = false;
  controller.dashboard("power on", quit);
  for (int i = 0; i < 100; ++i) controller.tick();
  controller.dashboard("brake release", quit);
  controller.receiveProgram(out.script);
  std::vector<sim::UrTraceSample> trace;
  for (int i = 0; i < static_cast<int>(600.0 / sim::kUrTickSeconds); ++i) {
    controller.tick();
    for (sim::UrTraceSample& s : controller.takeTrace()) trace.push_back(std::move(s));
    if (controller.programState() == UrProgramState::Stopped && controller.atRest()) break;
  }
  ASSERT_EQ(controller.lastFault(), "");
  ASSERT_EQ(controller.programsFinished(), 1u);

  // The G-code's extrusion moves, in the files' frame (the step's pose is the identity here).
  const auto parsed = multidir::slicing::parseGcode(input.gcode, "A", input.gcodeFile);
  ASSERT_TRUE(parsed.ok());
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> extrusions;
  double gcodeFilament = 0.0;
  for (const auto& m : parsed->moves)
    if (m.extrudes()) {
      extrusions.emplace_back(m.from, m.to);
      gcodeFilament += m.filamentMm;
    }
  double worst = 0.0, pushed = 0.0;
  int extrudingTicks = 0;
  for (std::size_t k = 1; k < trace.size(); ++k) {
    const sim::UrTraceSample& s = trace[k];
    pushed += s.analogOut0 * cell.maxFilamentMmPerS * (s.time - trace[k - 1].time);
    if (s.analogOut0 <= 0.0) continue;
    ++extrudingTicks;
    const Eigen::Isometry3d tcp = sim::urPoseToIsometry(
        {s.tcp[0] / 1000.0, s.tcp[1] / 1000.0, s.tcp[2] / 1000.0, s.tcp[3], s.tcp[4], s.tcp[5]});
    const Eigen::Vector3d nozzle = tcp.inverse() * cell.nozzleTipMm;
    double nearest = 1e9;
    for (const auto& [a, b] : extrusions) nearest = std::min(nearest, distanceToSegment(nozzle, a, b));
    worst = std::max(worst, nearest);
  }
  std::cout << "[ measured ] nozzle off the G-code's extrusion moves by at most " << worst << " mm over "
            << extrudingTicks << " extruding ticks; filament pushed " << pushed << " mm, G-code E " << gcodeFilament
            << " mm\n";
  EXPECT_GT(extrudingTicks, 100);
  EXPECT_LT(worst, 0.05);
  EXPECT_NEAR(pushed / gcodeFilament, 1.0, 0.005);
}

}  // namespace
