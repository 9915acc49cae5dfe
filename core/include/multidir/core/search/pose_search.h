#pragma once
// Best pose: how the model stands on the platform, chosen together with its decomposition.
//
// A pose is an up direction of the model (MachineSpec::up); plans stay in the model's coordinates. The model
// stands on a patch of its convex hull (contact_patch.h): a pose is tried only when that patch has an area and
// holds the centre of mass (no pose balances on a point or an edge, or tips over). Candidates are the user's
// up (always tried: where the model would not stand in it, the plan says so) and the model's standing poses:
// the largest contacts, then the ones farthest from those taken, so the directions are covered. The user's up gets the full search first; every other pose
// that could beat its plan (its unavoidable risky area is below that plan's J_G) gets a cheap score (the J_G of a
// greedy plan), and the best few of those the full search, each the plain search (decompose) at that pose:
// polished, and on a huge model on the proxy decompose at that up uses; the plan with the least J_G wins (ties:
// fewer regions, then the larger contact area), so the result is never worse than decompose at a given up the
// model stands in.
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::core {

enum class PoseSource { Given, Resting };
const char* poseSourceName(PoseSource source);  // "given", "resting"

struct PoseCandidate {
  Vec3 up = Vec3::UnitZ();         // unit, in the model's coordinates
  PoseSource source = PoseSource::Given;
  double contactAreaMm2 = 0.0;     // area of the hull patch it stands on (0: a point or an edge)
  double stabilityMarginMm = 0.0;  // the centre of mass's projection inside that patch: > 0 inside, else tips
  double riskyAreaMm2 = 0.0;       // single-direction risky area: J_G before for this up
  bool stands() const { return contactAreaMm2 > 0.0 && stabilityMarginMm > 0.0; }
};

struct PoseOptions {
  int poses = 24;             // candidates, the given up included; in [1, 200]
  int fullSearches = 3;       // candidates given the full search, the given up included; in [1, poses]
  double mergeDegrees = 3.0;  // standing poses whose ups are this close are one (the larger contact); [0, 30]
  SearchScheme cheapScheme = SearchScheme::Greedy;  // how the cheap score is found
};

Status validate(const PoseOptions& options);

// The poses a closed model stands in (on a hull face's plane, its centre of mass inside the contact), largest
// contact area first, then larger margin.
// Errors: EmptyMesh, InvalidParameter (a flat or degenerate model).
Result<std::vector<PoseCandidate>> restingPoses(const TriangleMesh& model, double mergeDegrees = 3.0,
                                                const SearchOptions& options = {});

// Candidates in the order they are tried: the given up first (with its contact and margin, whether it stands
// or not), then standing poses (none within a few degrees of an earlier one), at most options.poses of them,
// each with its risky area.
Result<std::vector<PoseCandidate>> candidatePoses(const TriangleMesh& model, const Vec3& givenUp,
                                                  const PoseOptions& poseOptions, const SearchOptions& options = {});

// The rotation that turns the model so that `up` points along `platformUp` (the shortest such rotation).
Eigen::Matrix3d poseRotation(const Vec3& up, const Vec3& platformUp);

// The machine with the pose's up: the 4-DOF axis and forbidden cones turn with it.
MachineSpec machineForPose(const MachineSpec& machine, const Vec3& up);

struct PoseTrial {
  PoseCandidate pose;
  double cheapJgMm2 = 0.0;  // J_G of the cheap (greedy) plan; 0 when not scored
  bool searched = false;    // given the full search
  double jgAfterMm2 = 0.0;  // full search (else the cheap plan's); 0 with no plan (regions 0)
  int regions = 0;          // of its plan; 0: it has none (ruled out, or cancelled before it was scored)
  double seconds = 0.0;
  // Ruled out: the risky area no plan of this pose can avoid is above the given up's plan's J_G, so it could not
  // win and was neither scored nor searched. `unavoidableMm2` is that area as far as it was summed: above the
  // given up's J_G, at most the whole of it; a lower bound on the J_G of every plan of this pose.
  bool ruledOut = false;
  double unavoidableMm2 = 0.0;
};

struct PoseSearchResult {
  Decomposition plan;         // for machineForPose(machine, chosen.up)
  PoseCandidate chosen;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // poseRotation(chosen.up, the given up)
  std::vector<PoseTrial> trials;  // every candidate that stands, in candidate order
  int chosenTrial = 0;
  double seconds = 0.0;
};

// Pose search over the given up and the candidates that stand (a given up that does not is named in
// plan.statistics.notes): the given up's full search first, on every thread; then, threaded across poses, each
// other pose is ruled out when its unavoidable risky area is above the given up's J_G (it could not win), else
// given its cheap score; then the best-scored poses not ruled out get the full search, one thread each. Results,
// and which poses were scored and searched, do not depend on the thread count. Progress: the given up's search,
// the scores, then the other full searches. A cancelled search returns the best plan it has (the given up's best
// so far at least) with plan.cancelled set.
Result<PoseSearchResult> decomposeWithPoseSearch(const TriangleMesh& model, const MachineSpec& machine,
                                                 const SearchOptions& options, const PoseOptions& poseOptions,
                                                 JobContext& job);

}  // namespace multidir::core
