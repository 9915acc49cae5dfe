#pragma once
// Candidate clipping planes (the paper's Section III-B): normals sampled uniformly on the Gaussian sphere and
// kept where the machine can print along them, and offsets every stepMm across the solid along each normal,
// minus those that would cut the platform region (Criterion III).
#include <algorithm>
#include <limits>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/geometry/plane.h"
#include "multidir/core/search/machine.h"
#include "multidir/core/search/plane_sweep.h"

namespace multidir::core {

// `count` nearly uniform unit vectors on the sphere (a Fibonacci lattice), deterministic.
std::vector<Vec3> fibonacciSphere(int count);

struct CandidateOptions {
  int normalSamples = 250;     // on the whole sphere, before the machine's limits (5-DOF); >= 1
  double offsetStepMm = 1.0;   // > 0
  // 4-DOF: angle between neighbouring candidate normals on the circle, rounded to whole stepper steps. The
  // 5-DOF lattice of 250 normals is about 12.8 degrees apart; 3 degrees on the circle found the same plans
  // as every 1-degree step on the kitten at a third of the cost.
  double rotarySpacingDegrees = 3.0;
  double platformClearanceMm = 0.0;  // planes must pass at least this far above P
};

Status validate(const CandidateOptions& options);

// The printing directions the search may use: 3-DOF: up; 4-DOF: up turned about r by the realizable angles
// that are multiples of the spacing (0 excluded: that is the platform's own direction); 5-DOF: the lattice points within the tilt limit and
// outside forbidden cones, up excluded.
std::vector<Vec3> candidateNormals(const MachineSpec& machine, const CandidateOptions& options);

// The typical angle between neighbouring normals of candidateNormals (radians): sqrt(4 pi / samples) on the
// 5-DOF lattice, the step between used stepper angles for 4-DOF, 0 for 3-DOF.
double normalSpacingRadians(const MachineSpec& machine, const CandidateOptions& options);

// Realizable normals about `radiusRadians` away from `normal`, to refine a promising candidate between the
// lattice points: 5-DOF six directions on a cone around it (turned by `turnRadians` about it); 4-DOF the
// stepper angles nearest to +-radius from its angle (none when the radius is below one step); 3-DOF none.
std::vector<Vec3> neighbourNormals(const MachineSpec& machine, const Vec3& normal, double radiusRadians,
                                   double turnRadians = 0.0);

// Criterion III: whether the platform region P lies wholly below `plane` (at least clearanceMm below).
bool planeClearsPlatform(const Plane& plane, const PlatformRegion& platform, const Vec3& up, double clearanceMm = 0.0);

// The most offsets one normal may have (20 m across at the default 1 mm step: no printer is that large), and
// the most candidate planes one level of the search may score (normals x offsets, about 64 bytes each while a
// level is ranked).
constexpr long long kMaxOffsetsPerNormal = 20'000;
constexpr long long kMaxCandidatesPerLevel = 50'000'000;

// Refuses, before anything is allocated, a search that needs more offsets per normal (the model's
// bounding-box diagonal over the offset step) or more candidates per level than the bounds above: the usual
// cause is a model in the wrong units (micrometres read as millimetres are 1000 times too wide), so the
// message gives the model's width in metres and suggests --scale, a larger offset step or fewer normals.
// Errors: InvalidParameter (where: "model").
Status checkCandidateCount(const TriangleMesh& model, const MachineSpec& machine, const CandidateOptions& options);

// Offsets along one normal for a solid: every stepMm from just above the lowest allowed offset to below the
// solid's top, where the lowest allowed offset keeps the platform region P wholly below (Criterion III).
// At most kMaxCandidatesPerLevel offsets (checkCandidateCount refuses models that need more), so the count
// never overflows whatever the model's size.
OffsetGrid candidateOffsets(const TriangleMesh& solid, const Vec3& normal, const PlatformRegion& platform,
                            const Vec3& up, const CandidateOptions& options);
// The same without a platform region (the apart machine: Criterion III does not apply), from just above the
// solid's lowest point along the normal.
OffsetGrid candidateOffsets(const TriangleMesh& solid, const Vec3& normal, const CandidateOptions& options);

// A solid's extent along a normal: its vertices' lowest and highest level (normal . v); empty (low above
// high) for a solid without vertices.
struct LevelRange {
  double lowMm = std::numeric_limits<double>::infinity();
  double highMm = -std::numeric_limits<double>::infinity();
  void include(double level) {
    lowMm = std::min(lowMm, level);
    highMm = std::max(highMm, level);
  }
};
LevelRange levelRange(const TriangleMesh& solid, const Vec3& normal);
// candidateOffsets() from the solid's extent along the normal, for a caller that has it already (the search
// reads each vertex's level once per normal for both the grid and the sweep).
OffsetGrid candidateOffsets(const LevelRange& range, const Vec3& normal, const PlatformRegion& platform,
                            const Vec3& up, const CandidateOptions& options);
OffsetGrid candidateOffsets(const LevelRange& range, const CandidateOptions& options);

}  // namespace multidir::core
