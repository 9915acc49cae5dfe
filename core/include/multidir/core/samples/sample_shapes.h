#pragma once
// The generators behind makeSample(), one per sample. The rest of the app should use catalogue() and
// makeSample(); these are public so tests can compare a sample with what it is designed to be.
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/samples/revolve.h"

namespace multidir::core::samples {

// Three smoothly joined spheres with two arms and a nose, about 150 mm tall, flattened at the bottom.
Result<TriangleMesh> makeSnowman();

// The (r, z) profile of the mushroom, as revolveProfile() takes it: a flared stem under a wide cap.
std::vector<Vec2> mushroomProfile();
// The mushroom profile revolved around +Z, 100 mm tall.
Result<TriangleMesh> makeMushroom();

// A mug with a rounded rim and a D-shaped handle (genus 1), about 80 mm tall.
Result<TriangleMesh> makeMug();

}  // namespace multidir::core::samples
