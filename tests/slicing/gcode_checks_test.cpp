// G-code read back and checked: extrusions on or above the base plane and inside the printer, turns only with
// the nozzle above the clearance and nothing else moving; refusals name step, line and reason.
#include "multidir/slicing/gcode_checks.h"

#include <gtest/gtest.h>

#include "multidir/slicing/estimates.h"
#include "multidir/slicing/gcode_program.h"
#include "multidir/slicing/stitch.h"

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

// Issue 28: `G1 Z-5 E3` (no XY move, so no extrusion) drove the nozzle into the bed unchecked.
TEST(GcodeChecks, AMoveBelowTheBedIsRefusedThoughItLaysNoLine) {
  const auto checked = checkStepProgram(parsed("G90\nM83\n; MULTIDIR STEP 1\nG1 X10 Y10 Z0.3\nG1 X20 E1\nG1 Z-5 E3\n"),
                                        bounds(1, 0.0), "step-01.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().message.find("step 1, line 6: a move to z -5.00 mm, below the bed"), std::string::npos)
      << checked.error().message;
}

// Issue 28: a step's program that commands the platform's axis to where the parser believes it stands (A0 at
// the start) turns the platform all the same: the program does not know where it stands.
TEST(GcodeChecks, AnyCommandOfThePlatformsAxisInAStepsProgramIsRefused) {
  for (const std::string line : {"G1 A0", "MANUAL_STEPPER STEPPER=rotary_a MOVE=0"}) {
    const auto checked =
        checkStepProgram(parsed("G90\nM83\n" + line + "\n; MULTIDIR STEP 1\nG1 X10 Y10 Z0.3\nG1 X20 E1\n"),
                         bounds(1, 0.0), "step-01.gcode");
    ASSERT_FALSE(checked.ok()) << line;
    EXPECT_NE(checked.error().message.find("line 3: the platform turns inside a step's own program"), std::string::npos)
        << checked.error().message;
  }
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

TEST(GcodeChecks, ExtrudingWhileRetractedIsRefused) {
  // The filament is drawn back 1 mm for a travel (E 1 to 0) and never pushed again: the next line starts
  // without plastic.
  const GcodeProgram p = parsed("M82\n; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\nG1 E0 F2400\nG92 E0\n"
                                "G1 X120 Y120\nG1 X130 E0.5\n");
  const auto checked = checkStepProgram(p, bounds(1, 0.0), "step-01.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_EQ(checked.error().code, core::ErrorCode::CheckFailed);
  EXPECT_EQ(checked.error().where, "step-01.gcode");
  EXPECT_NE(checked.error().message.find("step 1, line 8"), std::string::npos) << checked.error().message;
  EXPECT_NE(checked.error().message.find("retracted by 1.00 mm"), std::string::npos) << checked.error().message;
}

TEST(GcodeChecks, RetractionPushedBackBeforeTheNextExtrusionPassesInAbsoluteAndRelativeE) {
  const GcodeProgram absolute = parsed("M82\n; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\nG1 E0\nG92 E0\n"
                                       "G1 X120 Y120\nG1 E1\nG92 E0\nG1 X130 E0.5\n");
  const GcodeProgram relative = parsed("M83\n; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\nG1 E-2\n"
                                       "G1 X120 Y120\nG1 E2\nG1 X130 E0.5\n");
  for (const GcodeProgram* p : {&absolute, &relative}) {
    const auto checked = checkStepProgram(*p, bounds(1, 0.0), "step-01.gcode");
    ASSERT_TRUE(checked.ok()) << checked.error().describe();
    EXPECT_NEAR(checked->filamentAtEnd.retractedMm, 0.0, 1e-9);
  }
}

TEST(GcodeChecks, FirmwareRetractionWithoutUnretractIsRefused) {
  const GcodeProgram p = parsed("; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\nG10\nG1 X120 Y120\nG1 X130 E2\n");
  const auto checked = checkStepProgram(p, bounds(1, 0.0), "step-01.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().message.find("line 6"), std::string::npos) << checked.error().message;
  EXPECT_NE(checked.error().message.find("G10 without G11"), std::string::npos) << checked.error().message;
  const GcodeProgram primed = parsed("; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\nG10\nG1 X120 Y120\nG11\n"
                                     "G1 X130 E2\n");
  EXPECT_TRUE(checkStepProgram(primed, bounds(1, 0.0), "step-01.gcode").ok());
}

TEST(GcodeChecks, AStepThatStartsRetractedMustPrimeBeforeItsFirstExtrusion) {
  // Step 1 ended with the filament drawn back 3 mm (its program's end state carries over to step 2's program).
  FilamentState drawnBack;
  drawnBack.retractedMm = 3.0;
  const GcodeProgram unprimed = parsed("G90\nG92 E0\n; MULTIDIR STEP 2\nG1 X100 Y100 Z10.2\nG1 X110 E1\n");
  const auto refused = checkStepProgram(unprimed, bounds(2, 10.0), "step-02.gcode", nullptr, drawnBack);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("step 2, line 5"), std::string::npos) << refused.error().message;
  EXPECT_NE(refused.error().message.find("retracted by 3.00 mm"), std::string::npos) << refused.error().message;
  const GcodeProgram primed =
      parsed("G90\nG92 E0\nG1 E3.2 F2400\nG92 E0\n; MULTIDIR STEP 2\nG1 X100 Y100 Z10.2\nG1 X110 E1\n");
  EXPECT_TRUE(checkStepProgram(primed, bounds(2, 10.0), "step-02.gcode", nullptr, drawnBack).ok());
}

TEST(GcodeChecks, StitchedProgramThatTurnsWithoutPrimingAgainIsRefused) {
  const GcodeProgram p = parsed(
      "; MULTIDIR STEP 1\nG1 X100 Y100 Z0.2\nG1 X110 E1\n; MULTIDIR TRANSITION 1\nG92 E0\nG1 E-2\nG1 Z50\nG1 X5 Y5\n"
      "G1 A30\nG1 X100 Y100\nG92 E0\nG1 E1\nG92 E0\n; MULTIDIR STEP 2\nG1 Z5.2\nG1 X110 E2\n");
  const auto checked = checkStitchedProgram(p, {bounds(1, 0), bounds(2, 5)}, {{1, 40.0}}, "job.gcode");
  ASSERT_FALSE(checked.ok());
  EXPECT_EQ(checked.error().where, "job.gcode");
  EXPECT_NE(checked.error().message.find("step 2, line 16"), std::string::npos) << checked.error().message;
  EXPECT_NE(checked.error().message.find("retracted by 1.00 mm"), std::string::npos) << checked.error().message;
}

TEST(Stitch, PrimeCommandsPushBackWhatIsDrawnBackPlusTheRestartExtra) {
  PrimeSettings prime;
  prime.restartExtraMm = 0.2;
  prime.speedMmPerS = 30.0;
  FilamentState state;
  state.retractedMm = 1.5;
  const GcodeProgram p = parsed("M82\n" + primeCommands(state, prime));
  double pushed = 0.0;
  for (const GcodeMove& m : p.moves) pushed += m.filamentMm;
  EXPECT_NEAR(pushed, 1.7, 1e-9);
  state.firmwareRetracted = true;
  EXPECT_EQ(primeCommands(state, prime).rfind("G11", 0), 0u);
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

TEST(Estimates, SupportVolumeIsTheFilamentExtrudedUnderTheSupportFeatures) {
  // Absolute E with a reset, then relative E: 2 + 1.5 mm under support, 3 + 4 mm elsewhere; 10.5 mm in all
  // is 0.021 cm^3, so 3.5 mm is 0.007 cm^3.
  const auto e = parseEstimate(
      "M82\nG92 E0\n;TYPE:Perimeter\nG1 X1 E3\n;TYPE:Support material\nG1 X2 E5\nG1 E4.2\nG1 E5\nG92 E0\n"
      "M83\n;TYPE:Support material interface\nG1 X3 E1.5\n;TYPE:Solid infill\nG1 X4 E4 ; support\n"
      "; filament used [mm] = 10.5\n; filament used [cm3] = 0.021\n"
      "; estimated printing time (normal mode) = 1m 0s\n",
      "x.gcode");
  ASSERT_TRUE(e.ok()) << e.error().describe();
  // The retract (E5 -> E4.2) and its prime back to E5 add nothing.
  EXPECT_NEAR(e->supportFilamentMm, 3.5, 1e-9);
  EXPECT_NEAR(e->supportCm3, 0.007, 1e-12);
}

TEST(Estimates, GcodeWithoutEstimatesIsMalformed) {
  const auto e = parseEstimate("G1 X1\n", "x.gcode");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().code, core::ErrorCode::MalformedFile);
}
