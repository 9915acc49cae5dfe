#pragma once
// The range a printer's numbers must lie in before MultiDir shows them or acts on them. A sensor reads
// between absolute zero and a few hundred degrees (Marlin writes -14 for an open thermistor, a shorted one
// reads hot); line noise or a broken server ("T:nan", "temperature": 1e308) is not a reading.
#include <cmath>
#include <sstream>
#include <string>

namespace multidir::hardware {

constexpr double kMinPlausibleCelsius = -273.15;
constexpr double kMaxPlausibleCelsius = 2000.0;

inline bool plausibleCelsius(double value) {
  return std::isfinite(value) && value >= kMinPlausibleCelsius && value <= kMaxPlausibleCelsius;
}

// "`field` reads 1e+308 °C, outside what a heater's sensor reports (-273.15 to 2000 °C)".
inline std::string implausibleCelsiusMessage(const std::string& field, double value) {
  std::ostringstream out;
  out.precision(6);
  out << field << " reads " << value << " \u00b0C, outside what a heater's sensor reports (" << kMinPlausibleCelsius
      << " to " << kMaxPlausibleCelsius << " \u00b0C): the printer or the server answering for it is faulty";
  return out.str();
}

}  // namespace multidir::hardware
