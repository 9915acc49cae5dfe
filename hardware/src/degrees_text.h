#pragma once
// How hardware messages print an angle: two decimals, the register resolution of every device (0.01 degree).
#include <string>

namespace multidir::hardware {

// degreesText(12.3456) == "12.35"; beyond 1e6 in magnitude six significant digits: "1e+308".
std::string degreesText(double value);

}  // namespace multidir::hardware
