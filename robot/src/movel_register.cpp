#include "multidir/robot/movel_register.h"

#include <algorithm>
#include <cmath>

#include "multidir/robot/robot_program.h"

namespace multidir::robot {
namespace {

double distanceToSegment(const std::array<double, 3>& p, const std::array<double, 3>& a,
                         const std::array<double, 3>& b) {
  double ab2 = 0.0, apab = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    ab2 += (b[i] - a[i]) * (b[i] - a[i]);
    apab += (p[i] - a[i]) * (b[i] - a[i]);
  }
  const double t = ab2 > 0.0 ? std::clamp(apab / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double c = a[i] + t * (b[i] - a[i]) - p[i];
    d2 += c * c;
  }
  return std::sqrt(d2);
}

}  // namespace

bool programNumbersMovels(const std::string& script) {
  return script.find("write_output_integer_register(" + std::to_string(kMovelRegister) + ", ") != std::string::npos;
}

int movelNamedByRegister(const std::vector<std::array<double, 3>>& ends, const std::array<double, 3>& firstFromMm,
                         const std::array<double, 3>& tcpMm, int movelRegister, double toleranceMm) {
  if (movelRegister < 1 || static_cast<std::size_t>(movelRegister) > ends.size()) return -1;
  const std::size_t i = static_cast<std::size_t>(movelRegister - 1);
  const std::array<double, 3>& from = i == 0 ? firstFromMm : ends[i - 1];
  return distanceToSegment(tcpMm, from, ends[i]) <= toleranceMm ? static_cast<int>(i) : -1;
}

}  // namespace multidir::robot
