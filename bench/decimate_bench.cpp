// Times the proxy's decimation on its own (the proxy search's first step):
//
//   multidir_decimate_bench MODEL FACES [TOLERANCE_MM]   e.g. multidir_decimate_bench /tmp/kitten-64x.stl 50000 0.01
//
// MODEL is a name in ../shared/models (without .off) or a path. Prints the seconds to load, to decimate, the
// faces left and the volume change.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "shared_model_path.h"

using namespace multidir::core;

namespace {
double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: multidir_decimate_bench MODEL FACES [TOLERANCE_MM]\n");
    return 2;
  }
  std::string path = argv[1];
  path = multidir::bench::sharedModelPath(path);
  const auto loadStart = std::chrono::steady_clock::now();
  const auto loaded = loadMesh(path);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s\n", loaded.error().describe().c_str());
    return 1;
  }
  const double loadSeconds = secondsSince(loadStart);
  const auto start = std::chrono::steady_clock::now();
  const auto proxy = decimated(loaded->mesh, static_cast<std::size_t>(std::atol(argv[2])), argc == 4 ? std::atof(argv[3]) : 0.0);
  const double seconds = secondsSince(start);
  if (!proxy.ok()) {
    std::fprintf(stderr, "%s\n", proxy.error().describe().c_str());
    return 1;
  }
  std::printf("%zu faces: loaded in %.2f s, decimated to %zu faces in %.2f s, volume change %.4f %%\n",
              loaded->mesh.faceCount(), loadSeconds, proxy->mesh.faceCount(), seconds, proxy->volumeChangePercent);
  return 0;
}
