#pragma once
// What every benchmark program needs: its lists from the command line and the process's CPU time.
#include <sys/resource.h>

#include <sstream>
#include <string>
#include <vector>

namespace multidir::bench {

// "kitten,bunny" -> {"kitten", "bunny"}; empty items are left out.
inline std::vector<std::string> commaList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

// User + system CPU seconds of the whole process so far, every thread counted: on a machine shared with other
// work this compares runs where wall time does not.
inline double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace multidir::bench
