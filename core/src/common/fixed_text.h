#pragma once
// A number written with a fixed count of decimals ("12.35", "+0.20"): the one formatter behind the millimetres,
// areas and prices that core's notes and errors quote, so that every message rounds the same way.
#include <cstdio>
#include <string>

namespace multidir::core::detail {

// `decimals` digits after the point; with `showSign`, a "+" before positive values too.
inline std::string fixedText(double value, int decimals, bool showSign = false) {
  char text[64];
  if (showSign)
    std::snprintf(text, sizeof text, "%+.*f", decimals, value);
  else
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace multidir::core::detail
