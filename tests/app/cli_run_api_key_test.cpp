// `multidir run`'s printer API key: from a file (--api-key-file) or the environment (MULTIDIR_PRINTER_API_KEY),
// so that it does not show in the process list as --api-key KEY does. Against the OctoPrint simulator, whose
// answer to a wrong key ("the API key is wrong") proves that the key was read and sent.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/octoprint_simulator.h"
#include "support/cli_runner.h"
#include "support/run_job_writer.h"
#include "support/test_models.h"

namespace {

using multidir::test::CliRun;
using multidir::test::runCli;
namespace hw = multidir::hardware;

class CliRunApiKeyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    hw::SimulatorOptions deviceOptions;
    deviceOptions.robot = false;
    devices = std::make_unique<hw::DeviceSimulator>(deviceOptions);
    ASSERT_TRUE(devices->start().ok());
    hw::OctoPrintSimulatorOptions printerOptions;
    printerOptions.speed = 1000.0;  // each step's simulated print takes milliseconds
    printer = std::make_unique<hw::OctoPrintSimulator>(printerOptions);
    ASSERT_TRUE(printer->start().ok());
  }

  // `multidir run` of a two-step job at the simulators, with `keyArgs` and `environment` (shell words put
  // before the program, such as "MULTIDIR_PRINTER_API_KEY=wrong").
  CliRun run(const std::string& testName, const std::string& keyArgs, const std::string& environment = "") {
    dir = multidir::test::scratchDirectory(testName);
    multidir::test::writeJob(dir + "/job");
    return runCli("run '" + dir + "/job' --printer octoprint://127.0.0.1:" + std::to_string(printer->port()) +
                      " --platform 127.0.0.1:" + std::to_string(devices->port()) + " --machine '" +
                      multidir::test::platformProfileBeside(dir + "/job") + "' " + keyArgs,
                  dir, environment + " timeout 60");
  }

  std::string keyFile(const std::string& name, const std::string& text) {
    const std::string path = multidir::test::scratchDirectory("CliRunApiKey.Files") + "/" + name;
    std::ofstream(path) << text;
    return path;
  }

  std::unique_ptr<hw::DeviceSimulator> devices;
  std::unique_ptr<hw::OctoPrintSimulator> printer;
  std::string dir;
};

TEST_F(CliRunApiKeyTest, TheKeyIsReadFromTheFileGivenWithApiKeyFileWithoutItsLineEnd) {
  const CliRun wrong = run("CliRunApiKey.WrongFile", "--api-key-file '" + keyFile("wrong.key", "wrong\n") + "'");
  EXPECT_EQ(wrong.exitCode, 4) << wrong.out << wrong.err;
  EXPECT_NE(wrong.err.find("the API key is wrong"), std::string::npos) << wrong.err;
  const CliRun right =
      run("CliRunApiKey.RightFile",
          "--api-key-file '" + keyFile("right.key", std::string(hw::kOctoPrintSimulatorApiKey) + "\r\n") + "'");
  EXPECT_EQ(right.err.find("the API key is wrong"), std::string::npos) << right.err;
  EXPECT_NE(right.out.find("connected to OctoPrint printer at 127.0.0.1"), std::string::npos) << right.out << right.err;
}

TEST_F(CliRunApiKeyTest, TheKeyIsReadFromTheEnvironmentWhenNoOptionGivesIt) {
  const CliRun wrong = run("CliRunApiKey.Environment", "", "MULTIDIR_PRINTER_API_KEY=wrong");
  EXPECT_EQ(wrong.exitCode, 4) << wrong.out << wrong.err;
  EXPECT_NE(wrong.err.find("the API key is wrong"), std::string::npos) << wrong.err;
}

TEST_F(CliRunApiKeyTest, AKeyFileThatCannotBeReadOrIsEmptyIsAUsageErrorNamingTheFile) {
  const CliRun missing = run("CliRunApiKey.Missing", "--api-key-file /nonexistent/octoprint.key");
  EXPECT_EQ(missing.exitCode, 2) << missing.err;
  EXPECT_NE(missing.err.find("cannot read the API key file '/nonexistent/octoprint.key'"), std::string::npos)
      << missing.err;
  const std::string empty = keyFile("empty.key", "\n");
  const CliRun blank = run("CliRunApiKey.Empty", "--api-key-file '" + empty + "'");
  EXPECT_EQ(blank.exitCode, 2) << blank.err;
  EXPECT_NE(blank.err.find("the API key file '" + empty + "' is empty"), std::string::npos) << blank.err;
}

TEST_F(CliRunApiKeyTest, ApiKeyAndApiKeyFileTogetherAreAUsageError) {
  const CliRun both = run("CliRunApiKey.Both", "--api-key wrong --api-key-file '" + keyFile("both.key", "x") + "'");
  EXPECT_EQ(both.exitCode, 2) << both.err;
  EXPECT_NE(both.err.find("give the API key once"), std::string::npos) << both.err;
}

TEST(CliRunApiKey, HelpSaysToPreferTheKeyFileOrTheEnvironmentToApiKey) {
  const CliRun help = runCli("run --help", multidir::test::scratchDirectory("CliRunApiKey.Help"));
  ASSERT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("--api-key-file FILE"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("MULTIDIR_PRINTER_API_KEY"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("visible to every user in the process list"), std::string::npos) << help.out;
}

}  // namespace
