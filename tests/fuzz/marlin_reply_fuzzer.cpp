// libFuzzer harness for Marlin's replies: every line of the input keeps the parser's promise
// (tests/support/marlin_reply_promise.h). Build and run: docs/robustness.md ("Fuzzing").
#include <algorithm>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "support/marlin_reply_promise.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes = multidir::fuzz::inputText(data, size);
  std::size_t start = 0;
  while (start <= bytes.size()) {
    const std::size_t end = std::min(bytes.find('\n', start), bytes.size());
    multidir::fuzz::requirePromise(multidir::test::brokenMarlinReplyPromise(bytes.substr(start, end - start)),
                                   "marlin::parseReply");
    start = end + 1;
  }
  return 0;
}
