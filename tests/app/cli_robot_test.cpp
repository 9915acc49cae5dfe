// The robot cell's commands: `multidir cell check`, `multidir robot-program` on a kitten job sliced with the
// cell's profile, `multidir cell reach`.
#include <gtest/gtest.h>
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::runCli;

const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

std::string quoted(const std::string& path) { return "'" + path + "'"; }

// The kitten at half size, 5-DOF greedy, sliced coarse with the cell's profile into `dir`/job.
void sliceKitten(const std::string& dir) {
  const CliRun decomposed = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                       " --up y --machine 5dof --scheme greedy --scale 0.5 -o " + quoted(dir + "/plan"),
                                   dir);
  ASSERT_EQ(decomposed.exitCode, 0) << decomposed.err;
  const CliRun sliced = runCli("slice " + quoted(dir + "/plan") +
                                   " --printer ur5-cell-0.8 --no-comparison --set 'layer_height=0.6 "
                                   "first_layer_height=0.6 perimeters=1 top_solid_layers=1 bottom_solid_layers=1 "
                                   "fill_density=0%' -o " + quoted(dir + "/job"),
                               dir);
  ASSERT_EQ(sliced.exitCode, 0) << sliced.err;
}

TEST(CliRobot, CellCheckFindsThePaperCellSound) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.CellCheckSound");
  const CliRun run = runCli("cell check " + quoted(kShippedCell), dir);
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("sound"), std::string::npos);
  EXPECT_NE(run.out.find("ur5"), std::string::npos);
}

TEST(CliRobot, CellCheckNamesEveryProblemsKey) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.CellCheckProblems");
  std::ifstream in(kShippedCell);
  nlohmann::json cell = nlohmann::json::parse(in);
  cell["nozzleAxis"] = {0, 0.5, 0};
  cell["homeDegrees"][2] = 270;
  std::ofstream(dir + "/cell.json") << cell.dump();
  const CliRun run = runCli("cell check " + quoted(dir + "/cell.json"), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("2 problem(s)"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("nozzleAxis: has length 0.5"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("homeDegrees[2]: is 270.0 deg"), std::string::npos) << run.err;
}

// With the cell's platform as large as the plan's platform region (docs/robot-cell.md, "The platform").
TEST(CliRobot, RobotProgramWritesTheContractsFolder) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.RobotProgramWrites");
  sliceKitten(dir);
  std::ifstream jobIn(dir + "/job/print-job.json");
  const nlohmann::json job = nlohmann::json::parse(jobIn);
  std::ifstream cellIn(kShippedCell);
  nlohmann::json cell = nlohmann::json::parse(cellIn);
  cell["platformRadiusMm"] = job["pivot"]["platformRadiusMm"];
  std::ofstream(dir + "/cell.json") << cell.dump(2);
  const CliRun run = runCli("robot-program " + quoted(dir + "/job") + " --cell " + quoted(dir + "/cell.json") + " -o " +
                                quoted(dir + "/robot"),
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::ifstream robotIn(dir + "/robot/robot-job.json");
  const nlohmann::json robot = nlohmann::json::parse(robotIn);
  EXPECT_EQ(robot["format"], "multidir-robot-job");
  EXPECT_EQ(robot["version"], 2);
  EXPECT_EQ(robot["robot"], "ur5");
  EXPECT_EQ(robot["cell"], "cell.json");
  ASSERT_EQ(robot["steps"].size(), job["steps"].size());
  for (const auto& step : robot["steps"]) {
    for (const char* key :
         {"step", "program", "parts", "seconds", "filamentMm", "moves", "reachMarginMm", "slowestJoint", "slowdowns"})
      EXPECT_TRUE(step.contains(key)) << key;
    ASSERT_FALSE(step["parts"].empty());
    EXPECT_EQ(step["program"], step["parts"][0]["program"]);
    // Each program within the cell's bound (the shipped cell's), as the controller takes it.
    for (const auto& part : step["parts"]) {
      const std::string file = dir + "/robot/" + part["program"].get<std::string>();
      ASSERT_TRUE(std::filesystem::exists(file)) << file;
      EXPECT_EQ(std::filesystem::file_size(file), part["bytes"].get<std::size_t>()) << file;
      EXPECT_LE(std::filesystem::file_size(file), cell["maxProgramBytes"].get<std::size_t>()) << file;
    }
  }
  EXPECT_TRUE(std::filesystem::exists(dir + "/robot/cell.json"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/robot/summary.txt"));
  EXPECT_NE(run.out.find("robot time"), std::string::npos);
}

// The paper cell's 30 mm platform swings into the extruder on the kitten's steeply tilted step: refused with the
// step and line, nothing written.
TEST(CliRobot, RobotProgramRefusesAJobTheCellCannotRunNamingStepAndLine) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.RobotProgramRefuses");
  sliceKitten(dir);
  const CliRun run = runCli("robot-program " + quoted(dir + "/job") + " --cell " + quoted(kShippedCell) + " -o " +
                                quoted(dir + "/robot"),
                            dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("the job cannot run on the cell"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(", line "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("the platform would hit the extruder's body"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/robot"));
}

TEST(CliRobot, CellReachReportsTheBestNozzlePositionAndWritesTheMap) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.CellReach");
  const CliRun decomposed = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                       " --up y --machine 5dof --scheme greedy --scale 0.5 -o " + quoted(dir + "/plan"),
                                   dir);
  ASSERT_EQ(decomposed.exitCode, 0) << decomposed.err;
  const CliRun run = runCli("cell reach " + quoted(dir + "/plan") + " --cell " + quoted(kShippedCell) +
                                " --grid 150 -o " + quoted(dir + "/reach.ply"),
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("best position"), std::string::npos);
  EXPECT_NE(run.out.find("100.0 % of the needed poses reachable"), std::string::npos) << run.out;
  std::ifstream ply(dir + "/reach.ply");
  std::string first;
  std::getline(ply, first);
  EXPECT_EQ(first, "ply");
}

// An 8-bit RGB PNG read back: its size and pixels (rows unfiltered, as MultiDir writes them).
struct Png {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  std::array<int, 3> at(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

std::uint32_t big32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
}

Png readPng(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  Png png;
  std::vector<std::uint8_t> packed;
  EXPECT_GE(bytes.size(), 8u);
  for (std::size_t at = 8; at + 12 <= bytes.size();) {
    const std::uint32_t length = big32(bytes, at);
    const std::string type(bytes.begin() + static_cast<std::ptrdiff_t>(at + 4), bytes.begin() + static_cast<std::ptrdiff_t>(at + 8));
    if (type == "IHDR") {
      png.width = static_cast<int>(big32(bytes, at + 8));
      png.height = static_cast<int>(big32(bytes, at + 12));
      EXPECT_EQ(bytes[at + 16], 8);  // bits per channel
      EXPECT_EQ(bytes[at + 17], 2);  // RGB
    }
    if (type == "IDAT") packed.insert(packed.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at + 8),
                                      bytes.begin() + static_cast<std::ptrdiff_t>(at + 8 + length));
    at += 12 + length;
  }
  const std::size_t row = 1 + 3 * static_cast<std::size_t>(png.width);
  std::vector<std::uint8_t> raw(row * static_cast<std::size_t>(png.height));
  uLongf size = static_cast<uLongf>(raw.size());
  EXPECT_EQ(uncompress(raw.data(), &size, packed.data(), static_cast<uLong>(packed.size())), Z_OK);
  EXPECT_EQ(size, raw.size());
  for (int y = 0; y < png.height; ++y) {
    EXPECT_EQ(raw[row * static_cast<std::size_t>(y)], 0) << "row " << y << " filtered";
    png.rgb.insert(png.rgb.end(), raw.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y) + 1),
                   raw.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y + 1)));
  }
  return png;
}

struct PlyVertex {
  double x, y, z, score;
  std::array<int, 3> colour;
};

std::vector<PlyVertex> readReachPly(const std::string& path) {
  std::ifstream ply(path);
  std::string line;
  while (std::getline(ply, line) && line != "end_header") {
  }
  std::vector<PlyVertex> vertices;
  PlyVertex v{};
  while (ply >> v.x >> v.y >> v.z >> v.score >> v.colour[0] >> v.colour[1] >> v.colour[2]) vertices.push_back(v);
  return vertices;
}

// The PNG slice beside the PLY: it decodes; it is as large as its documented layout (cells of 8 px from a 10 px
// margin, the colour bar on the right); the best position's cell has the top colour of the scale (blue, score
// 1, as the bar's top); and every position of the PLY in the slice's plane has its PLY colour in the PNG.
TEST(CliRobot, CellReachWritesAPngSliceThatAgreesWithThePlyAtTheBestPosition) {
  const std::string dir = multidir::test::scratchDirectory("CliRobot.CellReachPng");
  const CliRun decomposed = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                       " --up y --machine 5dof --scheme greedy --scale 0.5 -o " + quoted(dir + "/plan"),
                                   dir);
  ASSERT_EQ(decomposed.exitCode, 0) << decomposed.err;
  const double grid = 150.0;
  const CliRun run = runCli("cell reach " + quoted(dir + "/plan") + " --cell " + quoted(kShippedCell) +
                                " --grid 150 -o " + quoted(dir + "/reach.ply"),
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("saved in " + dir + "/reach.png"), std::string::npos) << run.out;
  double bx = 0.0, by = 0.0, bz = 0.0;
  const std::size_t best = run.out.find("best position");
  ASSERT_NE(best, std::string::npos) << run.out;
  ASSERT_EQ(std::sscanf(run.out.c_str() + best, "best position (%lf, %lf, %lf)", &bx, &by, &bz), 3) << run.out;

  const std::vector<PlyVertex> vertices = readReachPly(dir + "/reach.ply");
  ASSERT_FALSE(vertices.empty());
  double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
  for (const auto& v : vertices) {
    minX = std::min(minX, v.x);
    maxX = std::max(maxX, v.x);
    minY = std::min(minY, v.y);
    maxY = std::max(maxY, v.y);
  }
  const int columns = static_cast<int>(std::lround((maxX - minX) / grid)) + 1;
  const int rows = static_cast<int>(std::lround((maxY - minY) / grid)) + 1;
  auto pixelOf = [&](double x, double y) {
    return std::array<int, 2>{10 + static_cast<int>(std::lround((x - minX) / grid)) * 8 + 4,
                              10 + static_cast<int>(std::lround((maxY - y) / grid)) * 8 + 4};
  };

  const Png png = readPng(dir + "/reach.png");
  EXPECT_GT(png.width, 20 + 8 * columns);  // the map, then the colour bar
  EXPECT_GE(png.height, 20 + 8 * rows);
  ASSERT_EQ(png.rgb.size(), 3u * static_cast<std::size_t>(png.width) * static_cast<std::size_t>(png.height));

  const std::array<int, 3> top = {0, 0, 255};
  const auto bestPixel = pixelOf(bx, by);
  EXPECT_EQ(png.at(bestPixel[0], bestPixel[1]), top);
  int inPlane = 0;
  for (const auto& v : vertices) {
    if (std::abs(v.z - bz) > 0.05) continue;
    ++inPlane;
    const auto p = pixelOf(v.x, v.y);
    EXPECT_EQ(png.at(p[0], p[1]), v.colour) << "at (" << v.x << ", " << v.y << ")";
    if (std::abs(v.x - bx) < 0.05 && std::abs(v.y - by) < 0.05) {
      EXPECT_EQ(v.colour, top) << "the PLY's best position";
      EXPECT_DOUBLE_EQ(v.score, 1.0);
    }
  }
  EXPECT_GT(inPlane, 10);
}

}  // namespace
