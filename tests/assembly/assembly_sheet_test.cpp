// The assembly sheet of a plan printed apart (docs/apart.md, "Assembly sheet"): gluing order, pictures, page.
#include <gtest/gtest.h>

#include <zlib.h>

#include <set>

#include "multidir/assembly/assembly_sheet.h"
#include "multidir/assembly/picture.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "support/primitives.h"

using namespace multidir;
using core::Vec3;

namespace {

// A box 60 x 40 x 90 mm on a printer 40 mm tall: cut across its height until every part fits (4 parts).
core::ApartPlan tallBox() {
  core::Decomposition plan;
  core::Region whole;
  whole.mesh = test::makeBox(Vec3(0, 0, 0), Vec3(60, 40, 90));
  plan.regions.push_back(whole);
  core::ApartOptions options;
  options.buildVolume = {220, 220, 40};
  return *core::apartPlan(plan, options);
}

std::uint32_t big32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
}

}  // namespace

TEST(AssemblySheet, GluingStartsWithPartOneAndGluesEveryJointOnceOntoWhatIsAlreadyGlued) {
  const core::ApartPlan plan = tallBox();
  ASSERT_GE(plan.parts.size(), 3u);
  const std::vector<assembly::GluingStep> steps = assembly::gluingOrder(plan);
  ASSERT_EQ(steps.size(), plan.parts.size());
  EXPECT_EQ(steps.front().part, 0);
  EXPECT_TRUE(steps.front().joints.empty());
  std::set<int> glued, joints;
  for (const assembly::GluingStep& step : steps) {
    EXPECT_TRUE(glued.insert(step.part).second) << "part " << step.part + 1 << " glued twice";
    if (step.part != 0) {
      EXPECT_FALSE(step.joints.empty()) << "part " << step.part + 1 << " glued onto nothing";
    }
    for (int j : step.joints) {
      EXPECT_TRUE(joints.insert(j).second) << "joint " << j + 1 << " glued twice";
      const core::ApartJoint& joint = plan.joints[static_cast<std::size_t>(j)];
      const int other = joint.upper == step.part ? joint.lower : joint.upper;
      EXPECT_TRUE(glued.count(other)) << "joint " << j + 1 << " meets a part not glued yet";
    }
  }
  EXPECT_EQ(joints.size(), plan.joints.size());
}

TEST(Picture, AFaceTowardTheEyeIsDrawnInItsColourAndNothingElseIsWhite) {
  const core::TriangleMesh box = test::makeBox(Vec3(0, 0, 0), Vec3(10, 10, 10));
  assembly::View view;  // looking along -z, y up
  view.width = 100;
  view.height = 100;
  const assembly::Image image = assembly::render({{&box, assembly::Colour(0.2, 0.4, 0.8), Vec3::Zero()}}, {}, view);
  ASSERT_EQ(image.rgb.size(), 3u * 100 * 100);
  // Only the top face (z = 10) faces the eye, squarely: its full colour.
  EXPECT_TRUE(image.at(50, 50).isApprox(assembly::Colour(0.2, 0.4, 0.8), 0.01)) << image.at(50, 50).transpose();
  // The margin around the fitted box stays white.
  EXPECT_TRUE(image.at(1, 1).isApprox(assembly::Colour(1, 1, 1), 1e-9));
  EXPECT_TRUE(image.at(98, 50).isApprox(assembly::Colour(1, 1, 1), 1e-9));
}

TEST(Picture, PngHasItsSignatureChunksWithValidCrcsAndTheRowsUncompressed) {
  assembly::Image image;
  image.width = 3;
  image.height = 2;
  image.rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30, 40, 50, 60, 70, 80, 90};
  const std::vector<std::uint8_t> png = assembly::encodePng(image);
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(std::vector<std::uint8_t>(png.begin(), png.begin() + 8),
            (std::vector<std::uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
  std::vector<std::string> types;
  std::vector<std::uint8_t> idat;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length = big32(png, at);
    const std::string type(png.begin() + static_cast<std::ptrdiff_t>(at + 4), png.begin() + static_cast<std::ptrdiff_t>(at + 8));
    types.push_back(type);
    const uLong crc = crc32(0L, png.data() + at + 4, static_cast<uInt>(length + 4));
    EXPECT_EQ(big32(png, at + 8 + length), static_cast<std::uint32_t>(crc)) << type;
    if (type == "IHDR") {
      EXPECT_EQ(big32(png, at + 8), 3u);
      EXPECT_EQ(big32(png, at + 12), 2u);
    }
    if (type == "IDAT") idat.insert(idat.end(), png.begin() + static_cast<std::ptrdiff_t>(at + 8), png.begin() + static_cast<std::ptrdiff_t>(at + 8 + length));
    at += 12 + length;
  }
  EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
  std::vector<std::uint8_t> rows(2 * (1 + 3 * 3));
  uLongf size = static_cast<uLongf>(rows.size());
  ASSERT_EQ(uncompress(rows.data(), &size, idat.data(), static_cast<uLong>(idat.size())), Z_OK);
  EXPECT_EQ(rows, (std::vector<std::uint8_t>{0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 10, 20, 30, 40, 50, 60, 70, 80, 90}));
}

TEST(AssemblySheet, ThePageShowsEveryPartStepAndPlateAndSaysWhichPartsHaveNoNumber) {
  const core::ApartPlan plan = tallBox();
  const assembly::DowelOptions dowelOptions;
  const assembly::DowelLayout layout = assembly::placeDowels(plan, dowelOptions);
  const auto drilled = assembly::drillParts(plan, layout, dowelOptions);
  ASSERT_TRUE(drilled.ok());
  std::vector<assembly::PartLabel> labels = assembly::placeLabels(plan, layout, dowelOptions, assembly::LabelOptions{});
  labels[1].placed = false;  // as if its faces had no room
  labels[1].note = "no joint face has room for its number beside the dowel holes: mark it by hand";
  std::vector<core::Vec3> directions, axes;
  for (const core::ApartPart& part : plan.parts) directions.push_back(part.printingDirection);
  for (const assembly::Dowel& dowel : layout.dowels) axes.push_back(dowel.axis);
  const auto plates = assembly::arrangeOnPlates(drilled->parts, directions, drilled->dowels, axes, {});
  ASSERT_TRUE(plates.ok());
  assembly::SheetInput input;
  input.title = "tall box";
  input.plan = &plan;
  input.layout = &layout;
  input.labels = &labels;
  input.parts = &drilled->parts;
  input.dowels = &drilled->dowels;
  input.plates = &*plates;
  input.estimates = {{"Plate 1", 3600, 12.5, 0.0}, {"One piece with supports", 4000, 14.0, 1.5}};
  const auto sheet = assembly::assemblySheet(input);
  ASSERT_TRUE(sheet.ok()) << sheet.error().describe();
  // The exploded parts, one picture per gluing step after the first, one per plate.
  EXPECT_EQ(sheet->pictures.size(), 1 + (plan.parts.size() - 1) + static_cast<std::size_t>(plates->plates));
  for (const assembly::SheetPicture& picture : sheet->pictures) {
    EXPECT_NE(sheet->html.find("src=\"" + picture.name + "\""), std::string::npos) << picture.name;
    EXPECT_GT(picture.png.size(), 100u);
  }
  for (std::size_t k = 1; k < plan.parts.size(); ++k)
    EXPECT_NE(sheet->html.find("Step " + std::to_string(k) + ":"), std::string::npos) << k;
  EXPECT_NE(sheet->html.find("none: no joint face has room"), std::string::npos);
  EXPECT_NE(sheet->html.find("One piece with supports"), std::string::npos);
  EXPECT_NE(sheet->html.find("1h 00m 00s"), std::string::npos);
}
