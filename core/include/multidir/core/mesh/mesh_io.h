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

// Counts and measures of a mesh. genus is the sum over shells of (2 - chi)/2 when the mesh is closed, else 0.
MeshStatistics computeStatistics(const TriangleMesh& mesh);

// One kind of defect found on load, with how many and the first few indices (faces or vertices).
struct MeshDefect {
  std::string kind;                 // stable name: "duplicate-vertices", "degenerate-faces", "open-boundary", ...
  std::size_t count = 0;
  std::vector<std::int64_t> firstIndices;  // at most a handful
  std::string description;          // a sentence for a person
  bool repaired = false;            // true when load repaired it (then `repairs` says how)
  // false for facts that are reported but need no repair ("several-shells", "unused-vertices").
  bool needsRepair = true;
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
  // loadMesh multiplies every coordinate by this before the checks, for a model saved in other units
  // (0.001: micrometres, 25.4: inches, 10: centimetres). From 1e-6 to 1e6, else InvalidParameter.
  double scale = 1.0;
};

struct LoadedMesh {
  TriangleMesh mesh;  // closed, oriented, positive volume; origins reset to Surface(index)
  MeshReport report;
};

// Loads a mesh file, checks it and repairs what is safe to repair. Errors name the defect, how many,
// the first few indices and the file: FileNotFound, UnsupportedFormat, MalformedFile, TooLarge, EmptyMesh,
// NonFiniteVertex, NotManifold, OpenBoundary, InconsistentOrientation.
// Files are checked for structure before they are read (lying counts, truncation, indices out of range),
// so bad input costs at most one pass over the file and memory in proportion to what it really holds.
// Every format is read by MultiDir's own readers (STL ASCII or binary, told apart by size, not by the word
// "solid"), which parse every number strictly: plain decimal notation, finite as a double and as a float
// (|x| <= 3.4e38); "1e39", "0x10", "nan" or "inf" as a coordinate or index is refused naming the line.
// Text coordinates keep full double precision. Thread-safety: loads on different threads are independent.
Result<LoadedMesh> loadMesh(const std::string& path, const LoadOptions& options = {});

// A polygon soup as a file holds it: vertices and triangles (polygons already fanned into triangles),
// before any check. Indices may be out of range, faces degenerate, vertices duplicated.
struct RawSoup {
  std::vector<Vec3> vertices;       // mm
  std::vector<Triangle> triangles;  // indices into vertices, as read
  std::size_t droppedByReader = 0;  // polygons with fewer than three corners, left out: degenerate
};

// The checks and repairs loadMesh runs after reading, for a soup built in memory. `sourceName` is put in
// front of messages ("kitten.off"). Repairs, in this order: weld vertices closer than weldToleranceMm, drop
// degenerate faces (area below degenerateAreaMm2) and duplicate faces, orient each shell consistently, flip
// shells that face inward (a shell nested inside an odd number of others is a cavity and must face inward).
// With options.repair == false each of these is an error instead: duplicate vertices OpenBoundary (the
// faces do not connect), degenerate or duplicate faces NotManifold, orientation and inside-out shells
// InconsistentOrientation. Several shells and unused vertices are reported but are no defect. Refused
// whatever the options: shells that cross each other (neither inside nor outside the other, decided by up
// to 16 probes each: NotManifold) and shells that enclose no volume (flat: EmptyMesh). Errors as loadMesh,
// plus MalformedFile for an index out of range and InvalidParameter for negative tolerances.
// Cost: about linear in the size of the soup; with 2 to 64 shells, nesting adds up to 16 x shells x faces
// work (only for shells whose bounding boxes overlap).
Result<LoadedMesh> checkAndRepair(const RawSoup& soup, const LoadOptions& options = {},
                                  const std::string& sourceName = "mesh");

struct SaveOptions {
  bool asciiStl = false;  // .stl only: write ASCII instead of binary
};

// Saves a mesh; the format follows the extension (.stl binary unless options.asciiStl, .obj, .off, .ply,
// all text but binary STL). Text formats keep every double exactly (17 significant digits); binary STL is
// float by definition. The file is written beside the target and renamed into place, so a failed save
// leaves no half-written file. Errors: UnsupportedFormat, WriteFailed, InvalidParameter (index out of range).
Status saveMesh(const TriangleMesh& mesh, const std::string& path, const SaveOptions& options = {});

}  // namespace multidir::core
