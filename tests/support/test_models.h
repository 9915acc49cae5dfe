#pragma once
// Where tests find the shared real meshes, and helpers that read them.
#include <string>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::test {

// Absolute path of a file in ../shared/models (e.g. "kitten.off", "defective/halftunnel-open.off").
std::string sharedModelPath(const std::string& name);

// Loads a model of ../shared/models with core::loadMesh; throws std::runtime_error with core's description
// when it cannot (a test then fails with that message).
core::TriangleMesh loadSharedModel(const std::string& name);

// The closed, consistently oriented real models listed in ../shared/models/README.md.
const std::vector<std::string>& closedSharedModels();

// A fresh folder under the build tree for files a test writes; removed and recreated on each call.
std::string scratchDirectory(const std::string& testName);

}  // namespace multidir::test
