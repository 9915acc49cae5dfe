#include <gtest/gtest.h>

#include "multidir/core/search/decompose.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

MachineSpec rotaryUpY() {
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = platformFrameX(machine.up);
  return machine;
}

// Twelve axes: more than the second stage searches in full, so both stages run.
Decomposition axisSearch(int threads) {
  SearchOptions options;
  options.threads = threads;
  JobContext job;
  auto plan = decomposeWithAxisSearch(multidir::test::loadSharedModel("bumpy.off"), rotaryUpY(), options, 12, job);
  if (!plan.ok()) throw std::runtime_error(plan.error().describe());
  return std::move(plan).value();
}

}  // namespace

TEST(AxisSearch, OneAndTwoThreadsChooseTheSameAxisAndPlan) {
  const Decomposition one = axisSearch(1), two = axisSearch(2);
  EXPECT_EQ(one.rotationAxis, two.rotationAxis);
  EXPECT_EQ(one.jgAfterMm2, two.jgAfterMm2);
  ASSERT_EQ(one.clippingPlanes.size(), two.clippingPlanes.size());
  for (std::size_t i = 0; i < one.clippingPlanes.size(); ++i) {
    EXPECT_EQ(one.clippingPlanes[i].normal, two.clippingPlanes[i].normal);
    EXPECT_EQ(one.clippingPlanes[i].offset, two.clippingPlanes[i].offset);
  }
}

TEST(AxisSearch, IsNeverWorseThanTheFullSearchOnTheGivenAxis) {
  JobContext job;
  const auto given = decompose(multidir::test::loadSharedModel("bumpy.off"), rotaryUpY(), SearchOptions{}, job);
  ASSERT_TRUE(given.ok());
  EXPECT_LE(axisSearch(0).jgAfterMm2, given->jgAfterMm2 + 1e-9);
}
