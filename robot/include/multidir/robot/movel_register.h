#pragma once
// Which movel of a step's program the arm is on, as the robot itself says it (docs/robot-cell.md, "Pause and
// resume"): the program writes movel k's number to the output integer register kMovelRegister just before movel
// k (0 before the first and in the joint moves), and the controller's RTDE state carries the register. Paths of
// one layer that cross at one height cannot be told apart by where the arm stands; the register tells them apart.
#include <array>
#include <string>
#include <vector>

namespace multidir::robot {

// Does the program text number its movels in the register (programs written before it did do not)?
bool programNumbersMovels(const std::string& script);

// The movel (0-based) the register names, when the arm at `tcpMm` stands within `toleranceMm` of that movel's
// straight path (from the previous movel's end; the first from `firstFromMm`, the step's approach point); -1
// when the register is 0 (a joint move), names no movel of the program, or the arm is not on its path (the
// register of another program). `ends` are the movels' targets (mm, base frame), in order.
int movelNamedByRegister(const std::vector<std::array<double, 3>>& ends, const std::array<double, 3>& firstFromMm,
                         const std::array<double, 3>& tcpMm, int movelRegister, double toleranceMm);

}  // namespace multidir::robot
