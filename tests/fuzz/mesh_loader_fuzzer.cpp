// libFuzzer harness for the mesh loaders: every input is written to a file and loaded as .stl, .obj, .off
// and .ply in turn, and each load must keep loadMesh's promise (tests/support/loader_promises.h): a sound
// solid or a clear refusal. A broken promise aborts, so libFuzzer keeps the input.
// Build and run: docs/robustness.md ("Fuzzing").
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "multidir/core/mesh/mesh_io.h"
#include "support/loader_promises.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  multidir::core::LoadOptions options;
  options.maxTriangles = 200'000;  // keeps each run fast; the limits themselves are part of the promise
  for (const char* extension : {"stl", "obj", "off", "ply"}) {
    const std::string path = multidir::fuzz::scratchStem() + "." + extension;
    multidir::fuzz::writeInput(path, data, size);
    const std::string broken = multidir::test::brokenLoaderPromise(multidir::core::loadMesh(path, options),
                                                                   multidir::fuzz::inputText(data, size));
    std::remove(path.c_str());
    multidir::fuzz::requirePromise(broken, (std::string("loadMesh as .") + extension).c_str());
  }
  return 0;
}
