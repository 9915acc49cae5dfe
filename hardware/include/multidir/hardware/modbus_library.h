#pragma once
// Which libmodbus MultiDir was built and is running with, for `multidir info --version` and bug reports.
#include <string>

namespace multidir::hardware {

// "3.1.6": the libmodbus version linked at run time.
std::string modbusLibraryVersion();

}  // namespace multidir::hardware
