// Where to put the extruder: the reach map scores nozzle positions by the share of a plan's needed platform poses
// the arm reaches with the cell's margins.
#include <gtest/gtest.h>

#include "multidir/robot/cell.h"
#include "multidir/robot/reach_map.h"
#include "slicing/slicing_fixtures.h"
#include "support/test_models.h"

namespace multidir::robot {
namespace {

const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

std::vector<ReachStep> stepsOf(const std::string& model, double scale) {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::TiltRotate;
  machine.up = core::Vec3::UnitY();
  const core::LoadedPlan plan = test::plannedInMemory(test::loadSharedModel(model), machine, model, scale);
  auto steps = reachStepsOfPlan(plan);
  EXPECT_TRUE(steps.ok()) << steps.error().describe();
  EXPECT_GE(steps->size(), 2u);
  return steps.value();
}

TEST(ReachMap, ThePaperCellsNozzleReachesEveryKittenPoseAndAFarOneNone) {
  const Cell cell = loadCell(kShippedCell).value();
  const auto steps = stepsOf("kitten.off", 0.5);
  const ReachPoint own = reachScore(steps, cell, cell.nozzleTipMm, ReachMapOptions{});
  EXPECT_EQ(own.score, 1.0);
  EXPECT_GE(own.leastMarginMm, cell.margins.minReachMm);
  const ReachPoint far = reachScore(steps, cell, Eigen::Vector3d(1500.0, 0.0, 400.0), ReachMapOptions{});
  EXPECT_EQ(far.score, 0.0);
}

// A pose counts only with the cell's margins: asking for a reach margin no pose has leaves nothing reachable.
TEST(ReachMap, APoseCountsOnlyWithTheCellsMargins) {
  Cell cell = loadCell(kShippedCell).value();
  const auto steps = stepsOf("kitten.off", 0.5);
  cell.margins.minReachMm = 1000.0;
  EXPECT_EQ(reachScore(steps, cell, cell.nozzleTipMm, ReachMapOptions{}).score, 0.0);
}

class ReachMapOfModel : public ::testing::TestWithParam<std::string> {};

// The map's best position reaches every pose of every step, with the cell's margins.
TEST_P(ReachMapOfModel, BestPositionReachesEveryStepWithMargin) {
  const Cell cell = loadCell(kShippedCell).value();
  const auto steps = stepsOf(GetParam(), 0.5);
  ReachMapOptions options;
  options.gridMm = 150.0;
  const auto map = reachMap(steps, cell, options, core::JobContext());
  ASSERT_TRUE(map.ok()) << map.error().describe();
  ASSERT_FALSE(map->points.empty());
  EXPECT_EQ(map->best.score, 1.0);
  EXPECT_GE(map->best.leastMarginMm, cell.margins.minReachMm);
  // The best is the best: no sampled position scores higher or, as high, has a larger margin.
  for (const auto& p : map->points) {
    EXPECT_LE(p.score, map->best.score);
    if (p.score == map->best.score) {
      EXPECT_LE(p.leastMarginMm, map->best.leastMarginMm);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(SharedModels, ReachMapOfModel, ::testing::Values("kitten.off", "bunny.off", "fertility.off"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

}  // namespace
}  // namespace multidir::robot
