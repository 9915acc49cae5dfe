// `multidir run` on a job whose platform the printer's own firmware turns (issue 26, item 5): the printer alone
// prints the stitched program, on each printer simulator; the kitten's one-axis job really sliced (Klipper and
// Marlin dialects), and a two-axis job written by hand in the stitched program's format. The simulators record
// where their axes stood for every extrusion, so the tests check that each step printed at its own coordinates.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "multidir/hardware/marlin_simulator.h"
#include "multidir/hardware/moonraker_simulator.h"
#include "multidir/hardware/octoprint_simulator.h"
#include "support/cli_runner.h"
#include "support/test_models.h"
#include "support/two_axis_program.h"

namespace {

namespace fs = std::filesystem;
namespace hw = multidir::hardware;
using multidir::test::CliRun;
using multidir::test::runCli;
using Json = nlohmann::json;

std::string shellQuoted(const std::string& path) { return "'" + path + "'"; }

const char* const kCoarse =
    " --no-comparison --set 'layer_height=0.3 first_layer_height=0.3 perimeters=1 top_solid_layers=1 "
    "bottom_solid_layers=1 fill_density=0%'";

// This test's own scratch folder NAME: ctest runs the tests as processes side by side, and a folder shared
// between them would be emptied by one while another slices into it.
std::string ownScratch(const std::string& name) {
  return multidir::test::scratchDirectory(name + "." + testing::UnitTest::GetInstance()->current_test_info()->name());
}

// The kitten's 4-DOF plan (greedy), once per test process.
const std::string& kittenPlan() {
  static const std::string plan = [] {
    const std::string dir = ownScratch("CliRunStitched.Plan");
    const CliRun run = runCli("decompose " + shellQuoted(multidir::test::sharedModelPath("kitten.off")) +
                                  " --up y --machine 4dof --scheme greedy -o " + shellQuoted(dir + "/plan"),
                              dir);
    if (run.exitCode != 0) throw std::runtime_error("decompose failed: " + run.err);
    return dir + "/plan";
  }();
  return plan;
}

// The kitten sliced for a printer whose firmware turns the platform about one axis: klipper-rotary (a
// [manual_stepper rotary_a]), or the same printer under Marlin with an A axis. Once per dialect.
const std::string& kittenJob(bool klipper) {
  static std::string jobs[2];
  std::string& job = jobs[klipper ? 1 : 0];
  if (!job.empty()) return job;
  const std::string dir = ownScratch(klipper ? "CliRunStitched.Klipper" : "CliRunStitched.Marlin");
  std::string printer = "klipper-rotary";
  if (!klipper) {
    std::string profile =
        multidir::test::readAll(std::string(MULTIDIR_SOURCE_DIR) + "/resources/printers/klipper-rotary.ini");
    profile = std::regex_replace(profile, std::regex("# multidir.dialect = klipper"), "# multidir.dialect = marlin");
    printer = dir + "/marlin-rotary.ini";
    std::ofstream(printer) << profile;
  }
  const CliRun run = runCli("slice " + shellQuoted(kittenPlan()) + " --printer " + shellQuoted(printer) + kCoarse +
                                " -o " + shellQuoted(dir + "/job"),
                            dir);
  if (run.exitCode != 0) throw std::runtime_error("slice failed: " + run.err);
  job = dir + "/job";
  return job;
}

// Each extrusion happened at the coordinate of the step it belongs to: the steps are told apart by the turns
// between them (a turn's sequence number lies between the two steps' lines), and each step's coordinate is the
// one the turn before it went to (the first step's: rest, 0).
void expectEveryExtrusionAtItsStepsAngle(const hw::SimulatedAxisLog& log, const Json& job) {
  const Json& turns = job["slicing"]["turns"];
  ASSERT_EQ(log.turns.size(), turns.size());
  ASSERT_FALSE(log.extrusions.empty());
  std::size_t turn = 0;
  int checked = 0;
  for (const hw::SimulatedMove& e : log.extrusions) {
    while (turn < log.turns.size() && log.turns[turn].sequence < e.sequence) ++turn;
    const double expected = turn == 0 ? 0.0 : turns[turn - 1]["toDegrees"].get<double>();
    ASSERT_EQ(e.axisDegrees.size(), 1u);
    if (std::abs(e.axisDegrees[0] - expected) > 1e-9) {
      ADD_FAILURE() << "an extrusion of step " << turn + 1 << " printed at " << e.axisDegrees[0] << " degrees, not "
                    << expected;
      return;
    }
    ++checked;
  }
  EXPECT_EQ(turn, turns.size());  // the last step's extrusions came after the last turn
  for (std::size_t k = 0; k < turns.size(); ++k)
    EXPECT_NEAR(log.turns[k].axisDegrees[0], turns[k]["toDegrees"].get<double>(), 1e-9);
  EXPECT_GT(checked, 1000);
}

Json jobJson(const std::string& folder) { return Json::parse(multidir::test::readAll(folder + "/print-job.json")); }

TEST(CliRunStitched, AOneAxisKittenJobPrintsAsOneProgramOnMoonraker) {
  const std::string job = kittenJob(true);
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.Moonraker");
  hw::MoonrakerSimulatorOptions options;
  options.speed = 100000.0;
  options.rotaryAxes.manualSteppers = {"rotary_a"};
  hw::MoonrakerSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const CliRun run = runCli("run " + shellQuoted(job) + " --printer http://" + printer.address(), dir, "timeout 120");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("the program turns the manual steppers rotary_a; the printer has them"), std::string::npos)
      << run.out;
  std::vector<std::string> completed;
  for (const hw::PrinterJobEvent& e : printer.jobEvents())
    if (e.state == "complete") completed.push_back(e.file);
  EXPECT_EQ(completed, std::vector<std::string>{"job.gcode"});
  expectEveryExtrusionAtItsStepsAngle(printer.axisLog(), jobJson(job));
}

TEST(CliRunStitched, AOneAxisKittenJobPrintsAsOneProgramOnMarlin) {
  const std::string job = kittenJob(false);
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.MarlinRun");
  hw::MarlinSimulatorOptions options;
  options.speed = 100000.0;
  options.rotaryAxes.letters = {"A"};
  hw::MarlinSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const CliRun run =
      runCli("run " + shellQuoted(job) + " --printer serial://" + printer.devicePath(), dir, "timeout 300");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("the program turns the axes A; the printer has them (M114)"), std::string::npos) << run.out;
  expectEveryExtrusionAtItsStepsAngle(printer.axisLog(), jobJson(job));
}

TEST(CliRunStitched, AOneAxisKittenJobPrintsOnOctoPrintOnlyWhenTheOperatorSaysTheAxesAreConfigured) {
  const std::string job = kittenJob(false);
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.OctoPrint");
  hw::OctoPrintSimulatorOptions options;
  options.speed = 100000.0;
  options.rotaryAxes.letters = {"A"};
  hw::OctoPrintSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const std::string base =
      "run " + shellQuoted(job) + " --printer octoprint://" + printer.address() + " --api-key " + printer.apiKey();
  const CliRun refused = runCli(base, dir, "timeout 60");
  EXPECT_EQ(refused.exitCode, 4) << refused.out << refused.err;
  EXPECT_NE(refused.err.find("OctoPrint cannot be asked which axes"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--yes-axes-configured"), std::string::npos) << refused.err;
  EXPECT_TRUE(printer.state().files.empty());  // nothing was uploaded
  const CliRun run = runCli(base + " --yes-axes-configured", dir, "timeout 120");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  expectEveryExtrusionAtItsStepsAngle(printer.axisLog(), jobJson(job));
}

// --from 3 on the kitten: the axis is declared where step 2 printed (the program's own turn before it), so the turn
// to step 3 takes |step 3's angle - step 2's| at the profile's 30 degrees per second, and step 3 on print there.
TEST(CliRunStitched, AKittenJobResumedAtTheThirdStepTurnsFromTheSecondStepsAngle) {
  const std::string job = kittenJob(true);
  const Json turns = jobJson(job)["slicing"]["turns"];
  ASSERT_GE(turns.size(), 2u);
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.KittenFrom3");
  hw::MoonrakerSimulatorOptions options;
  options.speed = 100000.0;
  options.rotaryAxes.manualSteppers = {"rotary_a"};
  hw::MoonrakerSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const CliRun run =
      runCli("run " + shellQuoted(job) + " --printer http://" + printer.address() + " --from 3", dir, "timeout 120");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_EQ(printer.state().files, std::vector<std::string>{"job-from-03.gcode"});
  const hw::SimulatedAxisLog log = printer.axisLog();
  ASSERT_EQ(log.turns.size(), turns.size() - 1);
  const double from = turns[1]["fromDegrees"].get<double>();
  const double to = turns[1]["toDegrees"].get<double>();
  EXPECT_NEAR(log.turns[0].endSeconds - log.turns[0].startSeconds, std::abs(to - from) / 30.0, 1e-9);
  ASSERT_FALSE(log.extrusions.empty());
  EXPECT_GT(log.extrusions.front().sequence, log.turns[0].sequence);
  EXPECT_NEAR(log.extrusions.front().axisDegrees[0], to, 1e-9);
}

// The kitten's 5-DOF plan sliced for klipper-2axis (the slicer's own two-axis stitched program) and printed on the
// Moonraker simulator with the profile's two manual steppers: every extrusion of step k happens at the axis
// coordinates print-job.json records for step k (slicing.steps[k].axisDegrees; to the program's 3 decimals). The
// steps are told apart by the turns between them.
TEST(CliRunStitched, TheKittensTwoAxisJobPrintsEachStepAtItsRecordedAxisCoordinates) {
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.Kitten5dof");
  const CliRun plan = runCli("decompose " + shellQuoted(multidir::test::sharedModelPath("kitten.off")) +
                                 " --up y --machine 5dof -o " + shellQuoted(dir + "/plan"),
                             dir);
  ASSERT_EQ(plan.exitCode, 0) << plan.err;
  const CliRun sliced = runCli(
      "slice " + shellQuoted(dir + "/plan") + " --printer klipper-2axis" + kCoarse + " -o " + shellQuoted(dir + "/job"),
      dir);
  ASSERT_EQ(sliced.exitCode, 0) << sliced.err;
  const Json job = jobJson(dir + "/job");
  const Json& axes = job["slicing"]["printer"]["axes"];
  const std::string tilt = axes["tilt"]["letter"], rotation = axes["rotation"]["letter"];
  hw::MoonrakerSimulatorOptions options;
  options.speed = 100000.0;
  options.rotaryAxes.manualSteppers = {axes["tilt"]["stepper"], axes["rotation"]["stepper"]};
  hw::MoonrakerSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const CliRun run =
      runCli("run " + shellQuoted(dir + "/job") + " --printer http://" + printer.address(), dir, "timeout 120");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  const hw::SimulatedAxisLog log = printer.axisLog();
  const Json& steps = job["slicing"]["steps"];
  std::size_t step = 0;
  std::size_t turn = 0;
  std::size_t checked = 0;
  for (const hw::SimulatedMove& e : log.extrusions) {
    bool turned = false;
    while (turn < log.turns.size() && log.turns[turn].sequence < e.sequence) turned = true, ++turn;
    if (turned && checked > 0) ++step;
    ASSERT_LT(step, steps.size());
    const Json& at = steps[step]["axisDegrees"];
    if (std::abs(e.axisDegrees[0] - at[tilt].get<double>()) > 1e-3 ||
        std::abs(e.axisDegrees[1] - at[rotation].get<double>()) > 1e-3) {
      ADD_FAILURE() << "an extrusion of step " << step + 1 << " printed at " << e.axisDegrees[0] << ", "
                    << e.axisDegrees[1] << ", not at " << at.dump();
      return;
    }
    ++checked;
  }
  EXPECT_EQ(step + 1, steps.size());
  EXPECT_GT(checked, 1000u);
}

// A job for a platform the printer turns, given the options of a platform driven over Modbus.
TEST(CliRunStitched, AFirmwareJobGivenModbusDeviceOptionsIsAUsageErrorNamingTheOption) {
  const std::string job = kittenJob(true);
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.Modbus");
  for (const std::string option : {"--platform 127.0.0.1:502", "--machine platform.json", "--unit 1"}) {
    const CliRun run = runCli("run " + shellQuoted(job) + " --printer http://127.0.0.1:1 " + option, dir);
    EXPECT_EQ(run.exitCode, 2) << option;
    EXPECT_NE(run.err.find("sliced for a platform the printer's firmware turns (firmware-axis)"), std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find(option.substr(0, option.find(' ')) + " (an option for a platform driven over Modbus)"),
              std::string::npos)
        << run.err;
  }
}

// A hand-written two-axis job (two_axis_program.h) in a job folder as `multidir slice` writes one.
std::string writeTwoAxisJob(const std::string& dir, bool klipper) {
  const multidir::test::TwoAxisProgram program = multidir::test::twoAxisProgram(klipper);
  fs::create_directories(dir + "/job");
  std::ofstream(dir + "/job/job.gcode") << program.text;
  const multidir::test::TwoAxisMachineSetup m;
  const Json axis = {{"zero", m.tiltZero}, {"direction", m.tiltDirection}, {"min", -90}, {"max", 90}};
  Json tilt = axis;
  tilt["letter"] = m.tiltLetter;
  tilt["stepper"] = m.tiltStepper;
  Json rotation = {{"letter", m.rotationLetter},
                   {"stepper", m.rotationStepper},
                   {"zero", m.rotationZero},
                   {"direction", m.rotationDirection},
                   {"min", -360},
                   {"max", 360}};
  Json steps = Json::array();
  Json sliced = Json::array();
  for (int k = 0; k < 2; ++k) {
    steps.push_back(
        {{"index", k + 1}, {"angles", {{"tiltDegrees", k == 0 ? 0.0 : program.tiltDegrees}, {"azimuthDegrees", 0.0}}}});
    sliced.push_back({{"index", k + 1},
                      {"gcode", "step-0" + std::to_string(k + 1) + ".gcode"},
                      {"estimate", {{"printSeconds", program.moveSeconds / 2}}},
                      {"axisDegrees", {{m.tiltLetter, program.tiltAt[k]}, {m.rotationLetter, program.rotationAt[k]}}}});
  }
  const Json job = {{"schema", "multidir-print-job"},
                    {"version", 1},
                    {"machine", {{"kind", "5dof"}, {"up", {0, 0, 1}}, {"maxTiltDegrees", 90}}},
                    {"steps", steps},
                    {"slicing",
                     {{"printer",
                       {{"name", "two-axis test printer"},
                        {"platform", "firmware-2axis"},
                        {"dialect", klipper ? "klipper" : "rrf"},
                        {"axes",
                         {{"tilt", tilt},
                          {"rotation", rotation},
                          {"tiltAlong", "X"},
                          {"tiltHeightMm", 0},
                          {"rotationCenterMm", {110, 110}}}}}},
                      {"steps", sliced},
                      {"stitched", "job.gcode"}}}};
  std::ofstream(dir + "/job/print-job.json") << job.dump(2);
  return dir + "/job";
}

void expectStepsAtTheirCoordinates(const hw::SimulatedAxisLog& log, const multidir::test::TwoAxisProgram& p,
                                   int firstStep) {
  ASSERT_EQ(log.extrusions.size(), static_cast<std::size_t>((3 - firstStep) * p.extrusionsPerStep));
  for (std::size_t i = 0; i < log.extrusions.size(); ++i) {
    const int step = firstStep - 1 + static_cast<int>(i) / p.extrusionsPerStep;
    ASSERT_EQ(log.extrusions[i].axisDegrees.size(), 2u);
    EXPECT_NEAR(log.extrusions[i].axisDegrees[0], p.tiltAt[step], 1e-9) << "extrusion " << i;
    EXPECT_NEAR(log.extrusions[i].axisDegrees[1], p.rotationAt[step], 1e-9) << "extrusion " << i;
  }
}

TEST(CliRunStitched, ATwoAxisJobPrintsOnEachPrinterWithItsAxes) {
  const multidir::test::TwoAxisProgram klipperProgram = multidir::test::twoAxisProgram(true);
  const multidir::test::TwoAxisProgram letterProgram = multidir::test::twoAxisProgram(false);
  {
    const std::string dir = multidir::test::scratchDirectory("CliRunStitched.TwoAxisMoonraker");
    hw::MoonrakerSimulatorOptions options;
    options.speed = 1000.0;
    options.rotaryAxes.manualSteppers = {"tilt", "rotation"};
    hw::MoonrakerSimulator printer(options);
    ASSERT_TRUE(printer.start().ok());
    const CliRun run = runCli(
        "run " + shellQuoted(writeTwoAxisJob(dir, true)) + " --printer http://" + printer.address(), dir, "timeout 60");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    expectStepsAtTheirCoordinates(printer.axisLog(), klipperProgram, 1);
  }
  {
    const std::string dir = multidir::test::scratchDirectory("CliRunStitched.TwoAxisMarlin");
    hw::MarlinSimulatorOptions options;
    options.speed = 1000.0;
    options.rotaryAxes.letters = {"U", "V"};
    hw::MarlinSimulator printer(options);
    ASSERT_TRUE(printer.start().ok());
    const CliRun run =
        runCli("run " + shellQuoted(writeTwoAxisJob(dir, false)) + " --printer serial://" + printer.devicePath(), dir,
               "timeout 60");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("the program turns the axes U, V; the printer has them (M114)"), std::string::npos)
        << run.out;
    expectStepsAtTheirCoordinates(printer.axisLog(), letterProgram, 1);
  }
  {
    const std::string dir = multidir::test::scratchDirectory("CliRunStitched.TwoAxisOctoPrint");
    hw::OctoPrintSimulatorOptions options;
    options.speed = 1000.0;
    options.rotaryAxes.letters = {"U", "V"};
    hw::OctoPrintSimulator printer(options);
    ASSERT_TRUE(printer.start().ok());
    const CliRun run = runCli("run " + shellQuoted(writeTwoAxisJob(dir, false)) + " --printer octoprint://" +
                                  printer.address() + " --api-key " + printer.apiKey() + " --yes-axes-configured",
                              dir, "timeout 60");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    expectStepsAtTheirCoordinates(printer.axisLog(), letterProgram, 1);
  }
}

// Ctrl-C while the program prints step 1: the printer's job is cancelled, as in any run, and the advice names the
// step the printer was in (from how far it had read the program) and what --from needs on such a printer.
TEST(CliRunStitched, CtrlCInTheFirstStepCancelsTheProgramAndNamesThatStep) {
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.CtrlC");
  hw::MoonrakerSimulatorOptions options;
  options.speed = 1.0;  // step 1 prints for seconds
  options.rotaryAxes.manualSteppers = {"tilt", "rotation"};
  hw::MoonrakerSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const std::string job = writeTwoAxisJob(dir, true);
  const std::string pidFile = dir + "/pid";
  const std::string prefix = multidir::test::pidRecordingPrefix(pidFile);
  auto cli = std::async(std::launch::async, [&] {
    return runCli("run " + shellQuoted(job) + " --printer http://" + printer.address(), dir, prefix);
  });
  const bool interrupted =
      multidir::test::signalCliWhen(pidFile, SIGINT, [&] { return printer.axisLog().extrusions.size() >= 2; });
  const CliRun run = cli.get();
  ASSERT_TRUE(interrupted) << run.out << run.err;
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  int cancels = 0;
  for (const hw::PrinterRequestRecord& r : printer.requests()) cancels += r.path == "/printer/print/cancel" ? 1 : 0;
  EXPECT_EQ(cancels, 1);
  EXPECT_EQ(printer.state().jobState, "cancelled");
  EXPECT_LT(printer.axisLog().extrusions.size(), 8u);  // step 1 was not finished
  EXPECT_NE(run.err.find("step 1 was interrupted while printing"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--from 2"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("the platform's axes must stand where the step before it printed"), std::string::npos)
      << run.err;
}

TEST(CliRunStitched, APrinterLackingAnAxisTheProgramTurnsIsRefusedBeforeAnythingIsSent) {
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.Lacking");
  hw::MarlinSimulatorOptions options;
  options.rotaryAxes.letters = {"U"};  // no V
  hw::MarlinSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const CliRun run =
      runCli("run " + shellQuoted(writeTwoAxisJob(dir, false)) + " --printer serial://" + printer.devicePath(), dir,
             "timeout 60");
  EXPECT_EQ(run.exitCode, 4) << run.out << run.err;
  EXPECT_NE(run.err.find("the printer's M114 reports no V axis (it reports X, Y, Z, U and E)"), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("nothing was printed"), std::string::npos) << run.err;
  EXPECT_TRUE(printer.axisLog().extrusions.empty());
}

TEST(CliRunStitched, AJobWithoutItsStitchedProgramIsRefused) {
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.Missing");
  const std::string job = writeTwoAxisJob(dir, true);
  fs::remove(job + "/job.gcode");
  const CliRun run = runCli("run " + shellQuoted(job) + " --printer http://127.0.0.1:1", dir);
  EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
  EXPECT_NE(run.err.find("the stitched program (slicing.stitched) is missing"), std::string::npos) << run.err;
}

// --from 2: the printer gets the program from the transition after step 1 on, with the axes declared where step 1
// printed; it turns them to step 2's coordinates and prints step 2 only.
TEST(CliRunStitched, ResumedAtTheSecondStepPrintsOnlyItAtItsCoordinates) {
  const std::string dir = multidir::test::scratchDirectory("CliRunStitched.Resume");
  hw::MoonrakerSimulatorOptions options;
  options.speed = 1000.0;
  options.rotaryAxes.manualSteppers = {"tilt", "rotation"};
  hw::MoonrakerSimulator printer(options);
  ASSERT_TRUE(printer.start().ok());
  const CliRun run =
      runCli("run " + shellQuoted(writeTwoAxisJob(dir, true)) + " --printer http://" + printer.address() + " --from 2",
             dir, "timeout 60");
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  EXPECT_EQ(printer.state().files, std::vector<std::string>{"job-from-02.gcode"});
  const multidir::test::TwoAxisProgram program = multidir::test::twoAxisProgram(true);
  const hw::SimulatedAxisLog log = printer.axisLog();
  expectStepsAtTheirCoordinates(log, program, 2);
  ASSERT_EQ(log.turns.size(), 2u);
  // The turns went from step 1's coordinates: their times are the programmed turns' (|change| / 30 degrees/s).
  EXPECT_NEAR(log.turns[0].endSeconds - log.turns[0].startSeconds,
              std::abs(program.tiltAt[1] - program.tiltAt[0]) / 30.0, 1e-9);
  EXPECT_NEAR(log.turns[1].endSeconds - log.turns[1].startSeconds,
              std::abs(program.rotationAt[1] - program.rotationAt[0]) / 30.0, 1e-9);
}

}  // namespace
