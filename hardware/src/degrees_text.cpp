#include "degrees_text.h"

#include <cstdio>

namespace multidir::hardware {

std::string degreesText(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", value);
  return text;
}

}  // namespace multidir::hardware
