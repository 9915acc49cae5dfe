// G-code read back and checked: extrusions on or above the base plane and inside the printer, turns only with
// the nozzle above the clearance and nothing else moving; refusals name step, line and reason.
#include "multidir/slicing/gcode_checks.h"

#include <gtest/gtest.h>

#include "multidir/slicing/estimates.h"
#include "multidir/slicing/gcode_program.h"

using namespace multidir;
using namespace multidir::slicing;

namespace {

StepBounds bounds(int step, double baseZ) {
  StepBounds b;
  b.step = step;
  b.baseZMm = baseZ;
  b.bedMin = {0, 0};
  b.bedMax = {220, 220};
  b.maxZMm = 250;
  return b;
}

GcodeProgram parsed(const std::string& text) {
  core::Result<GcodeProgram> p = parseGcode(text);
  EXPECT_TRUE(p.ok()) << p.error().describe();
  return p.ok() ? *p : GcodeProgram{};
}

}  // namespace

TEST(GcodeProgram, AbsoluteAndRelativeExtrusionGiveTheSameFilament) {
  const GcodeProgram absolute = parsed("G90\nM82\nG92 E0\nG1 X10 Y10 Z1\nG1 X20 E1.5\nG1 X30 E2\n");
  const GcodeProgram relative = parsed("G90\nM83\nG1 X10 Y10 Z1\nG1 X20 E1.5\nG1 X30 E0.5\n");
  ASSERT_EQ(absolute.moves.size(), 3u);
  ASSERT_EQ(relative.moves.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(absolute.moves[i].filamentMm, relative.moves[i].filamentMm);
    EXPECT_EQ(absolute.moves[i].to, relative.moves[i].to);
  }
  EXPECT_TRUE(absolute.moves[1].extrudes());
  EXPECT_FALSE(absolute.moves[0].extrudes());
}

TEST(GcodeProgram, RotaryAxisAndKlipperManualStepperAreTurns) {
  const GcodeProgram p = parsed("G1 A30 F1800\nMANUAL_STEPPER STEPPER=rotary_a MOVE=-15 SPEED=30\n");
  ASSERT_EQ(p.moves.size(), 2u);
  EXPECT_TRUE(p.moves[0].rotates());
  EXPECT_DOUBLE_EQ(p.moves[1].rotaryFromDegrees, 30);
  EXPECT_DOUBLE_EQ(p.moves[1].rotaryToDegrees, -15);
}

TEST(GcodeProgram, AWordThatIsNotANumberIsRefusedWithItsLine) {
  const auto p = parseGcode("G1 X1\nG1 Xabc\n", "A", "bad.gcode");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, core::ErrorCode::MalformedFile);
  EXPECT_NE(p.error().message.find("line 2"), std::string::npos);
}

TEST(GcodeChecks, ExtrusionBelowTheBasePlaneIsRefusedNamingStepAndLine) {
  const GcodeProgram p = parsed("; MULTIDIR STEP 2\nG1 X100 Y100 Z10.2\nG1 X110 E1\nG1 Z9.5\nG1 X120 E2\n");
  const auto checked = checkStepProgram(p, bounds(2, 10.0), "step-02.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_EQ(checked.error().code, core::ErrorCode::CheckFailed);
  EXPECT_NE(checked.error().message.find("step 2, line 5"), std::string::npos) << checked.error().message;
  EXPECT_NE(checked.error().message.find("below the step's base plane"), std::string::npos);
}

TEST(GcodeChecks, ExtrusionOutsideTheBedIsRefused) {
  const GcodeProgram p = parsed("; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X230 E1\n");
  const auto checked = checkStepProgram(p, bounds(1, 0.0), "step-01.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().message.find("outside the printer's bed"), std::string::npos) << checked.error().message;
}

TEST(GcodeChecks, ProgramOnItsBasePlaneInsideTheBedPassesWithTotals) {
  const GcodeProgram p = parsed("; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\nG1 Z0.4\nG1 X100 E2\n");
  const auto checked = checkStepProgram(p, bounds(1, 0.0), "step-01.gcode");
  ASSERT_TRUE(checked.ok()) << checked.error().describe();
  EXPECT_EQ(checked->extrusions, 2);
  EXPECT_DOUBLE_EQ(checked->filamentMm, 2.0);
  EXPECT_DOUBLE_EQ(checked->highestZMm, 0.4);
}

TEST(GcodeChecks, TurnWithTheNozzleBelowTheClearanceIsRefused) {
  const GcodeProgram p = parsed(
      "; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\n; MULTIDIR TRANSITION 1\nG1 Z20\nG1 A30\n"
      "; MULTIDIR STEP 2\nG1 X100 Y100 Z5.2\nG1 X110 E2\n");
  const auto checked = checkStitchedProgram(p, {bounds(1, 0), bounds(2, 5)}, {{1, 40.0}}, "job.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().message.find("step 1, line 6"), std::string::npos) << checked.error().message;
  EXPECT_NE(checked.error().message.find("below the swept part's clearance"), std::string::npos);
}

TEST(GcodeChecks, TurnThatAlsoMovesTheNozzleIsRefused) {
  const GcodeProgram p = parsed(
      "; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\n; MULTIDIR TRANSITION 1\nG1 Z50\nG1 X5 A30\n"
      "; MULTIDIR STEP 2\nG1 X100 Y100 Z5.2\nG1 X110 E2\n");
  const auto checked = checkStitchedProgram(p, {bounds(1, 0), bounds(2, 5)}, {{1, 40.0}}, "job.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().message.find("turns while the nozzle"), std::string::npos) << checked.error().message;
}

TEST(GcodeChecks, ParkingBeforeLiftingIsRefused) {
  const GcodeProgram p = parsed(
      "; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\n; MULTIDIR TRANSITION 1\nG1 X5 Y5\nG1 Z50\nG1 A30\n"
      "; MULTIDIR STEP 2\nG1 X100 Y100 Z5.2\nG1 X110 E2\n");
  const auto checked = checkStitchedProgram(p, {bounds(1, 0), bounds(2, 5)}, {{1, 40.0}}, "job.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().message.find("lift before parking"), std::string::npos) << checked.error().message;
}

TEST(GcodeChecks, LiftParkTurnReturnPasses) {
  const GcodeProgram p = parsed(
      "; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\n; MULTIDIR TRANSITION 1\nG1 E-1\nG1 Z50\nG1 X5 Y5\nG1 A30\n"
      "G1 X100 Y100\nG1 E1\n; MULTIDIR STEP 2\nG1 Z5.2\nG1 X110 E2\n");
  const auto checked = checkStitchedProgram(p, {bounds(1, 0), bounds(2, 5)}, {{1, 40.0}}, "job.gcode");
  ASSERT_TRUE(checked.ok()) << checked.error().describe();
  EXPECT_EQ(checked->size(), 2u);
}

TEST(Estimates, PrusaSlicerCommentsGiveTimeAndFilament) {
  const auto e = parseEstimate(
      "G1 X1\n; filament used [mm] = 1499.18\n; filament used [cm3] = 3.61\n; total filament used [g] = 4.47\n"
      "; estimated printing time (normal mode) = 1h 13m 58s\n",
      "x.gcode");
  ASSERT_TRUE(e.ok()) << e.error().describe();
  EXPECT_DOUBLE_EQ(e->printSeconds, 3600 + 13 * 60 + 58);
  EXPECT_DOUBLE_EQ(e->filamentMm, 1499.18);
  EXPECT_DOUBLE_EQ(e->filamentGrams, 4.47);
}

TEST(Estimates, GcodeWithoutEstimatesIsMalformed) {
  const auto e = parseEstimate("G1 X1\n", "x.gcode");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().code, core::ErrorCode::MalformedFile);
}
