// libFuzzer harness for project files (.multidir): loadProject must refuse any input clearly
// (tests/support/refusal_promise.h) or load a project whose machine passes validate().
// Build and run: docs/robustness.md ("Fuzzing").
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "multidir/core/plan/project_file.h"
#include "multidir/core/search/machine.h"
#include "support/refusal_promise.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = multidir::fuzz::scratchStem() + ".multidir";
  multidir::fuzz::writeInput(path, data, size);
  const auto loaded = multidir::core::loadProject(path);
  std::remove(path.c_str());
  std::string broken = multidir::test::brokenRefusalPromise(loaded, multidir::fuzz::inputText(data, size));
  if (loaded && !multidir::core::validate(loaded->machine)) broken = "loaded a machine that validate() refuses";
  multidir::fuzz::requirePromise(broken, "loadProject");
  return 0;
}
