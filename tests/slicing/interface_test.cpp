// Interfaces between steps (docs/slicing.md, "Interfaces between steps"): a later step's first layer is an
// interior layer printed onto the lower step's top skin, not the bottom of a part on a bed.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "multidir/core/samples/samples.h"
#include "multidir/slicing/slice_job.h"
#include "slicing_fixtures.h"
#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;
using core::Vec3;

namespace {

// Extruded length per PrusaSlicer feature (";TYPE:" comments) on one layer of one step of a program, and the
// fastest extruding feed there (mm/min). Layers count from 1 after the step's marker (";LAYER_CHANGE").
struct LayerFeatures {
  std::map<std::string, double> lengthMm;
  double fastestFeedMmPerMin = 0.0;
};

LayerFeatures featuresOf(const std::string& text, int step, int layer) {
  LayerFeatures out;
  std::istringstream lines(text);
  std::string line, type;
  bool inStep = false;
  int layerNow = 0;
  double x = 0, y = 0, e = 0, feed = 0;
  bool relative = false;
  while (std::getline(lines, line)) {
    if (line.rfind("; MULTIDIR STEP ", 0) == 0) inStep = std::stoi(line.substr(16)) == step;
    if (line.rfind("; MULTIDIR END SEQUENCE", 0) == 0 || line.rfind("; MULTIDIR TRANSITION", 0) == 0) inStep = false;
    if (line.rfind(";LAYER_CHANGE", 0) == 0 && inStep) ++layerNow;
    if (line.rfind(";TYPE:", 0) == 0) type = line.substr(6);
    if (line.rfind("M83", 0) == 0) relative = true;
    if (line.rfind("M82", 0) == 0) relative = false;
    if (line.rfind("G92", 0) == 0 && line.find(" E") != std::string::npos) e = 0;
    if (line.rfind("G1 ", 0) != 0 && line.rfind("G0 ", 0) != 0) continue;
    double nx = x, ny = y, ne = relative ? 0.0 : e;
    bool hasE = false;
    std::istringstream words(line.substr(0, line.find(';')));
    std::string word;
    while (words >> word) {
      const double value = word.size() > 1 ? std::atof(word.c_str() + 1) : 0.0;
      if (word[0] == 'X') nx = value;
      if (word[0] == 'Y') ny = value;
      if (word[0] == 'F') feed = value;
      if (word[0] == 'E') {
        ne = value;
        hasE = true;
      }
    }
    const double pushed = hasE ? (relative ? ne : ne - e) : 0.0;
    const double length = std::hypot(nx - x, ny - y);
    if (inStep && layerNow == layer && pushed > 1e-9 && length > 1e-9) {
      out.lengthMm[type] += length;
      out.fastestFeedMmPerMin = std::max(out.fastestFeedMmPerMin, feed);
    }
    x = nx;
    y = ny;
    if (hasE && !relative) e = ne;
  }
  return out;
}

double lengthOf(const LayerFeatures& f, const std::string& type) {
  const auto it = f.lengthMm.find(type);
  return it == f.lengthMm.end() ? 0.0 : it->second;
}

// The snowman on the Klipper printer's rotary axis with the profile's own skins and infill (0.3 mm layers).
struct SlicedSnowman {
  core::Result<SlicedJob> sliced = core::Error{core::ErrorCode::Internal, "not sliced", "test"};
  std::string dir;
};

const SlicedSnowman& slicedSnowman() {
  static const SlicedSnowman out = [] {
    SlicedSnowman s;
    const core::Result<core::TriangleMesh> snowman = core::samples::makeSample("snowman");
    if (!snowman) throw std::runtime_error(snowman.error().describe());
    core::MachineSpec machine;
    machine.kind = core::MachineKind::RotaryPlatform;
    machine.up = Vec3::UnitZ();
    machine.rotationAxis = Vec3::UnitX();
    const core::LoadedPlan plan = test::plannedInMemory(*snowman, machine, "snowman", 0.5);
    core::Result<PrinterProfile> profile = loadPrinterProfile("klipper-rotary");
    if (!profile) throw std::runtime_error(profile.error().describe());
    SliceJobOptions options;
    options.settings = {{"layer_height", "0.3"}, {"first_layer_height", "0.3"}, {"fill_density", "15%"},
                        {"bottom_solid_layers", "3"}, {"top_solid_layers", "3"}};
    options.fixedDirection = false;
    // ctest runs each test in its own process, side by side: each slices into its own folder.
    s.dir = test::scratchDirectory(std::string("interface.snowman.") +
                                   testing::UnitTest::GetInstance()->current_test_info()->name());
    core::JobContext context;
    s.sliced = sliceJob(test::machineJob(plan), *profile, options, s.dir, context);
    return s;
  }();
  return out;
}

}  // namespace

TEST(Interfaces, ALaterStepsFirstLayerIsSparseInfillNotABottomSkin) {
  const SlicedSnowman& s = slicedSnowman();
  ASSERT_TRUE(s.sliced.ok()) << s.sliced.error().describe();
  ASSERT_GE(s.sliced->steps.size(), 2u);
  const std::string text = test::readFile(s.dir + "/" + s.sliced->steps[1].gcodeFile);
  const LayerFeatures first = featuresOf(text, s.sliced->steps[1].index, 1);
  ASSERT_GT(lengthOf(first, "Perimeter") + lengthOf(first, "External perimeter"), 0.0) << "no first layer found";
  // A bottom skin would fill the base plane with solid infill; an interior layer is mostly sparse infill.
  EXPECT_GT(lengthOf(first, "Internal infill"), lengthOf(first, "Solid infill"));
}

TEST(Interfaces, TheStepBelowClosesTheCutFaceWithATopSkin) {
  const SlicedSnowman& s = slicedSnowman();
  ASSERT_TRUE(s.sliced.ok()) << s.sliced.error().describe();
  ASSERT_GE(s.sliced->steps.size(), 2u);
  // Step 1 ends at the cut face step 2 stands on: its last layers close it.
  const std::string text = test::readFile(s.dir + "/" + s.sliced->steps[0].gcodeFile);
  double topSkin = 0.0;
  for (int layer = 1; layer < 2000; ++layer) {
    const LayerFeatures f = featuresOf(text, s.sliced->steps[0].index, layer);
    if (f.lengthMm.empty()) break;
    topSkin += lengthOf(f, "Top solid infill");
  }
  EXPECT_GT(topSkin, 0.0);
}

TEST(Interfaces, ALaterStepsFirstLayerIsPrintedAtTheNormalSpeedNotTheBedsFirstLayerSpeed) {
  const SlicedSnowman& s = slicedSnowman();
  ASSERT_TRUE(s.sliced.ok()) << s.sliced.error().describe();
  ASSERT_GE(s.sliced->steps.size(), 2u);
  const double firstLayerSpeed = 30.0 * 60.0;  // PrusaSlicer's first_layer_speed (the profile keeps it)
  const LayerFeatures step1 =
      featuresOf(test::readFile(s.dir + "/" + s.sliced->steps[0].gcodeFile), s.sliced->steps[0].index, 1);
  const LayerFeatures step2 =
      featuresOf(test::readFile(s.dir + "/" + s.sliced->steps[1].gcodeFile), s.sliced->steps[1].index, 1);
  EXPECT_LE(step1.fastestFeedMmPerMin, firstLayerSpeed + 1e-6) << "the bed's first layer is slow";
  EXPECT_GT(step2.fastestFeedMmPerMin, firstLayerSpeed) << "a first layer on plastic need not be";
}
