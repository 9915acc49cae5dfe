#pragma once
// Numbers as the command line prints them.
#include <string>

namespace multidir::cli {

// 1234567 -> "1,234,567".
std::string withThousands(long long value);

// printf-style text of one number: formatNumber("%.2f", 3.14159) -> "3.14".
std::string formatNumber(const char* pattern, double value);

}  // namespace multidir::cli
