// libFuzzer harness for the mesh loaders: every input is written to a file and loaded as .stl, .obj, .off
// and .ply in turn, and each load must keep loadMesh's promise (tests/support/loader_promises.h): a sound
// solid or a clear refusal. A broken promise aborts, so libFuzzer keeps the input.
// Build and run: see docs/testing.md ("Fuzzing the loaders").
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "multidir/core/mesh/mesh_io.h"
#include "support/loader_promises.h"

namespace {

const std::string& scratchStem() {
  static const std::string stem = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp && *tmp ? tmp : "/tmp") + "/multidir-fuzz-" + std::to_string(::getpid());
  }();
  return stem;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  multidir::core::LoadOptions options;
  options.maxTriangles = 200'000;  // keeps each run fast; the limits themselves are part of the promise
  for (const char* extension : {"stl", "obj", "off", "ply"}) {
    const std::string path = scratchStem() + "." + extension;
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    const std::string broken = multidir::test::brokenLoaderPromise(multidir::core::loadMesh(path, options));
    std::remove(path.c_str());
    if (!broken.empty()) {
      std::fprintf(stderr, "loadMesh broke its promise as .%s: %s\n", extension, broken.c_str());
      std::abort();
    }
  }
  return 0;
}
