#pragma once
// Numbers as the command line prints them.
#include <string>

#include "multidir/core/search/machine.h"

namespace multidir::cli {

// 1234567 -> "1,234,567".
std::string withThousands(long long value);

// printf-style text of one number: formatNumber("%.2f", 3.14159) -> "3.14".
std::string formatNumber(const char* pattern, double value);

// A printing direction's machine angles as the region and step tables show them: "-" on a 3-axis machine,
// "rotary   30.0" on a 4-DOF one, "tilt  45.0  azimuth   90.0" on a 5-DOF one.
std::string machineAnglesText(core::MachineKind kind, const core::MachineAngles& angles);

}  // namespace multidir::cli
