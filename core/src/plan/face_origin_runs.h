#pragma once
// FaceOrigin lists as compact text, because STL cannot carry them. Clipping keeps faces in their order and
// appends each cap's faces together, so a region's origins are long runs:
//   "s0+1200"   surface faces 0, 1, ..., 1199 (one each)
//   "s57*2"     surface face 57 twice (a face split by a plane)
//   "c1*34"     34 faces of the cap of clipping plane 1
//   "s8"        surface face 8 once ("c3": one face of cap 3)
// Runs are separated by single spaces, in face order.
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

std::string encodeFaceOrigins(const std::vector<FaceOrigin>& origins);

// Decodes text from encodeFaceOrigins, refusing more than `maxFaces` faces (so a lying file cannot make it
// allocate without bound). Errors: MalformedFile, the message naming the run ("run 3 ('x2') ...").
Result<std::vector<FaceOrigin>> decodeFaceOrigins(const std::string& text, std::size_t maxFaces);

}  // namespace multidir::core::detail
