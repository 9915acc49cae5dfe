// multidir apart: a plan printed apart on an ordinary printer (docs/apart.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/test_models.h"

namespace fs = std::filesystem;
using multidir::test::readAll;
using multidir::test::runCli;
using multidir::test::scratchDirectory;
using multidir::test::sharedModelPath;

TEST(CliApart, PrintsASavedPlanApartWithPartsDowelsPlatesAndA3mf) {
  const std::string dir = scratchDirectory("CliApartPlan");
  const auto plan = runCli("decompose '" + sharedModelPath("kitten.off") + "' --up y --machine apart --scheme greedy "
                           "--no-supports -o '" + dir + "/plan'", dir);
  ASSERT_EQ(plan.exitCode, 0) << plan.err;
  const auto apart = runCli("apart '" + dir + "/plan' -o '" + dir + "/out' --printer marlin-220 --no-slice", dir);
  ASSERT_EQ(apart.exitCode, 0) << apart.err;
  const nlohmann::json summary = nlohmann::json::parse(readAll(dir + "/out/apart.json"));
  const int parts = summary["parts"].get<int>();
  EXPECT_GE(parts, 2);
  EXPECT_GE(summary["dowels"].get<int>(), 2);
  // The plan's regions come back from binary STL: the same J_G up to float rounding.
  const double planJg = summary["jgPlanMm2"].get<double>();
  EXPECT_LE(summary["jgApartMm2"].get<double>(), planJg + 1e-6 * std::max(1.0, planJg));
  for (int p = 1; p <= parts; ++p) EXPECT_TRUE(fs::exists(dir + "/out/part-0" + std::to_string(p) + ".stl")) << p;
  EXPECT_TRUE(fs::exists(dir + "/out/dowel-01.stl"));
  EXPECT_TRUE(fs::exists(dir + "/out/plate-1.stl"));
  EXPECT_TRUE(fs::exists(dir + "/out/parts.3mf"));
  EXPECT_FALSE(fs::exists(dir + "/out/plate-1.gcode"));  // --no-slice
}

TEST(CliApart, DecomposeKeepsBothPricesOfAPartInThePlan) {
  const std::string dir = scratchDirectory("CliApartPrices");
  const auto plan = runCli("decompose '" + sharedModelPath("kitten.off") + "' --up y --machine apart --scheme greedy "
                           "--part-cost 50 --cut-face-cost 0.5 --no-supports -o '" + dir + "/plan'", dir);
  ASSERT_EQ(plan.exitCode, 0) << plan.err;
  const nlohmann::json saved = nlohmann::json::parse(readAll(dir + "/plan/plan.json"));
  EXPECT_EQ(saved["search"]["partCostMm2"].get<double>(), 50.0);
  EXPECT_EQ(saved["search"]["cutFaceCost"].get<double>(), 0.5);
}

TEST(CliApart, RefusesAModelThatNeedsTooManyPartsForThePrinter) {
  const std::string dir = scratchDirectory("CliApartTooLarge");
  // The knight three times its size (243 x 405 x 123 mm) on a 220 x 220 mm bed, at most 4 parts.
  const auto run = runCli("apart '" + sharedModelPath("knight.off") + "' --up y --scheme greedy --scale 3 "
                          "--max-parts 4 --printer marlin-220 --no-slice -o '" + dir + "/out'", dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("more than 4 parts"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("larger printer"), std::string::npos) << run.err;
}

TEST(CliApart, SlicesEveryPlateAndTheWholeModelWithSupports) {
  const std::string dir = scratchDirectory("CliApartSlice");
  const auto run = runCli("apart '" + sharedModelPath("knight.off") + "' --up y --scheme greedy -o '" + dir +
                              "/out' --printer marlin-220",
                          dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json summary = nlohmann::json::parse(readAll(dir + "/out/apart.json"));
  const int plates = summary["plates"].get<int>();
  ASSERT_GE(plates, 1);
  for (int p = 1; p <= plates; ++p) EXPECT_TRUE(fs::exists(dir + "/out/plate-" + std::to_string(p) + ".gcode"));
  EXPECT_TRUE(fs::exists(dir + "/out/whole.gcode"));
  EXPECT_GT(summary["apartSeconds"].get<double>(), 0.0);
  EXPECT_GT(summary["wholeSeconds"].get<double>(), 0.0);
  EXPECT_NE(run.out.find("One piece with supports"), std::string::npos) << run.out;
}

TEST(CliApart, NumbersEveryPartWithRoomAndNamesThoseWithout) {
  const std::string dir = scratchDirectory("CliApartNumbers");
  const auto run = runCli("apart '" + sharedModelPath("knight.off") + "' --up y --scheme greedy -o '" + dir +
                              "/out' --printer marlin-220 --no-slice",
                          dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json summary = nlohmann::json::parse(readAll(dir + "/out/apart.json"));
  const nlohmann::json& labels = summary["labels"];
  ASSERT_EQ(labels.size(), summary["parts"].get<std::size_t>());
  int placed = 0;
  for (std::size_t p = 0; p < labels.size(); ++p) {
    EXPECT_EQ(labels[p]["number"].get<std::string>(), std::to_string(p + 1));
    if (labels[p]["placed"].get<bool>()) {
      ++placed;
      EXPECT_GE(labels[p]["joint"].get<int>(), 1);
    } else {
      EXPECT_NE(run.out.find("Part " + std::to_string(p + 1) + ": " + labels[p]["note"].get<std::string>()),
                std::string::npos);
    }
  }
  EXPECT_GE(placed, 1);
  EXPECT_EQ(summary["partsNumbered"].get<int>(), placed);
}

TEST(CliApart, WritesAnAssemblySheetWhosePicturesArePngFilesBesideIt) {
  const std::string dir = scratchDirectory("CliApartSheet");
  const auto run = runCli("apart '" + sharedModelPath("knight.off") + "' --up y --scheme greedy -o '" + dir +
                              "/out' --printer marlin-220 --no-slice",
                          dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string html = readAll(dir + "/out/assembly.html");
  const nlohmann::json summary = nlohmann::json::parse(readAll(dir + "/out/apart.json"));
  const int parts = summary["parts"].get<int>();
  int pictures = 0;
  for (std::size_t at = html.find("src=\""); at != std::string::npos; at = html.find("src=\"", at + 1)) {
    const std::string name = html.substr(at + 5, html.find('"', at + 5) - at - 5);
    const std::string png = readAll(dir + "/out/" + name);
    ASSERT_GE(png.size(), 8u) << name;
    EXPECT_EQ(png.substr(1, 3), "PNG") << name;
    ++pictures;
  }
  // The parts, a step for each part after the first, a plate at least.
  EXPECT_GE(pictures, 1 + (parts - 1) + 1);
  int steps = 0;
  for (std::size_t at = html.find("<h3>Step "); at != std::string::npos; at = html.find("<h3>Step ", at + 1)) ++steps;
  EXPECT_EQ(steps, parts - 1);
}
