#include "multidir/hardware/simulated_axes.h"

#include <set>
#include <sstream>

namespace multidir::hardware {

core::Status validate(const SimulatedRotaryAxes& axes, const std::string& option) {
  const auto refuse = [&](const std::string& what) {
    return core::Error{core::ErrorCode::InvalidParameter, what, option};
  };
  if (axes.letters.size() + axes.manualSteppers.size() > kMaxSimulatedRotaryAxes)
    return refuse("a simulated printer has at most " + std::to_string(kMaxSimulatedRotaryAxes) + " rotary axes, not " +
                  std::to_string(axes.letters.size() + axes.manualSteppers.size()));
  std::set<std::string> seen;
  for (const std::string& letter : axes.letters) {
    if (letter.size() != 1 || std::string("ABCUVW").find(letter) == std::string::npos)
      return refuse("'" + letter + "' is not a rotary axis letter: give A, B, C, U, V or W (upper case)");
    if (!seen.insert(letter).second) return refuse("the axis " + letter + " is given twice");
  }
  for (const std::string& name : axes.manualSteppers) {
    if (name.empty() || name.find_first_of(" \t=;") != std::string::npos)
      return refuse("'" + name + "' is not a [manual_stepper] name: give one word without spaces, '=' or ';'");
    if (!seen.insert(name).second) return refuse("the manual stepper " + name + " is given twice");
  }
  return core::Done{};
}

std::vector<std::string> splitAxisList(const std::string& text) {
  std::vector<std::string> names;
  std::stringstream list(text);
  std::string name;
  while (std::getline(list, name, ',')) names.push_back(name);
  return names;
}

}  // namespace multidir::hardware
