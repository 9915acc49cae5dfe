// Where a paused arm is on its step's program (hardware/src/ur/robot_pause; docs/robot-cell.md, "Pause and resume").
#include <gtest/gtest.h>

#include <string>

#include "multidir/hardware/robot_pause.h"

namespace {

using multidir::hardware::movelUnderWay;
using multidir::hardware::parseStepScript;
using multidir::hardware::PauseGeometry;
using multidir::hardware::StepScript;

// A step as `multidir robot-program` writes it, on a flat layer at z = 400 mm (base frame): a travel to
// (10, 0), then an extrusion from there to (30, 0).
const char* const kStep =
    "def multidir_step_01():\n"
    "  set_tcp(p[0.0000000, 0.0000000, 0.0500000, 0.0000000, 0.0000000, 0.0000000])\n"
    "  set_standard_analog_out(0, 0.000000)\n"
    "  textmsg(\"multidir step 1 layer 1\")\n"
    "  movel(p[0.0000000, 0.0000000, 0.4000000, 0.0000000, 0.0000000, 0.0000000], a=1.5000, v=0.200000, r=0.000000)\n"
    "  movel(p[0.0100000, 0.0000000, 0.4000000, 0.0000000, 0.0000000, 0.0000000], a=1.5000, v=0.200000, r=0.000000)\n"
    "  set_standard_analog_out(0, 0.300000)\n"
    "  movel(p[0.0300000, 0.0000000, 0.4000000, 0.0000000, 0.0000000, 0.0000000], a=1.5000, v=0.030000, r=0.000000)\n"
    "  set_standard_analog_out(0, 0.000000)\n"
    "end\n";

StepScript step() {
  auto script = parseStepScript(kStep, "step");
  EXPECT_TRUE(script.ok());
  return script.ok() ? script.value() : StepScript{};
}

// The arm held 0.15 mm into the extrusion (within the 0.2 mm tolerance of the travel's end too) is on the
// extrusion: naming the travel would make the pause take it back to the travel's end and the resumed program
// print those 0.15 mm again.
TEST(RobotPause, AnArmHeldJustIntoAMoveIsOnThatMoveNotOnTheOneBefore) {
  const StepScript script = step();
  ASSERT_EQ(script.movels.size(), 3u);
  EXPECT_EQ(movelUnderWay(script, PauseGeometry{}, {10.15, 0.0, 400.0}, 0.2, 0), 2);
}

// At the common point of two moves either is right; the first is named.
TEST(RobotPause, AnArmHeldAtTheEndOfAMoveIsOnThatMove) {
  const StepScript script = step();
  ASSERT_EQ(script.movels.size(), 3u);
  EXPECT_EQ(movelUnderWay(script, PauseGeometry{}, {10.0, 0.0, 400.0}, 0.2, 0), 1);
}

// Just before the travel's end, the travel (not the extrusion 0.15 mm away).
TEST(RobotPause, AnArmHeldJustBeforeTheEndOfAMoveIsOnThatMove) {
  const StepScript script = step();
  ASSERT_EQ(script.movels.size(), 3u);
  EXPECT_EQ(movelUnderWay(script, PauseGeometry{}, {9.85, 0.0, 400.0}, 0.2, 0), 1);
}

}  // namespace
