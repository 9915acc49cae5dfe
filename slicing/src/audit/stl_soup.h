#pragma once
// An STL file read as it is: triangles with their corners, nothing welded, repaired or refused for crossing
// shells (a step's supports are struts that overlap one another and the region).
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::slicing::audit {

// Binary (told by its size: 84 + 50 x count bytes) or ASCII STL. Every triangle gets three vertices of its
// own. Errors: FileNotFound, MalformedFile (a count the size disagrees with, a coordinate that is not a
// finite number, no triangles).
core::Result<core::TriangleMesh> readStlSoup(const std::string& path);

}  // namespace multidir::slicing::audit
