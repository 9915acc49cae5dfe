// libFuzzer harness for machine profiles (multidir-machine JSON): loadMachineProfile must refuse any input
// clearly (tests/support/refusal_promise.h) or load a machine that validate() accepts.
// Build and run: docs/robustness.md ("Fuzzing").
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/machine.h"
#include "support/refusal_promise.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = multidir::fuzz::scratchStem() + "-machine.json";
  multidir::fuzz::writeInput(path, data, size);
  const auto loaded = multidir::core::loadMachineProfile(path);
  std::remove(path.c_str());
  std::string broken = multidir::test::brokenRefusalPromise(loaded, multidir::fuzz::inputText(data, size));
  if (loaded && !multidir::core::validate(*loaded)) broken = "loaded a machine that validate() refuses";
  multidir::fuzz::requirePromise(broken, "loadMachineProfile");
  return 0;
}
