#pragma once
// The result of the search: regions in printing order, each with the direction it is printed along.
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/geometry/plane.h"
#include "multidir/core/search/machine.h"
#include "multidir/core/search/search_options.h"

namespace multidir::core {

struct Region {
  TriangleMesh mesh;                 // closed; faces remember their origin (surface or cap of plane k)
  std::optional<Plane> basePlane;    // none for the first region, which stands on the platform
  std::int32_t clippingIndex = -1;   // k of the plane that cut it off (caps of plane k carry index k), -1 first
  Vec3 printingDirection = Vec3::UnitZ();
  MachineAngles angles;
  double volumeMm3 = 0.0;
  double riskyAreaMm2 = 0.0;         // w.r.t. its printing direction; its base (or the platform) is safe
};

struct SearchStatistics {
  long long candidatesScored = 0;    // plane evaluations over all levels and beams
  int candidatesPerLevel = 0;        // planes offered to the first level (normals x offsets)
  int normals = 0;
  int levels = 0;                    // levels the search ran
  int clipsPerformed = 0;
  double seconds = 0.0;
  int threads = 1;
  // Polishing (SearchOptions::polish): the found plan's J_G before it (equal to J_G after when polishing
  // changed nothing; negative when it did not run), the plans it evaluated and its seconds (in `seconds` too).
  double jgBeforePolishMm2 = -1.0;
  int polishEvaluations = 0;
  double polishSeconds = 0.0;
  int proxyFaces = 0;  // faces of the decimated proxy the search ran on (0: it ran on the full mesh)
  // What happened between the proxy and the full mesh: planes polished, replaced or dropped, or why no proxy
  // was used. One sentence each, for the log and the studio.
  std::vector<std::string> notes;
};

struct Decomposition {
  std::vector<Plane> clippingPlanes;  // in clipping order (plane k cut region N-k off)
  std::vector<Region> regions;        // in printing order
  double jgBeforeMm2 = 0.0;           // risky area printing the whole model along up
  double jgAfterMm2 = 0.0;            // sum of the regions' risky areas
  bool cancelled = false;             // the search stopped early: this is the best plan found until then
  Vec3 rotationAxis = Vec3::UnitX();  // 4-DOF: the axis used
  SearchStatistics statistics;
};

}  // namespace multidir::core
