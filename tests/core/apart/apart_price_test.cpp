// The price of a part on the apart machine (docs/apart.md, "The price of a part"): a fixed price and a price
// per mm^2 of its cut face, which a plane must save in support to stay in the plan.
#include <gtest/gtest.h>

#include "multidir/core/search/search_options.h"
#include "search/cut_face_area.h"
#include "search/run_decomposition.h"
#include "search/search_engine.h"
#include "support/primitives.h"

using namespace multidir::core;
using multidir::core::detail::SearchEngine;

namespace {

MachineSpec apartMachine() {
  MachineSpec machine;
  machine.kind = MachineKind::Apart;
  machine.rotationAxis = platformFrameX(machine.up);
  return machine;
}

// A pyramid on its tip (40 mm square top, 10 mm tall) cut 8 mm above the tip: the tip, printed upside down
// on its cut face, a 32 x 32 mm square.
struct CutPyramid {
  TriangleMesh pyramid = multidir::test::makeInvertedPyramid(40.0, 10.0);
  Plane plane{-Vec3::UnitZ(), -8.0};
};

}  // namespace

TEST(ApartPrice, ACutFaceIsTheCapOfTheRegionCutOffOneSideOnly) {
  const CutPyramid cut;
  const MachineSpec machine = apartMachine();
  const SearchOptions options;
  JobContext job;
  SearchEngine engine(cut.pyramid, machine, options, job);  // it keeps references to all four
  const auto node = engine.cut(engine.root(), cut.plane);
  ASSERT_TRUE(node.ok()) << node.error().describe();
  EXPECT_NEAR(detail::cutFaceAreaMm2(**node), 32.0 * 32.0, 1e-6);
  EXPECT_EQ(detail::cutFaceAreaMm2(*engine.root()), 0.0);
}

TEST(ApartPrice, APlaneStaysOnlyWhereItSavesMoreThanThePriceOfItsCutFace) {
  const CutPyramid cut;
  SearchOptions options;
  options.partCostMm2 = 0.0;
  options.minPlaneGainMm2 = 0.0;
  options.minPlaneGainPercent = 0.0;
  const MachineSpec machine = apartMachine();
  const SearchOptions engineOptions = options;
  JobContext job;
  SearchEngine engine(cut.pyramid, machine, engineOptions, job);
  const auto node = engine.cut(engine.root(), cut.plane);
  ASSERT_TRUE(node.ok()) << node.error().describe();
  const double saved = engine.root()->jg() - (*node)->jg();
  ASSERT_GT(saved, 0.0);
  const double perMm2ThatSaves = saved / (32.0 * 32.0);
  options.cutFaceCost = 0.9 * perMm2ThatSaves;
  EXPECT_EQ(detail::withoutUnpaidPlanes(engine, *node, options)->level, 1) << "a cut face priced below its saving";
  options.cutFaceCost = 1.1 * perMm2ThatSaves;
  EXPECT_EQ(detail::withoutUnpaidPlanes(engine, *node, options)->level, 0) << "a cut face priced above its saving";
  // The fixed price adds to it.
  options.cutFaceCost = 0.9 * perMm2ThatSaves;
  options.partCostMm2 = 0.2 * saved;
  EXPECT_EQ(detail::withoutUnpaidPlanes(engine, *node, options)->level, 0);
}
