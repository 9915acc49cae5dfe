// libFuzzer harness for Marlin's replies: every line a printer (or line noise) can write is parsed without
// crashing, a resend names a line number or none (-1), and a temperature read from it is one a sensor can read.
// Build and run: docs/robustness.md ("Fuzzing").
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "printer/marlin_protocol.h"
#include "printer/plausible_reading.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::size_t start = 0;
  while (start <= bytes.size()) {
    const std::size_t end = std::min(bytes.find('\n', start), bytes.size());
    const auto reply = multidir::hardware::marlin::parseReply(bytes.substr(start, end - start));
    std::string broken;
    if (reply.kind == multidir::hardware::marlin::Reply::Kind::Resend && reply.resendLine < -1)
      broken = "a resend naming a negative line";
    for (const auto& heater : {reply.extruder, reply.bed})
      if (heater && !(multidir::hardware::plausibleCelsius(heater->actualC) &&
                      multidir::hardware::plausibleCelsius(heater->targetC)))
        broken = "a temperature no sensor reads";
    multidir::fuzz::requirePromise(broken, "marlin::parseReply");
    start = end + 1;
  }
  return 0;
}
