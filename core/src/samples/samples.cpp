#include "multidir/core/samples/samples.h"

#include <algorithm>
#include <limits>
#include <string>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/samples/sample_shapes.h"

namespace multidir::core::samples {
namespace {

// Moves the mesh along Z so its lowest vertex is exactly at z = 0.
void placeOnPlatform(TriangleMesh& mesh) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& v : mesh.vertices) lowest = std::min(lowest, v.z());
  for (Vec3& v : mesh.vertices) v.z() -= lowest;
}

// The generators are built to give closed, outward-facing solids; if one ever does not, that is a bug
// here, not something the user can fix, so say so instead of handing on a broken model.
Status checkSolid(const TriangleMesh& mesh, const std::string& id) {
  const EdgeCensus census = edgeCensus(mesh);
  if (!census.closedOriented() || !(signedVolume(mesh) > 0.0))
    return Error{ErrorCode::Internal,
                 "the generated sample is not a closed, outward-facing solid (" + std::to_string(census.boundary) +
                     " open, " + std::to_string(census.nonManifold) + " non-manifold, " +
                     std::to_string(census.misoriented) + " misoriented edges); please report this",
                 "sample " + id};
  return Done{};
}

Result<TriangleMesh> generate(const std::string& id) {
  if (id == "snowman") return makeSnowman();
  if (id == "mushroom") return makeMushroom();
  if (id == "mug") return makeMug();
  std::string known;
  for (const SampleInfo& info : catalogue()) known += (known.empty() ? "" : ", ") + info.id;
  return Error{ErrorCode::InvalidParameter, "there is no sample called '" + id + "'; the samples are " + known,
               "sample"};
}

}  // namespace

const std::vector<SampleInfo>& catalogue() {
  static const std::vector<SampleInfo> kCatalogue = {
      {"snowman", "Snowman",
       "Three stacked spheres with arms and a nose: the arms' undersides and the lower half of each ball overhang."},
      {"mushroom", "Mushroom", "A stem under a wide cap: the cap's nearly flat underside overhangs all around."},
      {"mug", "Mug", "A cup with a D-shaped handle: the handle's lower arc and the underside of its top overhang."},
  };
  return kCatalogue;
}

Result<TriangleMesh> makeSample(const std::string& id) {
  Result<TriangleMesh> mesh = generate(id);
  if (!mesh) return mesh.error();
  placeOnPlatform(mesh.value());
  if (Status s = checkSolid(mesh.value(), id); !s) return s.error();
  return mesh;
}

}  // namespace multidir::core::samples
