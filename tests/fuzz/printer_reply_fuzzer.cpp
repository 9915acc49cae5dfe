// libFuzzer harness for the HTTP printers' replies: each input is parsed as a reply (depth-bounded, as the
// links parse) and read as Moonraker's status and OctoPrint's job and printer replies. None may crash; a
// refusal says what; a reading has a progress in [0, 1] and temperatures a sensor can read.
// Build and run: docs/robustness.md ("Fuzzing").
#include <cstdint>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "support/printer_reply_promise.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  multidir::fuzz::requirePromise(multidir::test::brokenPrinterReplyPromise(text), "printer reply readers");
  return 0;
}
