// The cell file: the shipped paper cell loads; each problem a lab can make is named with its key.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "multidir/robot/cell.h"
#include "support/test_models.h"

namespace multidir::robot {
namespace {

const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

nlohmann::json shippedCell() {
  std::ifstream in(kShippedCell);
  return nlohmann::json::parse(in);
}

std::string written(const std::string& test, const nlohmann::json& cell) {
  const std::string path = test::scratchDirectory("RobotCell." + test) + "/cell.json";
  std::ofstream(path) << cell.dump(2);
  return path;
}

// The problems of `cell`, as "key: message" lines.
std::string problemsOf(const std::string& test, const nlohmann::json& cell) {
  const auto parsed = parseCell(written(test, cell));
  if (!parsed.ok()) return "parse: " + parsed.error().message;
  std::string all;
  for (const auto& p : checkCell(parsed.value())) all += p.key + ": " + p.message + "\n";
  return all;
}

TEST(RobotCell, ShippedPaperCellLoadsAsAUr5WithItsBodies) {
  const auto cell = loadCell(kShippedCell);
  ASSERT_TRUE(cell.ok()) << cell.error().describe();
  EXPECT_EQ(cell->arm.name, "ur5");
  EXPECT_EQ(cell->boxes.size(), 3u);
  EXPECT_EQ(cell->cylinders.size(), 1u);
  EXPECT_NEAR(cell->nozzleAxis.z(), 1.0, 1e-12);
  EXPECT_NEAR(cell->flangeToPlatform.translation().z(), 50.0, 1e-12);
  // Elbow limited to +-180 deg in the paper cell.
  EXPECT_NEAR(cell->arm.limits[2].maxRad, 3.14159265358979323846, 1e-12);
}

TEST(RobotCell, UnknownModelIsRefusedNamingTheKnownOnes) {
  nlohmann::json cell = shippedCell();
  cell["robot"] = "ur7";
  const auto parsed = parseCell(written("UnknownModel", cell));
  ASSERT_FALSE(parsed.ok());
  EXPECT_EQ(parsed.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(parsed.error().message.find("robot"), std::string::npos);
  EXPECT_NE(parsed.error().message.find("ur5e"), std::string::npos);
}

TEST(RobotCell, MissingKeyIsNamed) {
  nlohmann::json cell = shippedCell();
  cell.erase("nozzleTipMm");
  const auto parsed = parseCell(written("MissingKey", cell));
  ASSERT_FALSE(parsed.ok());
  EXPECT_EQ(parsed.error().code, core::ErrorCode::MalformedFile);
  EXPECT_NE(parsed.error().message.find("nozzleTipMm is missing"), std::string::npos) << parsed.error().message;
}

TEST(RobotCell, NozzleAxisNotUnitIsAProblem) {
  nlohmann::json cell = shippedCell();
  cell["nozzleAxis"] = {0, 0, 2};
  EXPECT_NE(problemsOf("NozzleAxis", cell).find("nozzleAxis: has length 2"), std::string::npos);
}

TEST(RobotCell, HomeOutsideTheLimitsIsAProblem) {
  nlohmann::json cell = shippedCell();
  cell["homeDegrees"][2] = 200;  // the paper cell limits the elbow to +-180
  EXPECT_NE(problemsOf("HomeOutsideLimits", cell).find("homeDegrees[2]: is 200.0 deg, outside the joint's limits"),
            std::string::npos);
}

TEST(RobotCell, HomeHoldingThePlatformIntoTheTableIsAProblem) {
  nlohmann::json cell = shippedCell();
  cell["homeDegrees"] = {0, 0, 90, 0, 90, 0};  // the upper arm level: the forearm points down into the table
  EXPECT_NE(problemsOf("HomeIntoTable", cell).find("homeDegrees: puts the platform's lowest point"), std::string::npos);
}

TEST(RobotCell, TableAboveTheNozzleIsAProblem) {
  nlohmann::json cell = shippedCell();
  cell["tableZMm"] = 450;
  EXPECT_NE(problemsOf("TableAbove", cell).find("tableZMm: is 450.0 mm, not below the nozzle tip"), std::string::npos);
}

TEST(RobotCell, MalformedBodiesAreProblems) {
  nlohmann::json cell = shippedCell();
  cell["bodies"][0]["sizeMm"] = {24, 0, 20};
  cell["bodies"][3]["axis"] = {0, 0, 3};
  const std::string problems = problemsOf("Bodies", cell);
  EXPECT_NE(problems.find("bodies \"heater block\".sizeMm: every edge must be above 0"), std::string::npos) << problems;
  EXPECT_NE(problems.find("bodies \"mount column\".axis: must be a unit vector"), std::string::npos) << problems;
}

TEST(RobotCell, FlangeToPlatformFarFromTheFlangeIsAProblem) {
  nlohmann::json cell = shippedCell();
  cell["flangeToPlatform"]["translationMm"] = {0, 0, 800};
  EXPECT_NE(problemsOf("FlangeFar", cell).find("flangeToPlatform.translationMm: puts the platform centre 800.0 mm"),
            std::string::npos);
}

TEST(RobotCell, LoadCellRefusesACellWithProblemsListingThemAll) {
  nlohmann::json cell = shippedCell();
  cell["nozzleAxis"] = {0, 0, 2};
  cell["tableZMm"] = 450;
  const auto loaded = loadCell(written("LoadRefuses", cell));
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message.find("2 problem(s)"), std::string::npos) << loaded.error().message;
}

}  // namespace
}  // namespace multidir::robot
