// The printer simulators' rotary axes (issue 26, item 5): a stitched two-axis program, hand-written in the lines
// the slicer writes for each dialect, printed on each simulator: where the axes stood for every extrusion, that
// those coordinates turn the step's printing direction to +Z by the simulator's own kinematics, that the turns
// happen only between the steps, and that the job takes the sum of its moves' times.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <atomic>
#include <cmath>
#include <future>
#include <random>

#include "../support/two_axis_program.h"
#include "multidir/slicing/two_axis.h"
#include "printer_test_support.h"
#include "sim/gcode_timeline.h"
#include "sim/two_axis_kinematics.h"

namespace multidir::hardware {
namespace {

using multidir::test::TwoAxisProgram;
using namespace std::chrono_literals;

constexpr double kPi = 3.14159265358979323846;

// The test program's machine (two_axis_program.h): tilt along X at height 0 over the rotation centre.
sim::TwoAxisMachine testMachine() {
  const multidir::test::TwoAxisMachineSetup setup;
  sim::TwoAxisMachine m;
  m.tiltZeroDegrees = setup.tiltZero;
  m.tiltDirection = setup.tiltDirection;
  m.rotationZeroDegrees = setup.rotationZero;
  m.rotationDirection = setup.rotationDirection;
  m.tiltAlongX = true;
  m.rotationCenterMm = Eigen::Vector2d(110, 110);
  return m;
}

// Step 2's printing direction, written out by hand from the convention (two_axis.h): Tilt(t) turns by -t about
// +X, taking (0, -sin t, cos t) to +Z; Rot(r) turns by +r about +Z, so the direction Rot(-r) (0, -sin t, cos t)
// = (-sin t sin r, -sin t cos r, cos t) is the one the step prints along.
Eigen::Vector3d stepTwoDirection(const TwoAxisProgram& p) {
  const double t = p.tiltDegrees * kPi / 180.0;
  const double r = p.rotationDegrees * kPi / 180.0;
  return Eigen::Vector3d(-std::sin(t) * std::sin(r), -std::sin(t) * std::cos(r), std::cos(t));
}

// Every physical claim about one printed job, whatever simulator printed it.
void expectTheStepsPrintedWhereTheirAxesTurnThem(const SimulatedAxisLog& log, const TwoAxisProgram& p) {
  ASSERT_EQ(log.extrusions.size(), static_cast<std::size_t>(2 * p.extrusionsPerStep));
  const Eigen::Vector3d directions[2] = {Eigen::Vector3d::UnitZ(), stepTwoDirection(p)};
  for (std::size_t i = 0; i < log.extrusions.size(); ++i) {
    const SimulatedMove& e = log.extrusions[i];
    const int step = static_cast<int>(i) / p.extrusionsPerStep;
    ASSERT_EQ(e.axisDegrees.size(), 2u);
    EXPECT_NEAR(e.axisDegrees[0], p.tiltAt[step], 1e-9) << "extrusion " << i;
    EXPECT_NEAR(e.axisDegrees[1], p.rotationAt[step], 1e-9) << "extrusion " << i;
    const Eigen::Vector3d up =
        sim::twoAxisPlatformPose(testMachine(), e.axisDegrees[0], e.axisDegrees[1]).linear() * directions[step];
    EXPECT_NEAR((up - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-9) << "extrusion " << i << " of step " << step + 1;
  }
  // The two turns (tilt, then rotation), after step 1's last extrusion and before step 2's first.
  ASSERT_EQ(log.turns.size(), 2u);
  const SimulatedMove& lastOfStepOne = log.extrusions[static_cast<std::size_t>(p.extrusionsPerStep) - 1];
  const SimulatedMove& firstOfStepTwo = log.extrusions[static_cast<std::size_t>(p.extrusionsPerStep)];
  for (const SimulatedMove& turn : log.turns) {
    EXPECT_GT(turn.sequence, lastOfStepOne.sequence);
    EXPECT_LT(turn.sequence, firstOfStepTwo.sequence);
    EXPECT_GE(turn.startSeconds, lastOfStepOne.endSeconds);
    EXPECT_LE(turn.endSeconds, firstOfStepTwo.startSeconds);
  }
  EXPECT_NEAR(log.turns[0].axisDegrees[0], p.tiltAt[1], 1e-9);
  EXPECT_NEAR(log.turns[1].axisDegrees[1], p.rotationAt[1], 1e-9);
  EXPECT_NEAR(log.turns[1].endSeconds - log.turns[1].startSeconds, std::abs(p.rotationDegrees) / 30.0, 1e-9);
  EXPECT_NEAR(log.printSeconds, p.moveSeconds, 1e-6);
}

// The program's turns follow an M400 and are followed by one (the contract the printers' checks rely on).
TEST(TwoAxisTestProgram, TurnsOnlyBetweenTwoM400s) {
  for (const bool klipper : {false, true}) {
    const std::vector<std::string> lines = test::gcodeCommands(multidir::test::twoAxisProgram(klipper).text);
    int turns = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const bool turn = lines[i].rfind("MANUAL_STEPPER STEPPER=tilt MOVE", 0) == 0 || lines[i].rfind("G1 U", 0) == 0;
      if (!turn) continue;
      ++turns;
      EXPECT_EQ(lines[i - 1].substr(0, 4), "M400");
      EXPECT_TRUE(lines[i + 2].rfind("M400", 0) == 0) << lines[i + 2];
    }
    EXPECT_EQ(turns, 1);
  }
}

// The simulator's kinematics and the slicer's angle solver agree: slicing's axis coordinates for 1,000 random
// directions, applied by the simulator's machine model, point each direction along +Z.
TEST(TwoAxisSimulatorKinematics, TurnsTheSlicersAnglesDirectionsToPlusZ) {
  slicing::TwoAxisPlatform platform;
  platform.tilt = {"U", "tilt", 5.0, -1.0, -120.0, 120.0};
  platform.rotation = {"V", "rotation", -30.0, 1.0, -400.0, 400.0};
  platform.tiltAlong = slicing::TiltAlong::Y;
  sim::TwoAxisMachine machine = testMachine();
  machine.tiltAlongX = false;
  std::mt19937 random(26);
  std::normal_distribution<double> normal;
  slicing::TwoAxisAngles previous = slicing::restAngles(platform);
  for (int i = 0; i < 1000; ++i) {
    Eigen::Vector3d d(normal(random), normal(random), normal(random));
    d.normalize();
    if (d.z() < -0.45) d.z() = -d.z();  // within the 120 degree tilt limit
    const core::Result<slicing::TwoAxisAngles> angles = slicing::twoAxisAngles(d, platform, previous, i + 1);
    ASSERT_TRUE(angles.ok()) << angles.error().describe();
    const Eigen::Vector3d up =
        sim::twoAxisPlatformPose(machine, angles->tiltDegrees, angles->rotationDegrees).linear() * d;
    EXPECT_NEAR((up - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-9) << "direction " << i;
    previous = *angles;
  }
}

// The rule of a move that turns rotary axes, as Marlin and RepRapFirmware take F (NIST rule A).
TEST(GcodeTimelineRotaryAxes, TimesLinearMovesByTheirXyzLengthAndRotaryOnlyMovesByTheirDegrees) {
  sim::GcodeTimelineReader reader({sim::RotaryAxisSetup::Firmware::Marlin, {"U", "V"}});
  EXPECT_NEAR(reader.read("G1 U30 V40 F600", 0).moveSeconds, 5.0, 1e-12);  // 50 degrees at 10 degrees/s
  EXPECT_NEAR(reader.read("G1 X30 U60 F600", 0).moveSeconds, 3.0, 1e-12);  // 30 mm at 10 mm/s; U rides along
  EXPECT_NEAR(reader.axisPosition(0), 60.0, 1e-12);
  const sim::TimelineLine unknown = reader.read("G1 W90 F600", 0);  // no W axis: skipped, as Marlin does
  EXPECT_EQ(unknown.moveSeconds, 0.0);
  EXPECT_FALSE(unknown.turns);
  reader.read("G92 U0", 0);
  EXPECT_EQ(reader.axisPosition(0), 0.0);
}

TEST(GcodeTimelineRotaryAxes, KlipperRefusesAManualStepperItLacksAndIgnoresRotaryLetters) {
  sim::GcodeTimelineReader reader({sim::RotaryAxisSetup::Firmware::Klipper, {"tilt"}});
  EXPECT_EQ(reader.read("MANUAL_STEPPER STEPPER=tlit MOVE=10", 0).error, "The value 'tlit' is not valid for STEPPER");
  EXPECT_FALSE(reader.read("G1 U30 F600", 0).turns);
  const sim::TimelineLine move = reader.read("MANUAL_STEPPER STEPPER=tilt MOVE=-12 SPEED=4", 0);
  EXPECT_TRUE(move.error.empty());
  EXPECT_NEAR(move.moveSeconds, 3.0, 1e-12);
  EXPECT_TRUE(sim::GcodeTimelineReader({sim::RotaryAxisSetup::Firmware::Klipper, {}})
                  .read("MANUAL_STEPPER STEPPER=tilt MOVE=10", 0)
                  .error.empty());  // without any manual stepper Klipper only reports an unknown command
}

// After M83, Klipper's G90 keeps extrusion relative (gcode_move.py: E is relative after G91 or M83), while
// Marlin's G90 makes every axis absolute, E too: a stitched program's transition (G90) must not change Klipper's E.
TEST(GcodeTimelineExtrusionMode, KlippersG90KeepsM83sRelativeExtrusionAndMarlinsDoesNot) {
  sim::GcodeTimelineReader klipper({sim::RotaryAxisSetup::Firmware::Klipper, {}});
  sim::GcodeTimelineReader marlin({sim::RotaryAxisSetup::Firmware::Marlin, {}});
  for (sim::GcodeTimelineReader* reader : {&klipper, &marlin})
    for (const char* line : {"M83", "G90", "G1 X10 E1 F600"}) reader->read(line, 0);
  EXPECT_TRUE(klipper.read("G1 X20 E1", 0).extrudes);
  EXPECT_FALSE(marlin.read("G1 X20 E1", 0).extrudes);  // E stays at 1: nothing pushed
}

// Moonraker and OctoPrint on the test's clock at 10x: the job ends exactly when the sum of its moves has passed.
class HttpTwoAxisPrint : public testing::TestWithParam<test::PrinterProtocol> {};

TEST_P(HttpTwoAxisPrint, PrintsEachStepAtItsAxisCoordinatesInTheTimeItsMovesTake) {
  const bool klipper = GetParam() == test::PrinterProtocol::Moonraker;
  static std::atomic<long long> elapsedUs{0};
  elapsedUs = 0;
  const auto origin = std::chrono::steady_clock::now();
  PrinterSimulatorOptions options;
  options.speed = 10.0;
  options.steadyNow = [origin] { return origin + std::chrono::microseconds(elapsedUs.load()); };
  if (klipper)
    options.rotaryAxes.manualSteppers = {"tilt", "rotation"};
  else
    options.rotaryAxes.letters = {"U", "V"};
  auto sim = test::printerSimulator(GetParam(), options);
  ASSERT_TRUE(sim->start().ok());
  const TwoAxisProgram program = multidir::test::twoAxisProgram(klipper);
  const std::string path =
      // One folder per protocol: ctest runs the two side by side, and each writes its own program.
      test::writeFile(std::filesystem::path(testing::TempDir()) / (klipper ? "two-axis-moonraker" : "two-axis-octoprint") /
                          "job.gcode",
                      program.text);
  auto link = test::printerLinkTo(GetParam(), sim->port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(test::outcome(link->upload(path, "job.gcode")).ok());
  ASSERT_TRUE(test::outcome(link->startPrint("job.gcode")).ok());
  const long long endUs = std::llround(program.moveSeconds / options.speed * 1e6);
  elapsedUs = endUs - 1000;
  EXPECT_EQ(sim->state().jobState, "printing");
  elapsedUs = endUs + 1000;
  EXPECT_EQ(sim->state().jobState, "complete");
  expectTheStepsPrintedWhereTheirAxesTurnThem(sim->axisLog(), program);
}

INSTANTIATE_TEST_SUITE_P(Protocols, HttpTwoAxisPrint, test::httpProtocols(), test::protocolName);

TEST(MarlinTwoAxisPrint, PrintsEachStepAtItsAxisCoordinatesInTheTimeItsMovesTake) {
  MarlinSimulatorOptions options = test::fastMarlinSimulatorOptions(1000.0);
  options.rotaryAxes.letters = {"U", "V"};
  test::SimulatedMarlin marlin(options);
  const TwoAxisProgram program = multidir::test::twoAxisProgram(false);
  const std::string path =
      test::writeFile(std::filesystem::path(testing::TempDir()) / "two-axis-marlin" / "job.gcode", program.text);
  auto link = test::connectedLink(marlin.link(test::fastPrinterOptions()));
  ASSERT_TRUE(test::uploadedAndStarted(*link, path));
  ASSERT_TRUE(test::eventually([&] { return link->status().state == PrinterJobState::Complete; }, 10s));
  expectTheStepsPrintedWhereTheirAxesTurnThem(marlin.simulator().axisLog(), program);
}

// Klipper ends a job at a MANUAL_STEPPER for a stepper it lacks, in its own words.
TEST(MoonrakerTwoAxisPrint, EndsTheJobInErrorAtAStepperThePrinterLacks) {
  PrinterSimulatorOptions options;
  options.speed = 1000.0;
  options.rotaryAxes.manualSteppers = {"tilt"};
  MoonrakerSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  const std::string path = test::writeFile(std::filesystem::path(testing::TempDir()) / "two-axis-lacking" / "job.gcode",
                                           multidir::test::twoAxisProgram(true).text);
  auto link = test::moonrakerLinkTo(sim.port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(test::uploadedAndStarted(*link, path));
  ASSERT_TRUE(test::eventually([&] { return sim.state().jobState == "error"; }, 5s));
  EXPECT_EQ(sim.state().message, "The value 'rotation' is not valid for STEPPER");
}

// The links ask each printer which axes its firmware has, before a program that turns them is sent.
TEST(PrinterFirmwareAxes, MoonrakerListsKlippersManualSteppers) {
  PrinterSimulatorOptions options;
  options.rotaryAxes.manualSteppers = {"tilt", "rotation"};
  MoonrakerSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  auto link = test::moonrakerLinkTo(sim.port());
  ASSERT_TRUE(link->connect().ok());
  std::future<core::Result<FirmwareAxes>> asked = link->readFirmwareAxes();
  ASSERT_EQ(asked.wait_for(3s), std::future_status::ready);
  const core::Result<FirmwareAxes> axes = asked.get();
  ASSERT_TRUE(axes.ok()) << axes.error().describe();
  EXPECT_EQ(axes->manualSteppers, (std::vector<std::string>{"tilt", "rotation"}));
  EXPECT_TRUE(axes->letters.empty());
}

TEST(PrinterFirmwareAxes, MarlinReportsItsExtraAxesInM114) {
  MarlinSimulatorOptions options = test::fastMarlinSimulatorOptions(100.0);
  options.rotaryAxes.letters = {"U", "V"};
  test::SimulatedMarlin marlin(options);
  auto link = test::connectedLink(marlin.link(test::fastPrinterOptions()));
  std::future<core::Result<FirmwareAxes>> asked = link->readFirmwareAxes();
  ASSERT_EQ(asked.wait_for(3s), std::future_status::ready);
  const core::Result<FirmwareAxes> axes = asked.get();
  ASSERT_TRUE(axes.ok()) << axes.error().describe();
  EXPECT_EQ(axes->letters, (std::vector<std::string>{"U", "V"}));
}

TEST(PrinterFirmwareAxes, MarlinWithoutExtraAxesReportsNone) {
  test::SimulatedMarlin marlin(test::fastMarlinSimulatorOptions(100.0));
  auto link = test::connectedLink(marlin.link(test::fastPrinterOptions()));
  std::future<core::Result<FirmwareAxes>> asked = link->readFirmwareAxes();
  ASSERT_EQ(asked.wait_for(3s), std::future_status::ready);
  const core::Result<FirmwareAxes> axes = asked.get();
  ASSERT_TRUE(axes.ok()) << axes.error().describe();
  EXPECT_TRUE(axes->letters.empty());
}

TEST(PrinterFirmwareAxes, OctoPrintCannotBeAsked) {
  OctoPrintSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  auto link = test::octoPrintLinkTo(sim.port());
  ASSERT_TRUE(link->connect().ok());
  const core::Result<FirmwareAxes> axes = link->readFirmwareAxes().get();
  ASSERT_FALSE(axes.ok());
  EXPECT_NE(axes.error().message.find("OctoPrint relays no firmware reply"), std::string::npos);
}

}  // namespace
}  // namespace multidir::hardware
