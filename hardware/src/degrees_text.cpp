#include "degrees_text.h"

#include <cmath>
#include <cstdio>

namespace multidir::hardware {

std::string degreesText(double value) {
  char text[32];
  // Beyond a million degrees (no device's angle, a corrupt file's) two decimals would print hundreds of digits.
  std::snprintf(text, sizeof(text), std::abs(value) < 1e6 ? "%.2f" : "%.6g", value);
  return text;
}

}  // namespace multidir::hardware
