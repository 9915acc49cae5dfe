#pragma once
// The subset of URScript that MultiDir's robot programs use (docs/hardware.md, "UR controller"; the contract
// the program writer `multidir robot-program` follows): one `def NAME():` ... `end` with, one per line,
// set_tcp, set_standard_analog_out, set_standard_digital_out, write_output_integer_register, movej, movel, sleep,
// textmsg and the heat wait
// `while get_standard_analog_in(0) < X:` / `sync()` / `end`. Anything else is refused with the line and column,
// as the controller's compile error names them, so the simulator runs exactly what the program writer may emit.
// URScript's own units stay here: metres, radians, seconds.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace multidir::hardware::ur {

enum class UrStatementKind {
  SetTcp,             // pose = the TCP in the flange frame
  SetAnalogOut,       // index 0..1, value 0..1
  SetDigitalOut,      // index 0..7, flag
  MoveJ,              // pose = joints (rad), a (rad/s^2), v (rad/s)
  MoveL,              // pose = TCP target in the base frame (m, rotation vector), a (m/s^2), v (m/s), r (m)
  Sleep,              // value = seconds
  TextMsg,            // text
  WaitAnalogInBelow,  // while get_standard_analog_in(index) < value: sync() end
  WriteIntRegister,   // write_output_integer_register(index, integer): index 0..47, integer in `integer`
};

struct UrStatement {
  UrStatementKind kind = UrStatementKind::Sleep;
  int line = 0;  // 1-based line of the program text
  std::array<double, 6> pose{};
  int index = 0;
  double value = 0.0;
  std::int32_t integer = 0;
  bool flag = false;
  double a = 0.0;
  double v = 0.0;
  double r = 0.0;
  std::string text;
};

struct UrProgram {
  std::string name;  // the def's name
  std::vector<UrStatement> statements;
};

struct UrScriptError {
  int line = 0;    // 1-based
  int column = 0;  // 1-based, where the offending text starts
  std::string message;
};

struct UrScriptParse {
  std::optional<UrProgram> program;
  UrScriptError error;  // when !program
};

// UR's defaults when a move names no a or v (URScript manual): movej a=1.4 rad/s^2, v=1.05 rad/s; movel
// a=1.2 m/s^2, v=0.25 m/s, r=0.
UrScriptParse parseUrScript(const std::string& text);

}  // namespace multidir::hardware::ur
