#pragma once
// Loading and saving meshes (STL ASCII/binary, OBJ, OFF, PLY), with checks and safe repairs on load.
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

struct MeshStatistics {
  std::size_t triangles = 0;
  std::size_t vertices = 0;
  std::size_t shells = 0;     // connected components
  long long genus = 0;        // total over shells, from the Euler characteristic of a closed surface
  BoundingBox bounds;         // mm
  double areaMm2 = 0.0;
  double volumeMm3 = 0.0;
  bool closed = false;        // every edge has two faces, consistently oriented, manifold vertices
};

MeshStatistics computeStatistics(const TriangleMesh& mesh);

// One kind of defect found on load, with how many and the first few indices (faces or vertices).
struct MeshDefect {
  std::string kind;                 // stable name: "duplicate-vertices", "degenerate-faces", "open-boundary", ...
  std::size_t count = 0;
  std::vector<std::int64_t> firstIndices;  // at most a handful
  std::string description;          // a sentence for a person
  bool repaired = false;            // true when load repaired it (then `repairs` says how)
};

struct MeshReport {
  std::vector<MeshDefect> defects;
  std::vector<std::string> repairs;  // sentences: "merged 1,204 duplicate vertices"
  MeshStatistics statistics;
};

struct LoadOptions {
  double weldToleranceMm = kDefaultWeldToleranceMm;
  double degenerateAreaMm2 = kDefaultDegenerateAreaMm2;
  std::size_t maxTriangles = 50'000'000;  // larger inputs are refused with TooLarge
  bool repair = true;                     // false: any defect is an error
};

struct LoadedMesh {
  TriangleMesh mesh;  // closed, oriented, positive volume; origins reset to Surface(index)
  MeshReport report;
};

// Loads a mesh file, checks it and repairs what is safe to repair. Errors name the defect, how many,
// the first few indices and the file: FileNotFound, UnsupportedFormat, MalformedFile, TooLarge, EmptyMesh,
// NonFiniteVertex, NotManifold, OpenBoundary, InconsistentOrientation.
Result<LoadedMesh> loadMesh(const std::string& path, const LoadOptions& options = {});

// Saves a mesh; the format follows the extension (.stl binary, .obj, .off, .ply). Errors: UnsupportedFormat, WriteFailed.
Status saveMesh(const TriangleMesh& mesh, const std::string& path);

}  // namespace multidir::core
