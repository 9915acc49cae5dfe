#pragma once
// The state of one beam: what is left of the model after a list of cuts, and how the list was made.
// Nodes are immutable once built and shared by their children through `parent`, so a list of planes costs
// one link per level (the paper's backward link).
#include <memory>
#include <vector>

#include "multidir/core/geometry/plane.h"
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/plane_sweep.h"

namespace multidir::core::detail {

// The sweep of one lattice normal through a node's remaining part.
struct NormalSweep {
  OffsetGrid grid;
  SweepProfile profile;
};

struct SearchNode {
  std::shared_ptr<const TriangleMesh> remaining;  // the part still to be cut (printed along up at the end)
  std::vector<double> riskyUpShare;                // per face of `remaining`: share of its area risky along up
  double riskyUpAreaMm2 = 0.0;
  double volumeMm3 = 0.0;

  std::shared_ptr<const SearchNode> parent;       // null at the root (the uncut model)
  Plane plane;                                    // the cut that made this node from its parent
  std::shared_ptr<const TriangleMesh> region;     // the part above that cut, printed along plane.normal
  double prefixJgMm2 = 0.0;                       // risky area of every region cut off so far
  int level = 0;                                  // number of cuts

  // How `remaining` differs from the parent's: the parent's faces it lost (cut off, split, or moved onto the
  // plane) and its own faces that are not unchanged copies of the parent's (pieces and the cap). Every sum
  // over faces of this node is the parent's minus the first plus the second.
  std::vector<std::int32_t> removedParentFaces;
  std::vector<std::int32_t> addedFaces;
  // The sweeps of every lattice normal once this node was scored, for scoring its children cheaply; the
  // search drops them when no child needs them any more. Not part of the node's value.
  mutable std::shared_ptr<const std::vector<NormalSweep>> latticeSweeps;

  // J_G of the plan that stops here: the regions cut off plus the remaining part printed along up.
  double jg() const { return prefixJgMm2 + riskyUpAreaMm2; }
};

// One candidate plane scored on one beam without clipping.
struct ScoredCandidate {
  int beam = 0;
  int normal = 0;
  double offsetMm = 0.0;
  double riskyAboveMm2 = 0.0;    // R(M+, plane): risky along the plane's normal
  double riskyUpAboveMm2 = 0.0;  // risky along up among the faces above: what the cut saves
  double volumeAboveMm3 = 0.0;
  double jgMm2 = 0.0;            // J_G of the plan that makes this cut and stops
  double localGainMm2() const { return riskyUpAboveMm2 - riskyAboveMm2; }  // J_L
};

}  // namespace multidir::core::detail
