// Models in the wrong units get advice (and --scale fixes them); an output folder that cannot be written is
// refused before the search, not after it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::readAll;
using multidir::test::runCli;

// An axis-aligned cube of the given size as OFF, standing on z = 0.
std::string writeCube(const std::string& path, double size) {
  std::ostringstream out;
  out.precision(17);
  out << "OFF\n8 12 0\n";
  for (int i = 0; i < 8; ++i) {
    const double x = (i == 1 || i == 2 || i == 5 || i == 6) ? size : 0.0;
    const double y = (i == 2 || i == 3 || i == 6 || i == 7) ? size : 0.0;
    out << x << " " << y << " " << (i >= 4 ? size : 0.0) << "\n";
  }
  out << "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 3 7 6\n3 3 6 2\n3 0 4 7\n3 0 7 3\n3 1 2 6\n"
         "3 1 6 5\n";
  std::ofstream(path) << out.str();
  return "'" + path + "'";
}

}  // namespace

TEST(CliUnits, DecomposeOfAModelInMicrometresIsRefusedWithScaleAdvice) {
  const std::string dir = multidir::test::scratchDirectory("CliUnits.Micrometres");
  const CliRun run = runCli("decompose " + writeCube(dir + "/part-um.off", 100'000.0) + " -o '" + dir + "/plan'", dir);
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find("173.2 m wide"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("Use --scale"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("internal error"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/plan/plan.json"));
}

TEST(CliUnits, DecomposeWithScaleReadsTheModelInMillimetres) {
  const std::string dir = multidir::test::scratchDirectory("CliUnits.Scale");
  const CliRun run = runCli("decompose " + writeCube(dir + "/part-um.off", 40'000.0) +
                                " --scale 0.001 --beam-width 1 --normals 30 --no-supports -o '" + dir + "/plan'",
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json plan = nlohmann::json::parse(readAll(dir + "/plan/plan.json"), nullptr, false);
  ASSERT_TRUE(plan.is_object());
  double volume = 0.0;
  for (const auto& region : plan["regions"]) volume += region["volumeMm3"].get<double>();
  EXPECT_NEAR(volume, 64'000.0, 1e-6 * 64'000.0) << "a 40 mm cube";
}

TEST(CliUnits, InfoScaleMultipliesEveryCoordinate) {
  const std::string dir = multidir::test::scratchDirectory("CliUnits.InfoScale");
  const CliRun run =
      runCli("info " + writeCube(dir + "/inch.off", 1.0) + " --scale 25.4 --json '" + dir + "/info.json'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json info = nlohmann::json::parse(readAll(dir + "/info.json"), nullptr, false);
  EXPECT_NEAR(info["statistics"]["volumeMm3"].get<double>(), 25.4 * 25.4 * 25.4, 1e-6);
}

TEST(CliUnits, ScaleOutOfRangeIsAUsageError) {
  const std::string dir = multidir::test::scratchDirectory("CliUnits.BadScale");
  const std::string cube = writeCube(dir + "/cube.off", 10.0);
  for (const char* scale : {"0", "-1", "1e9", "abc"}) {
    const CliRun run = runCli("info " + cube + " --scale " + scale, dir);
    EXPECT_EQ(run.exitCode, 2) << scale << "\n" << run.err;
    EXPECT_NE(run.err.find("--scale"), std::string::npos) << run.err;
  }
}

TEST(CliOutput, DecomposeRefusesAnOutputFolderBelowAFileBeforeSearching) {
  const std::string dir = multidir::test::scratchDirectory("CliOutput.BelowAFile");
  std::ofstream(dir + "/taken") << "a file, not a folder";
  const CliRun run = runCli("decompose '" + multidir::test::sharedModelPath("kitten.off") + "' --up y -o '" + dir +
                                "/taken/plan'",
                            dir);
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find("is a file, not a folder"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("searching"), std::string::npos) << "the search must not start:\n" << run.err;
  EXPECT_EQ(run.out.find("Regions in printing order"), std::string::npos) << run.out;
}
