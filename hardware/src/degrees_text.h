#pragma once
// How hardware messages print an angle: two decimals, the register resolution of every device (0.01 degree).
#include <string>

namespace multidir::hardware {

// degreesText(12.3456) == "12.35".
std::string degreesText(double value);

}  // namespace multidir::hardware
