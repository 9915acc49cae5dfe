// The whole pipeline on the kitten, headless: `multidir decompose` (4-DOF, greedy), `multidir slice`
// (PrusaSlicer, coarse), then `multidir run` against the rotary platform simulator and the OctoPrint simulator
// in this process. Every step must print, and no platform command may reach the platform while the printer
// prints: both simulators record on this process's steady clock, and the test compares their records.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/octoprint_simulator.h"
#include "support/cli_runner.h"
#include "support/test_models.h"

namespace {

namespace hw = multidir::hardware;
using multidir::test::CliRun;
using multidir::test::runCli;
using Clock = std::chrono::steady_clock;

std::string quoted(const std::string& path) { return "'" + path + "'"; }

TEST(CliRunKitten, AWholeKittenJobRunsEveryStepOnOctoPrintAndThePlatformNeverMovesWhileItPrints) {
  const std::string dir = multidir::test::scratchDirectory("CliRunKitten.OctoPrint");
  const CliRun decomposed = runCli("decompose " + quoted(multidir::test::sharedModelPath("kitten.off")) +
                                       " --up y --machine 4dof --scheme greedy -o " + quoted(dir + "/plan"),
                                   dir);
  ASSERT_EQ(decomposed.exitCode, 0) << decomposed.err;
  const CliRun sliced = runCli("slice " + quoted(dir + "/plan") +
                                   " --printer robot-0.8 --no-comparison --set 'layer_height=0.6 "
                                   "first_layer_height=0.6 perimeters=1 top_solid_layers=1 bottom_solid_layers=1 "
                                   "fill_density=0%' -o " +
                                   quoted(dir + "/job"),
                               dir);
  ASSERT_EQ(sliced.exitCode, 0) << sliced.err;
  const nlohmann::json job = nlohmann::json::parse(multidir::test::readAll(dir + "/job/print-job.json"));
  const std::size_t steps = job["steps"].size();
  ASSERT_GE(steps, 2u);
  // The platform the plan was made for: the job's own machine as its profile (`multidir run --machine`).
  nlohmann::json platform = job["machine"];
  platform["schema"] = "multidir-machine";
  platform["version"] = 1;
  std::ofstream(dir + "/platform.json") << platform.dump();

  hw::SimulatorOptions deviceOptions;
  deviceOptions.robot = false;
  hw::DeviceSimulator devices(deviceOptions);
  ASSERT_TRUE(devices.start().ok());
  hw::OctoPrintSimulatorOptions printerOptions;
  printerOptions.speed = 100000.0;  // each region's simulated print takes milliseconds
  hw::OctoPrintSimulator printer(printerOptions);
  ASSERT_TRUE(printer.start().ok());
  const auto started = Clock::now();
  const CliRun run = runCli("run " + quoted(dir + "/job") + " --printer octoprint://" + printer.address() +
                                " --api-key " + printer.apiKey() + " --platform " + devices.address() +
                                " --settle 20 --machine " + quoted(dir + "/platform.json"),
                            dir, "timeout 120");
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  std::cout << "[ measured ] multidir run printed the kitten's " << steps << " steps on the simulators in " << seconds
            << " s\n";

  std::vector<std::string> completed;
  for (const auto& e : printer.jobEvents())
    if (e.state == "complete") completed.push_back(e.file);
  ASSERT_EQ(completed.size(), steps);
  for (std::size_t k = 0; k < steps; ++k) {
    const std::string name = job["slicing"]["steps"][k]["gcode"].get<std::string>();
    EXPECT_EQ(completed[k], name);
  }
  // No platform command from a job's start to its end.
  const auto events = printer.jobEvents();
  const auto commands = devices.commandLog();
  int printed = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (events[i].state != "printing") continue;
    ++printed;
    const Clock::time_point to = i + 1 < events.size() ? events[i + 1].at : Clock::time_point::max();
    for (const auto& c : commands)
      EXPECT_FALSE(c.at >= events[i].at && c.at <= to)
          << "platform command " << c.command << " while " << events[i].file << " printed";
  }
  EXPECT_EQ(printed, static_cast<int>(steps));
  int moves = 0;
  for (const auto& c : commands) moves += c.command == 4 ? 1 : 0;  // the rotary controller's MOVE
  EXPECT_EQ(moves, static_cast<int>(steps));
}

}  // namespace
