// The print-apart pipeline (apart/print_apart.h, docs/apart.md): cancelling it, and the support the slicer
// gives each plate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "multidir/apart/print_apart.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir;
namespace fs = std::filesystem;

namespace {

// `mesh` as a plan of one region printed along +Z (what `multidir decompose` gives a model it leaves whole).
core::Decomposition onePiecePlan(core::TriangleMesh mesh) {
  mesh.resetOrigins();
  core::Decomposition plan;
  core::Region region;
  region.volumeMm3 = core::signedVolume(mesh);
  const core::Result<core::OverhangAnalysis> overhang = core::analyzeOverhang(mesh, core::Vec3::UnitZ());
  if (!overhang) throw std::runtime_error(overhang.error().describe());
  region.riskyAreaMm2 = overhang->riskyAreaMm2;
  region.mesh = std::move(mesh);
  plan.jgBeforeMm2 = plan.jgAfterMm2 = region.riskyAreaMm2;
  plan.regions.push_back(std::move(region));
  return plan;
}

apart::PrintApartOptions onTheMarlin220() {
  apart::PrintApartOptions options;
  core::Result<slicing::PrinterProfile> printer = slicing::loadPrinterProfile("marlin-220");
  if (!printer) throw std::runtime_error(printer.error().describe());
  options.printer = std::move(*printer);
  return options;
}

// `plan` printed apart on the Marlin 220 into the scratch folder `scratch`, which must give one plate: its estimate.
void printOnOnePlate(const core::Decomposition& plan, const std::string& scratch, slicing::Estimate& estimate) {
  const std::string dir = test::scratchDirectory(scratch);
  core::JobContext job;
  const core::Result<apart::ApartResult> result = apart::printApart(plan, onTheMarlin220(), dir + "/out", job);
  ASSERT_TRUE(result.ok()) << result.error().describe();
  ASSERT_EQ(result->plateEstimates.size(), 1u);
  estimate = result->plateEstimates.front().estimate;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The entries of `folder`, names only, sorted.
std::vector<std::string> entries(const std::string& folder) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST(PrintApart, CancelWhileSlicingLeavesNoOutputFolder) {
  const std::string dir = test::scratchDirectory("PrintApartCancel");
  const core::Decomposition plan = onePiecePlan(test::makeBox({0, 0, 0}, {20, 20, 20}));
  // The cancel comes the moment the first plate's slicing starts: the parts and the 3MF are written by then.
  std::shared_ptr<core::JobContext> job;
  job = std::make_shared<core::JobContext>([&job](double, const std::string& phase) {
    if (phase.rfind("slicing plate 1", 0) == 0) job->cancel();
  });
  const core::Result<apart::ApartResult> result = apart::printApart(plan, onTheMarlin220(), dir + "/out", *job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, core::ErrorCode::Cancelled) << result.error().describe();
  EXPECT_FALSE(fs::exists(dir + "/out"));
  EXPECT_TRUE(entries(dir).empty()) << "left behind: " << entries(dir).front();  // no staged folder either
}

TEST(PrintApart, CancelLeavesAnEarlierOutputAsItWas) {
  const std::string dir = test::scratchDirectory("PrintApartCancelKeeps");
  fs::create_directories(dir + "/out");
  std::ofstream(dir + "/out/apart.json") << "{\"earlier\": true}\n";
  const core::Decomposition plan = onePiecePlan(test::makeBox({0, 0, 0}, {20, 20, 20}));
  std::shared_ptr<core::JobContext> job;
  job = std::make_shared<core::JobContext>([&job](double, const std::string& phase) {
    if (phase.rfind("slicing plate 1", 0) == 0) job->cancel();
  });
  const core::Result<apart::ApartResult> result = apart::printApart(plan, onTheMarlin220(), dir + "/out", *job);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(entries(dir + "/out"), std::vector<std::string>{"apart.json"});
  EXPECT_EQ(readAll(dir + "/out/apart.json"), "{\"earlier\": true}\n");
}

TEST(PrintApart, APlateWhosePartHasRiskyAreaGetsTheSlicersSupport) {
  const std::string dir = test::scratchDirectory("PrintApartSupport");
  // A T on its stem: the bar's undersides overhang 15 mm on either side, 20 mm above the bed.
  const core::Decomposition plan = onePiecePlan(test::makeTBar(10, 20, 40, 5, 10));
  ASSERT_GT(plan.regions.front().riskyAreaMm2, 0.0);
  core::JobContext job;
  const core::Result<apart::ApartResult> result = apart::printApart(plan, onTheMarlin220(), dir + "/out", job);
  ASSERT_TRUE(result.ok()) << result.error().describe();
  ASSERT_EQ(result->plateEstimates.size(), 1u);
  EXPECT_GT(result->plateEstimates.front().estimate.supportCm3, 0.0);
}

TEST(PrintApart, APlateOfSupportFreePartsGetsNoSupport) {
  slicing::Estimate plate;
  ASSERT_NO_FATAL_FAILURE(
      printOnOnePlate(onePiecePlan(test::makeBox({0, 0, 0}, {20, 20, 20})), "PrintApartNoSupport", plate));
  EXPECT_GT(plate.printSeconds, 0.0);
  EXPECT_EQ(plate.supportCm3, 0.0);
}

namespace {

// A prism 20 mm tall and deep whose right side leans out over the bed, its normal `degreesFromDown` from
// straight down (the face's slope from the horizontal, as PrusaSlicer measures it).
core::TriangleMesh leaningPrism(double degreesFromDown) {
  const double run = 20.0 / std::tan(degreesFromDown * 3.14159265358979323846 / 180.0);
  return test::makeExtrudedProfile(
      {core::Vec3(0, 0, 0), core::Vec3(10, 0, 0), core::Vec3(10 + run, 0, 20), core::Vec3(0, 0, 20)}, 20.0);
}

}  // namespace

TEST(PrintApart, TheSlicersSupportThresholdIsOneDegreeBelowAlphaForItsInclusiveRule) {
  EXPECT_EQ(apart::slicerSupportThreshold(45.0), 44);
  EXPECT_EQ(apart::slicerSupportThreshold(45.7), 44);
  EXPECT_EQ(apart::slicerSupportThreshold(1.0), 1);  // 0 would be the slicer's automatic rule
}

TEST(PrintApart, APartWhoseFacesAreAllWithinAlphaGetsNoSupportFromTheSlicer) {
  // The kitten's middle part leaned 4,668 mm^2 of its faces 45 to 46 degrees from down, risk-free by J_G at
  // alpha_max = 45 (docs/apart.md, "Where the slicer puts support").
  const core::Decomposition plan = onePiecePlan(leaningPrism(45.5));
  ASSERT_EQ(plan.regions.front().riskyAreaMm2, 0.0);
  slicing::Estimate plate;
  ASSERT_NO_FATAL_FAILURE(printOnOnePlate(plan, "PrintApartWithinAlpha", plate));
  EXPECT_EQ(plate.supportCm3, 0.0);
}

TEST(PrintApart, APartWithAFaceBeyondAlphaGetsTheSlicersSupport) {
  const core::Decomposition plan = onePiecePlan(leaningPrism(43.0));
  ASSERT_GT(plan.regions.front().riskyAreaMm2, 0.0);
  slicing::Estimate plate;
  ASSERT_NO_FATAL_FAILURE(printOnOnePlate(plan, "PrintApartBeyondAlpha", plate));
  EXPECT_GT(plate.supportCm3, 0.0);
}
