// Times checkAndRepair on a double cone: two cones apex to apex, so one vertex carries every side face
// (a non-manifold vertex with half of all faces). The check that names such vertices used to walk each
// vertex's fan pairwise (quadratic: 46 s at 128k faces); it must stay linear.
// Usage: multidir_mesh_check_bench [segments per cone, default 32768 -> 131,072 faces]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_io.h"

namespace core = multidir::core;

namespace {

core::RawSoup doubleCone(int segments) {
  core::RawSoup soup;
  soup.vertices.push_back(core::Vec3::Zero());
  for (int cone = 0; cone < 2; ++cone) {
    const double z = cone == 0 ? 10.0 : -10.0;
    const auto centre = static_cast<std::int32_t>(soup.vertices.size());
    soup.vertices.emplace_back(0.0, 0.0, z);
    const auto ring = static_cast<std::int32_t>(soup.vertices.size());
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * core::kPi * i / segments;
      soup.vertices.emplace_back(5.0 * std::cos(a), 5.0 * std::sin(a), z);
    }
    for (int i = 0; i < segments; ++i) {
      const std::int32_t p = ring + i, q = ring + (i + 1) % segments;
      soup.triangles.push_back({0, q, p});
      soup.triangles.push_back({centre, p, q});
    }
  }
  return soup;
}

}  // namespace

int main(int argc, char** argv) {
  const int segments = argc > 1 ? std::atoi(argv[1]) : 32768;
  if (segments < 3 || segments > 4'000'000) {
    std::fprintf(stderr, "segments must be from 3 to 4000000\n");
    return 2;
  }
  const core::RawSoup soup = doubleCone(segments);
  const auto start = std::chrono::steady_clock::now();
  const core::Result<core::LoadedMesh> checked = core::checkAndRepair(soup);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("double cone, %d segments per cone, %zu faces: checkAndRepair %.3f s (%s)\n", segments,
              soup.triangles.size(), seconds,
              checked ? "accepted" : core::errorCodeName(checked.error().code));
  return 0;
}
