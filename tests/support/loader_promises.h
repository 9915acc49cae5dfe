#pragma once
// What loadMesh promises for any input whatever (header-only: shared by the corpus replay test and the
// libFuzzer harness in tests/fuzz/): either a closed, consistently oriented 2-manifold with finite
// coordinates and positive volume, or a refusal that says what is wrong (never Internal, never "please
// report it"). Returns an empty string when the promise holds, else what broke it; `input` as for
// brokenRefusalPromise.
#include <cmath>
#include <limits>
#include <string>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "support/refusal_promise.h"

namespace multidir::test {

inline std::string brokenLoaderPromise(const core::Result<core::LoadedMesh>& loaded, const std::string& input = {}) {
  if (!loaded) return brokenRefusalPromise(loaded.error(), input);
  const core::TriangleMesh& mesh = loaded->mesh;
  if (mesh.triangles.empty()) return "loaded without faces";
  if (mesh.origins.size() != mesh.triangles.size()) return "face origins do not match the faces";
  const double floatMax = static_cast<double>(std::numeric_limits<float>::max());
  for (const core::Vec3& v : mesh.vertices)
    if (!v.allFinite() || v.cwiseAbs().maxCoeff() > floatMax) return "loaded a coordinate that is not finite";
  for (const core::Triangle& t : mesh.triangles) {
    for (std::int32_t v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size()) return "loaded a vertex index out of range";
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "loaded a face with a repeated corner";
  }
  if (!core::edgeCensus(mesh).closedOriented()) return "loaded a mesh that is not a closed, oriented 2-manifold";
  if (!(core::signedVolume(mesh) > 0.0)) return "loaded a mesh whose volume is not positive";
  if (!loaded->report.statistics.closed) return "the report calls the loaded mesh open";
  return {};
}

}  // namespace multidir::test
