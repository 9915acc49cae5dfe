// libFuzzer harness for plan.json: the input becomes the plan.json of a scratch plan folder (with no region
// files) and loadPlan must refuse it clearly (tests/support/refusal_promise.h) or load a plan whose regions
// and supports agree in number. Build and run: docs/robustness.md ("Fuzzing").
#include <cstdint>
#include <filesystem>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "multidir/core/plan/plan_file.h"
#include "support/refusal_promise.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string folder = [] {
    const std::string path = multidir::fuzz::scratchStem() + "-plan";
    std::filesystem::create_directories(path);
    return path;
  }();
  multidir::fuzz::writeInput(folder + "/plan.json", data, size);
  const auto loaded = multidir::core::loadPlan(folder);
  std::string broken = multidir::test::brokenRefusalPromise(loaded, multidir::fuzz::inputText(data, size));
  if (loaded && !loaded->supports.empty() && loaded->supports.size() != loaded->decomposition.regions.size())
    broken = "loaded a plan whose support sets do not match its regions";
  multidir::fuzz::requirePromise(broken, "loadPlan");
  return 0;
}
