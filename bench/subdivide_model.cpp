// Writes a shared model subdivided K times (4^K as many faces, the same surface) for the scaling runs:
//
//   multidir_subdivide_model MODEL K OUT.stl [NOISE_MM]   e.g. multidir_subdivide_model fandisk 3 /tmp/fandisk-64x.stl
//
// NOISE_MM moves every vertex along its normal by a pseudo-random amount in [-NOISE_MM, NOISE_MM] (the same
// for every run), like a scan's measurement noise: then no collapse of the extra faces is free, and a
// decimated proxy keeps as many faces as it is allowed.
// MODEL is a name in ../shared/models (without .off) or a path.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "noisy_surface.h"
#include "shared_model_path.h"

using namespace multidir::core;


int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: multidir_subdivide_model MODEL LEVELS OUT [NOISE_MM]\n");
    return 2;
  }
  std::string path = argv[1];
  path = multidir::bench::sharedModelPath(path);
  const auto loaded = loadMesh(path);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s\n", loaded.error().describe().c_str());
    return 1;
  }
  auto fine = subdivided(loaded->mesh, std::atoi(argv[2]));
  if (!fine.ok()) {
    std::fprintf(stderr, "%s\n", fine.error().describe().c_str());
    return 1;
  }
  if (argc == 5) multidir::bench::addNoise(*fine, std::atof(argv[4]));
  if (const Status saved = saveMesh(*fine, argv[3]); !saved.ok()) {
    std::fprintf(stderr, "%s\n", saved.error().describe().c_str());
    return 1;
  }
  std::printf("%s: %zu faces\n", argv[3], fine->faceCount());
  return 0;
}
