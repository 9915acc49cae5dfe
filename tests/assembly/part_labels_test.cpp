// Part numbers sunk into a face of each part that gluing hides (docs/apart.md, "Part numbers").
#include <gtest/gtest.h>

#include "multidir/assembly/dowels.h"
#include "multidir/assembly/part_labels.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "support/primitives.h"

using namespace multidir;
using core::Vec3;

namespace {

// Two boxes `side` x `side` x 30 mm stacked along z, cut apart at z = 30 by the build volume: one joint.
core::ApartPlan stackedBoxes(double sideX, double sideY) {
  core::Decomposition plan;
  core::Region whole;
  whole.mesh = test::makeBox(Vec3(0, 0, 0), Vec3(sideX, sideY, 60));
  plan.regions.push_back(whole);
  core::ApartOptions options;
  options.buildVolume = {220, 220, 40};
  return *core::apartPlan(plan, options);
}

bool closedOrientedSolid(const core::TriangleMesh& mesh) {
  return core::edgeCensus(mesh).closedOriented() && core::signedVolume(mesh) > 0;
}

// The gap between two axis-aligned rectangles (0 when they touch or overlap).
double gapBetween(const assembly::Stroke& a, const assembly::Stroke& b) {
  const double dx = std::max({0.0, a.low.x() - b.high.x(), b.low.x() - a.high.x()});
  const double dy = std::max({0.0, a.low.y() - b.high.y(), b.low.y() - a.high.y()});
  return std::hypot(dx, dy);
}

}  // namespace

TEST(PartLabels, DigitsAreSevenSegmentStrokesThatNeverTouch) {
  const assembly::LabelOptions options;
  const std::vector<assembly::Stroke> strokes = assembly::textStrokes("0123456789", 6.0, options);
  // Segments lit: 6 + 2 + 5 + 5 + 4 + 5 + 6 + 3 + 7 + 6.
  ASSERT_EQ(strokes.size(), 49u);
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    EXPECT_GE((strokes[i].high - strokes[i].low).minCoeff(), options.minStrokeMm - 1e-12) << "stroke " << i;
    for (std::size_t j = i + 1; j < strokes.size(); ++j)
      EXPECT_GE(gapBetween(strokes[i], strokes[j]), options.gapMm - 1e-9) << "strokes " << i << " and " << j;
  }
}

TEST(PartLabels, StackedBoxesAreNumberedOnTheirJointFaceClearOfTheDowelHoles) {
  const core::ApartPlan plan = stackedBoxes(60, 40);
  const assembly::DowelOptions dowels;
  const assembly::DowelLayout layout = assembly::placeDowels(plan, dowels);
  ASSERT_EQ(layout.dowels.size(), 2u);
  const assembly::LabelOptions options;
  const std::vector<assembly::PartLabel> labels = assembly::placeLabels(plan, layout, dowels, options);
  ASSERT_EQ(labels.size(), 2u);
  for (const assembly::PartLabel& label : labels) {
    ASSERT_TRUE(label.placed) << label.note;
    EXPECT_EQ(label.text, std::to_string(label.part + 1));
    EXPECT_NEAR(label.centre.z(), 30.0, 0.01);  // on the joint face, hidden once glued
    EXPECT_DOUBLE_EQ(label.heightMm, options.heightsMm.front());
    const double reach = 0.5 * assembly::textSize(label.text, label.heightMm, options).norm() + options.marginMm;
    for (const assembly::Dowel& dowel : layout.dowels)
      EXPECT_GE((label.centre - dowel.centre).norm(), dowel.holeRadiusMm(dowels) + dowels.chamferMm + reach);
    // Inside the face with its margin: 60 x 40 mm.
    EXPECT_GE(label.centre.x() - reach, -1e-9);
    EXPECT_LE(label.centre.x() + reach, 60 + 1e-9);
    EXPECT_GE(label.centre.y() - reach, -1e-9);
    EXPECT_LE(label.centre.y() + reach, 40 + 1e-9);
  }
}

TEST(PartLabels, NumbersFaceOutOfTheirPartAndReadFromOutside) {
  const core::ApartPlan plan = stackedBoxes(60, 40);
  const assembly::DowelOptions dowels;
  const std::vector<assembly::PartLabel> labels =
      assembly::placeLabels(plan, assembly::placeDowels(plan, dowels), dowels, assembly::LabelOptions{});
  for (const assembly::PartLabel& label : labels) {
    ASSERT_TRUE(label.placed);
    const core::BoundingBox box = core::boundingBox(plan.parts[static_cast<std::size_t>(label.part)].mesh);
    const bool below = box.max.z() < 30.5;  // the part under the joint: its joint face looks up
    EXPECT_NEAR(label.outward.z(), below ? 1.0 : -1.0, 1e-12);
    EXPECT_NEAR(label.right.norm(), 1.0, 1e-12);
    EXPECT_NEAR(label.right.dot(label.outward), 0.0, 1e-12);
  }
}

TEST(PartLabels, NumberedPartsStayClosedOrientedSolidsAndLoseExactlyTheNumbersVolume) {
  const core::ApartPlan plan = stackedBoxes(60, 40);
  const assembly::DowelOptions dowels;
  const assembly::DowelLayout layout = assembly::placeDowels(plan, dowels);
  const auto drilled = assembly::drillParts(plan, layout, dowels);
  ASSERT_TRUE(drilled.ok()) << drilled.error().describe();
  const assembly::LabelOptions options;
  const std::vector<assembly::PartLabel> labels = assembly::placeLabels(plan, layout, dowels, options);
  const auto numbered = assembly::debossLabels(drilled->parts, labels, options);
  ASSERT_TRUE(numbered.ok()) << numbered.error().describe();
  ASSERT_EQ(numbered->size(), drilled->parts.size());
  for (std::size_t p = 0; p < numbered->size(); ++p) {
    EXPECT_TRUE(closedOrientedSolid((*numbered)[p])) << "part " << p + 1;
    const double lost = core::signedVolume(drilled->parts[p]) - core::signedVolume((*numbered)[p]);
    EXPECT_GT(lost, 0.0);
    EXPECT_NEAR(lost, assembly::labelVolumeMm3(labels[p], options), 1e-6) << "part " << p + 1;
  }
}

TEST(PartLabels, AFaceTooSmallForANumberLeavesThePartUnnumberedAndSaysSo) {
  // A 6 x 6 mm joint: a 6 mm digit with its margin needs a circle of 2 x 4.3 mm.
  const core::ApartPlan plan = stackedBoxes(6, 6);
  const assembly::DowelOptions dowels;
  const assembly::LabelOptions options;
  const std::vector<assembly::PartLabel> labels =
      assembly::placeLabels(plan, assembly::placeDowels(plan, dowels), dowels, options);
  ASSERT_EQ(labels.size(), 2u);
  for (const assembly::PartLabel& label : labels) {
    EXPECT_FALSE(label.placed);
    EXPECT_NE(label.note.find("no joint face has room"), std::string::npos) << label.note;
  }
  const auto numbered = assembly::debossLabels({plan.parts[0].mesh, plan.parts[1].mesh}, labels, options);
  ASSERT_TRUE(numbered.ok());
  EXPECT_DOUBLE_EQ(core::signedVolume((*numbered)[0]), core::signedVolume(plan.parts[0].mesh));
}
