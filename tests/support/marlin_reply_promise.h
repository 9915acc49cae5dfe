#pragma once
// What Marlin's reply parser promises for any line a printer (or line noise) can write (header-only: shared by
// the corpus replay test and the libFuzzer harness): it parses without crashing, a resend names a line or none
// (-1), and a temperature read from the line is one a sensor can read. Returns an empty string when the promise
// holds, else what broke it.
#include <string>

#include "printer/marlin_protocol.h"
#include "printer/plausible_reading.h"

namespace multidir::test {

inline std::string brokenMarlinReplyPromise(const std::string& line) {
  const hardware::marlin::Reply reply = hardware::marlin::parseReply(line);
  if (reply.kind == hardware::marlin::Reply::Kind::Resend && reply.resendLine < -1)
    return "a resend naming a negative line";
  for (const auto& heater : {reply.extruder, reply.bed})
    if (heater && !(hardware::plausibleCelsius(heater->actualC) && hardware::plausibleCelsius(heater->targetC)))
      return "a temperature no sensor reads";
  return {};
}

}  // namespace multidir::test
