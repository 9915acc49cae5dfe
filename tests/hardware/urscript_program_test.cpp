// The URScript subset the UR simulator runs: MultiDir's programs are read whole, anything else is refused with
// its line and column, as the controller's compile error names them.
#include "ur/urscript_program.h"

#include <gtest/gtest.h>

namespace {

using multidir::hardware::ur::parseUrScript;
using multidir::hardware::ur::UrStatementKind;

// The contract's example program (robot-contract.md), every statement of the subset.
const char* const kStep =
    "def multidir_step_03():\n"
    "  set_tcp(p[0.0, 0.0, 0.05, 0.0, 0.0, 0.0])\n"
    "  set_standard_analog_out(0, 0.4521)      # extruder filament speed\n"
    "  set_standard_analog_out(1, 0.7167)\n"
    "  set_standard_digital_out(0, True)\n"
    "  movej([0.1, -1.2, 1.5, -1.9, -1.57, 0.0], a=1.4, v=1.05)\n"
    "  movel(p[0.4, -0.1, 0.3, 0.0, 3.14, 0.0], a=1.2, v=0.25, r=0.0005)\n"
    "  sleep(0.5)\n"
    "  textmsg(\"multidir step 3 layer 12\")\n"
    "  while get_standard_analog_in(0) < 0.7100:   # wait until the nozzle is hot\n"
    "    sync()\n"
    "  end\n"
    "end\n";

TEST(UrScriptProgram, ReadsEveryStatementOfTheSubsetWithItsLine) {
  const auto parsed = parseUrScript(kStep);
  ASSERT_TRUE(parsed.program) << parsed.error.message << " at line " << parsed.error.line;
  const auto& p = *parsed.program;
  EXPECT_EQ(p.name, "multidir_step_03");
  ASSERT_EQ(p.statements.size(), 9u);
  EXPECT_EQ(p.statements[0].kind, UrStatementKind::SetTcp);
  EXPECT_DOUBLE_EQ(p.statements[0].pose[2], 0.05);
  EXPECT_EQ(p.statements[1].kind, UrStatementKind::SetAnalogOut);
  EXPECT_DOUBLE_EQ(p.statements[1].value, 0.4521);
  EXPECT_EQ(p.statements[3].kind, UrStatementKind::SetDigitalOut);
  EXPECT_TRUE(p.statements[3].flag);
  EXPECT_EQ(p.statements[4].kind, UrStatementKind::MoveJ);
  EXPECT_DOUBLE_EQ(p.statements[4].pose[1], -1.2);
  EXPECT_EQ(p.statements[5].kind, UrStatementKind::MoveL);
  EXPECT_DOUBLE_EQ(p.statements[5].v, 0.25);
  EXPECT_DOUBLE_EQ(p.statements[5].r, 0.0005);
  EXPECT_EQ(p.statements[5].line, 7);
  EXPECT_EQ(p.statements[7].text, "multidir step 3 layer 12");
  EXPECT_EQ(p.statements[8].kind, UrStatementKind::WaitAnalogInBelow);
  EXPECT_DOUBLE_EQ(p.statements[8].value, 0.71);
  EXPECT_EQ(p.statements[8].line, 10);
}

TEST(UrScriptProgram, AFunctionOutsideTheSubsetIsRefusedWithItsLine) {
  const auto parsed = parseUrScript(
      "def step():\n"
      "  movel(p[0.4, -0.1, 0.3, 0.0, 3.14, 0.0], a=1.2, v=0.25)\n"
      "  servoj([0, 0, 0, 0, 0, 0])\n"
      "end\n");
  ASSERT_FALSE(parsed.program);
  EXPECT_EQ(parsed.error.line, 3);
  EXPECT_EQ(parsed.error.column, 3);
  EXPECT_NE(parsed.error.message.find("'servoj' is not in the URScript subset"), std::string::npos)
      << parsed.error.message;
}

TEST(UrScriptProgram, AnArgumentOutsideTheSubsetIsRefusedAtItsColumn) {
  const auto parsed = parseUrScript(
      "def step():\n"
      "  movej([0, -1.5, 1.5, -1.5, -1.5, 0], a=1.4, v=1.05, t=2)\n"
      "end\n");
  ASSERT_FALSE(parsed.program);
  EXPECT_EQ(parsed.error.line, 2);
  EXPECT_EQ(parsed.error.column, 55);
  EXPECT_NE(parsed.error.message.find("'t' is not an argument"), std::string::npos) << parsed.error.message;
}

TEST(UrScriptProgram, AProgramWithoutItsEndOrWithASecondDefIsRefused) {
  const auto open = parseUrScript("def step():\n  sleep(1)\n");
  ASSERT_FALSE(open.program);
  EXPECT_EQ(open.error.line, 3);
  EXPECT_NE(open.error.message.find("without its 'end'"), std::string::npos);
  const auto two = parseUrScript("def a():\n  sleep(1)\nend\ndef b():\nend\n");
  ASSERT_FALSE(two.program);
  EXPECT_EQ(two.error.line, 4);
}

TEST(UrScriptProgram, OutOfRangeOutputsAreRefused) {
  const auto analog = parseUrScript("def step():\n  set_standard_analog_out(0, 1.5)\nend\n");
  ASSERT_FALSE(analog.program);
  EXPECT_EQ(analog.error.line, 2);
  EXPECT_NE(analog.error.message.find("between 0 and 1"), std::string::npos);
  const auto digital = parseUrScript("def step():\n  set_standard_digital_out(9, True)\nend\n");
  ASSERT_FALSE(digital.program);
  EXPECT_NE(digital.error.message.find("0 to 7"), std::string::npos);
}

// The movel register (docs/robot-cell.md, "Pause and resume"): UR's output integer registers are 0..47.
TEST(UrScriptProgram, AnOutputIntegerRegisterWriteIsReadAndAnUnknownRegisterIsRefused) {
  const auto write = parseUrScript("def step():\n  write_output_integer_register(24, 1234)\nend\n");
  ASSERT_TRUE(write.program) << write.error.message;
  ASSERT_EQ(write.program->statements.size(), 1u);
  EXPECT_EQ(write.program->statements[0].kind, UrStatementKind::WriteIntRegister);
  EXPECT_EQ(write.program->statements[0].index, 24);
  EXPECT_EQ(write.program->statements[0].integer, 1234);
  const auto beyond = parseUrScript("def step():\n  write_output_integer_register(48, 1)\nend\n");
  ASSERT_FALSE(beyond.program);
  EXPECT_NE(beyond.error.message.find("0 to 47"), std::string::npos);
  const auto fraction = parseUrScript("def step():\n  write_output_integer_register(24, 1.5)\nend\n");
  ASSERT_FALSE(fraction.program);
  EXPECT_NE(fraction.error.message.find("whole number"), std::string::npos);
}

}  // namespace
