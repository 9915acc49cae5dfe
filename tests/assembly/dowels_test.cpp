// Dowels between the parts of a plan printed apart (docs/apart.md, "Dowels").
#include <gtest/gtest.h>

#include <map>

#include "multidir/assembly/dowels.h"
#include "multidir/assembly/part_labels.h"
#include "multidir/assembly/plates.h"
#include "multidir/assembly/three_mf.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/decompose.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir;
using core::Vec3;

namespace {

// A shared model searched for the apart machine (greedy: the dowels' properties hold for any plan), its parts
// on an unlimited bed, their dowels and the drilled parts.
struct Assembled {
  core::TriangleMesh model;
  core::ApartPlan plan;
  assembly::DowelLayout layout;
  assembly::DrilledParts drilled;
};

Assembled assembledModel(const std::string& name, const assembly::DowelOptions& options = {}) {
  Assembled a;
  a.model = test::loadSharedModel(name);
  core::MachineSpec machine;
  machine.kind = core::MachineKind::Apart;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = core::platformFrameX(machine.up);
  core::SearchOptions search;
  search.scheme = core::SearchScheme::Greedy;
  core::JobContext job;
  auto plan = core::decompose(a.model, machine, search, job);
  if (!plan.ok()) throw std::runtime_error(plan.error().describe());
  auto apart = core::apartPlan(*plan);
  if (!apart.ok()) throw std::runtime_error(apart.error().describe());
  a.plan = std::move(*apart);
  a.layout = assembly::placeDowels(a.plan, options);
  auto drilled = assembly::drillParts(a.plan, a.layout, options);
  if (!drilled.ok()) throw std::runtime_error(drilled.error().describe());
  a.drilled = std::move(*drilled);
  return a;
}

// Kitten and bunny are searched once for all the tests below.
const Assembled& assembled(const std::string& name) {
  static std::map<std::string, Assembled> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, assembledModel(name)).first;
  return it->second;
}

bool closedOrientedSolid(const core::TriangleMesh& mesh) {
  return core::edgeCensus(mesh).closedOriented() && core::signedVolume(mesh) > 0;
}

// Two boxes 60 x 40 x 30 mm, one on the other, cut at z = 30: one joint of 60 x 40 mm.
core::ApartPlan stackedBoxes() {
  core::Decomposition plan;
  core::Region whole;
  whole.mesh = test::makeBox(Vec3(0, 0, 0), Vec3(60, 40, 60));
  plan.regions.push_back(whole);
  core::ApartOptions options;
  options.buildVolume = {220, 220, 40};
  return *core::apartPlan(plan, options);
}

}  // namespace

class DowelsOnSharedModels : public ::testing::TestWithParam<std::string> {};

TEST_P(DowelsOnSharedModels, EveryPartAndDowelIsAClosedOrientedSolid) {
  const Assembled& a = assembled(GetParam());
  ASSERT_EQ(a.drilled.parts.size(), a.plan.parts.size());
  for (const core::TriangleMesh& part : a.drilled.parts) EXPECT_TRUE(closedOrientedSolid(part));
  ASSERT_FALSE(a.drilled.dowels.empty());
  for (const core::TriangleMesh& dowel : a.drilled.dowels) EXPECT_TRUE(closedOrientedSolid(dowel));
}

TEST_P(DowelsOnSharedModels, PartsDowelsAndClearancesAddUpToTheModelWithinHalfAPercent) {
  const Assembled& a = assembled(GetParam());
  double volume = a.drilled.clearanceVolumeMm3;
  for (const core::TriangleMesh& part : a.drilled.parts) volume += core::signedVolume(part);
  for (const core::TriangleMesh& dowel : a.drilled.dowels) volume += core::signedVolume(dowel);
  const double model = core::signedVolume(a.model);
  EXPECT_NEAR(volume, model, 0.005 * model);
}

TEST_P(DowelsOnSharedModels, NoHoleComesCloserToAnOuterWallThanTheMinimum) {
  const Assembled& a = assembled(GetParam());
  const assembly::DowelOptions options;
  for (const assembly::Dowel& dowel : a.layout.dowels) {
    const core::ApartJoint& joint = a.plan.joints[static_cast<std::size_t>(dowel.joint)];
    for (const bool intoUpper : {true, false}) {
      const core::ApartPart& part = a.plan.parts[static_cast<std::size_t>(intoUpper ? joint.upper : joint.lower)];
      EXPECT_GE(assembly::holeWallMm(part.mesh, joint.planeId, dowel, intoUpper, options), options.minWallMm)
          << "joint " << dowel.joint << (intoUpper ? " upper" : " lower");
    }
  }
}

TEST_P(DowelsOnSharedModels, JointsWithRoomGetTwoDowelsOfDifferentDiameters) {
  const Assembled& a = assembled(GetParam());
  std::map<int, std::vector<double>> diameters;
  for (const assembly::Dowel& dowel : a.layout.dowels) diameters[dowel.joint].push_back(dowel.diameterMm);
  int withTwo = 0;
  for (const assembly::JointDowels& joint : a.layout.joints) {
    if (joint.count >= 2) {
      ++withTwo;
      EXPECT_GT(diameters[joint.joint][0], diameters[joint.joint][1]);
    } else {
      EXPECT_FALSE(joint.note.empty()) << "joint " << joint.joint << " has fewer dowels and no reason";
    }
  }
  EXPECT_GT(withTwo, 0);
}

TEST_P(DowelsOnSharedModels, EachPartLosesExactlyItsHolesVolume) {
  // Sharper than the balance above, whose 0.5 % of the model is more than all the clearances together.
  const Assembled& a = assembled(GetParam());
  const assembly::DowelOptions options;
  for (std::size_t p = 0; p < a.plan.parts.size(); ++p) {
    double holes = 0;
    for (const assembly::Dowel& dowel : a.layout.dowels) {
      const core::ApartJoint& joint = a.plan.joints[static_cast<std::size_t>(dowel.joint)];
      if (joint.upper == static_cast<int>(p) || joint.lower == static_cast<int>(p))
        holes += assembly::holeVolumeMm3(dowel, options);
    }
    const double removed = core::signedVolume(a.plan.parts[p].mesh) - core::signedVolume(a.drilled.parts[p]);
    EXPECT_NEAR(removed, holes, 1e-3 * holes + 1e-9 * a.plan.parts[p].volumeMm3) << "part " << p + 1;
  }
}

TEST_P(DowelsOnSharedModels, NumberedPartsStayClosedOrientedSolids) {
  const Assembled& a = assembled(GetParam());
  const assembly::DowelOptions dowels;
  const assembly::LabelOptions options;
  const std::vector<assembly::PartLabel> labels = assembly::placeLabels(a.plan, a.layout, dowels, options);
  ASSERT_EQ(labels.size(), a.plan.parts.size());
  const auto numbered = assembly::debossLabels(a.drilled.parts, labels, options);
  ASSERT_TRUE(numbered.ok()) << numbered.error().describe();
  int placed = 0;
  for (std::size_t p = 0; p < numbered->size(); ++p) {
    EXPECT_TRUE(closedOrientedSolid((*numbered)[p])) << "part " << p + 1;
    EXPECT_NEAR(core::signedVolume(a.drilled.parts[p]) - core::signedVolume((*numbered)[p]),
                assembly::labelVolumeMm3(labels[p], options), 1e-3)
        << "part " << p + 1;
    placed += labels[p].placed ? 1 : 0;
  }
  EXPECT_GT(placed, 0);
}

INSTANTIATE_TEST_SUITE_P(KittenAndBunny, DowelsOnSharedModels, ::testing::Values("kitten.off", "bunny.off"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

TEST(Dowels, AWideFaceGetsTwoDowelsFarApartOfDifferentDiameters) {
  const core::ApartPlan plan = stackedBoxes();
  ASSERT_EQ(plan.joints.size(), 1u);
  const assembly::DowelOptions options;
  const assembly::DowelLayout layout = assembly::placeDowels(plan, options);
  ASSERT_EQ(layout.dowels.size(), 2u);
  // 0.2 x sqrt(2400 mm^2) = 9.8 mm, within [3, 8]: 8 mm, and the key 7 mm.
  EXPECT_DOUBLE_EQ(layout.dowels[0].diameterMm, 8.0);
  EXPECT_DOUBLE_EQ(layout.dowels[1].diameterMm, 7.0);
  // Far apart: more than half the face's diagonal (72 mm).
  EXPECT_GT((layout.dowels[0].centre - layout.dowels[1].centre).norm(), 36.0);
  for (const assembly::Dowel& dowel : layout.dowels) {
    EXPECT_DOUBLE_EQ(dowel.lengthMm, 2.0 * dowel.diameterMm);
    EXPECT_NEAR(dowel.centre.z(), 30.0, 0.01);
  }
}

TEST(Dowels, AShallowPartGetsShorterDowels) {
  // Two boxes 60 x 40 x 6 mm: 6 mm deep on each side leaves room for 2 x (6 - 1.2 - 0.3) = 9 mm of dowel.
  core::Decomposition plan;
  core::Region whole;
  whole.mesh = test::makeBox(Vec3(0, 0, 0), Vec3(60, 40, 12));
  plan.regions.push_back(whole);
  core::ApartOptions fit;
  fit.buildVolume = {220, 220, 8};
  const core::ApartPlan apart = *core::apartPlan(plan, fit);
  const assembly::DowelOptions options;
  const assembly::DowelLayout layout = assembly::placeDowels(apart, options);
  ASSERT_FALSE(layout.dowels.empty());
  for (const assembly::Dowel& dowel : layout.dowels) {
    EXPECT_LE(0.5 * dowel.lengthMm + options.depthClearanceMm + options.minWallMm, 6.0 + 1e-9);
    EXPECT_GE(dowel.lengthMm, dowel.diameterMm);
  }
}

TEST(Dowels, DrilledBoxesKeepTheirVolumeBalance) {
  const core::ApartPlan plan = stackedBoxes();
  const assembly::DowelOptions options;
  const assembly::DowelLayout layout = assembly::placeDowels(plan, options);
  const auto drilled = assembly::drillParts(plan, layout, options);
  ASSERT_TRUE(drilled.ok()) << drilled.error().describe();
  double volume = drilled->clearanceVolumeMm3;
  for (const auto& part : drilled->parts) {
    EXPECT_TRUE(closedOrientedSolid(part));
    volume += core::signedVolume(part);
  }
  for (const auto& dowel : drilled->dowels) volume += core::signedVolume(dowel);
  // Boxes have no curved faces: the balance is exact up to rounding.
  EXPECT_NEAR(volume, 60.0 * 40.0 * 60.0, 1e-6 * 60.0 * 40.0 * 60.0);
}

namespace {

// The stacked boxes' parts and dowels, drilled and laid out on a 220 x 220 mm bed.
struct Laid {
  assembly::PlateOptions options;
  assembly::PlateLayout layout;
};

Laid laidBoxes() {
  const core::ApartPlan plan = stackedBoxes();
  const assembly::DowelOptions dowelOptions;
  const assembly::DowelLayout dowels = assembly::placeDowels(plan, dowelOptions);
  const assembly::DrilledParts drilled = *assembly::drillParts(plan, dowels, dowelOptions);
  std::vector<Vec3> directions, axes;
  for (const core::ApartPart& part : plan.parts) directions.push_back(part.printingDirection);
  for (const assembly::Dowel& dowel : dowels.dowels) axes.push_back(dowel.axis);
  Laid laid;
  laid.layout = *assembly::arrangeOnPlates(drilled.parts, directions, drilled.dowels, axes, laid.options);
  return laid;
}

}  // namespace

TEST(Plates, PartsLieCapDownWithinTheBedAndApart) {
  const Laid laid = laidBoxes();
  EXPECT_EQ(laid.layout.plates, 1);
  ASSERT_EQ(laid.layout.items.size(), 4u);  // two parts, two dowels
  std::vector<core::BoundingBox> boxes;
  for (const assembly::PlateItem& item : laid.layout.items) {
    const core::BoundingBox box = core::boundingBox(item.mesh);
    EXPECT_NEAR(box.min.z(), 0.0, 1e-9) << item.name;  // on the bed
    EXPECT_GE(box.min.x(), laid.options.marginMm - 1e-9) << item.name;
    EXPECT_GE(box.min.y(), laid.options.marginMm - 1e-9) << item.name;
    EXPECT_LE(box.max.x(), 220.0 - laid.options.marginMm + 1e-9) << item.name;
    EXPECT_LE(box.max.y(), 220.0 - laid.options.marginMm + 1e-9) << item.name;
    boxes.push_back(box);
  }
  // Both boxes' parts are 30 mm tall as laid, each on a cut face (the upper one upside down).
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(boxes[i].size().z(), 30.0, 1e-6);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const bool apart = boxes[i].max.x() <= boxes[j].min.x() || boxes[j].max.x() <= boxes[i].min.x() ||
                         boxes[i].max.y() <= boxes[j].min.y() || boxes[j].max.y() <= boxes[i].min.y();
      EXPECT_TRUE(apart) << laid.layout.items[i].name << " overlaps " << laid.layout.items[j].name;
    }
}

TEST(ThreeMf, ReadsBackTheSamePartsMeshesAndTransforms) {
  const Laid laid = laidBoxes();
  const std::string path = test::scratchDirectory("ThreeMfReadBack") + "/parts.3mf";
  ASSERT_TRUE(assembly::write3mf(laid.layout, laid.options, path).ok());
  const auto read = assembly::read3mf(path);
  ASSERT_TRUE(read.ok()) << read.error().describe();
  const std::vector<assembly::ThreeMfItem> written = assembly::threeMfItems(laid.layout, laid.options);
  ASSERT_EQ(read->size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    SCOPED_TRACE(written[i].name);
    EXPECT_EQ((*read)[i].name, written[i].name);
    EXPECT_EQ((*read)[i].vertices, written[i].vertices);
    EXPECT_EQ((*read)[i].triangles, written[i].triangles);
    // 3MF stores floats: a micrometre is plenty.
    EXPECT_LT(((*read)[i].transform - written[i].transform).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_NEAR((*read)[i].volumeMm3, written[i].volumeMm3, 1e-4 * written[i].volumeMm3);
  }
}
