// The G-code preview's geometry: moves after each step's marker only (travels from its first extrusion on), layers numbered over the job in
// printing order, each step's pose undone so its toolpaths lie in the model's coordinates.
#include "ui/viewer/gcode_toolpaths.h"

#include <gtest/gtest.h>

#include <cmath>

namespace multidir::ui {
namespace {

slicing::GcodeProgram programOf(const std::string& text) {
  const core::Result<slicing::GcodeProgram> program = slicing::parseGcode(text);
  EXPECT_TRUE(program.ok()) << program.error().describe();
  return program ? *program : slicing::GcodeProgram{};
}

// A start sequence with a purge, then two layers of one step, with a travel between.
const char* const kTwoLayers =
    "; MULTIDIR START SEQUENCE\n"
    "G90\nM82\nG92 E0\nG1 Z0.3 F600\nG1 X0 Y0 E5 F1500 ; purge\nG1 X0 Y10 E6\nG92 E0\n"
    "; MULTIDIR STEP %d\n"
    "G1 X10 Y10 F6000\n"   // travel to the part
    "G1 X20 Y10 E1 F1200\n"
    "G1 X20 Y20 E2\n"
    "G1 Z0.6 F600\n"       // lift to the next layer
    "G1 X10 Y20 E3\n"
    "G1 E2.5\n"            // a retraction in place: neither
    "; MULTIDIR END SEQUENCE\n"
    "G1 Z20 F600\nG1 X0 Y200 F6000\n";

std::string stepText(int step) {
  char text[1024];
  std::snprintf(text, sizeof text, kTwoLayers, step);
  return text;
}

TEST(GcodeToolpaths, OnlyTheStepsOwnMovesCountAndLayersRiseWithTheExtrusions) {
  const GcodePreview preview = buildGcodePreview({{1, programOf(stepText(1)), Eigen::Isometry3d::Identity()}});
  ASSERT_EQ(preview.extrusions.size(), 3u);  // the purge and the end sequence are left out
  ASSERT_EQ(preview.layerCount(), 2);
  EXPECT_EQ(preview.extrusions[0].layer, 1);
  EXPECT_EQ(preview.extrusions[1].layer, 1);
  EXPECT_EQ(preview.extrusions[2].layer, 2);
  ASSERT_EQ(preview.travels.size(), 1u);  // the lift; the approach from the start sequence is left out
  EXPECT_EQ(preview.travels[0].layer, 1);
  EXPECT_EQ(preview.extrusionsUpTo(1), 2u);
  EXPECT_EQ(preview.extrusionsUpTo(0), 0u);
  EXPECT_EQ(preview.extrusionsUpTo(99), 3u);
}

TEST(GcodeToolpaths, LayersAreNumberedOverTheJobAndEachStepsPoseIsUndone) {
  // Step 2 was printed with the part turned a quarter turn about X and lifted 5 mm: its toolpaths go back.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.rotate(Eigen::AngleAxisd(M_PI / 2.0, core::Vec3::UnitX()));
  pose.pretranslate(core::Vec3(0.0, 0.0, 5.0));
  const GcodePreview preview = buildGcodePreview({{1, programOf(stepText(1)), Eigen::Isometry3d::Identity()},
                                                  {2, programOf(stepText(2)), pose}});
  ASSERT_EQ(preview.layerCount(), 4);
  EXPECT_EQ(preview.layers[2].step, 2);
  EXPECT_EQ(preview.layers[2].layerInStep, 1);
  ASSERT_EQ(preview.extrusions.size(), 6u);
  const ToolpathSegment& first = preview.extrusions[3];
  EXPECT_EQ(first.step, 2);
  EXPECT_EQ(first.layer, 3);
  const core::Vec3 printed(20.0, 10.0, 0.3);
  EXPECT_LT((first.to - pose.inverse() * printed).norm(), 1e-9);
  EXPECT_LT((pose * first.to - printed).norm(), 1e-9);
  EXPECT_EQ(preview.extrusionsUpTo(2), 3u);
  EXPECT_EQ(preview.travelsUpTo(2), 1u);
}

TEST(GcodeToolpaths, SegmentsKnowTheirLineAndTheAuditsUnsupportedLinesMarkOnlyThatStepsExtrusions) {
  const GcodePreview unmarked = buildGcodePreview({{1, programOf(stepText(1)), Eigen::Isometry3d::Identity()},
                                                   {2, programOf(stepText(2)), Eigen::Isometry3d::Identity()}});
  ASSERT_EQ(unmarked.extrusions.size(), 6u);
  // Each step's file: the marker on line 9, the extrusions on lines 11, 12 and 14.
  const int lines[3] = {11, 12, 14};
  for (std::size_t i = 0; i < unmarked.extrusions.size(); ++i) {
    EXPECT_EQ(unmarked.extrusions[i].line, lines[i % 3]) << i;
    EXPECT_FALSE(unmarked.extrusions[i].unsupported) << i;
  }
  EXPECT_EQ(unmarked.travels[0].line, 13);
  EXPECT_FALSE(unmarked.audited);

  GcodePreview preview = unmarked;
  EXPECT_EQ(markUnsupported(preview, 2, {12, 14, 99}), 2u);  // a line that is no extrusion marks nothing
  for (std::size_t i = 0; i < preview.extrusions.size(); ++i)
    EXPECT_EQ(preview.extrusions[i].unsupported, i == 4 || i == 5) << i;  // step 1's lines 12 and 14 are not
  EXPECT_EQ(markUnsupported(preview, 3, {11}), 0u);                       // no such step
  EXPECT_EQ(markUnsupported(preview, 1, {}), 0u);
}

}  // namespace
}  // namespace multidir::ui
