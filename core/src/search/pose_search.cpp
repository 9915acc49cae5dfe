#include "multidir/core/search/pose_search.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "detail/parallel.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/convex_hull.h"
#include "multidir/core/search/candidate_planes.h"
#include "search/run_decomposition.h"

namespace multidir::core {
namespace {

// Two ups closer than this are one pose: the search would cut them alike.
constexpr double kDistinctDegrees = 5.0;

Error outOfRange(const std::string& what, const std::string& range) {
  return Error{ErrorCode::InvalidParameter, what + " " + range, "pose search"};
}

// Centre of mass of a closed solid (signed tetrahedra from the origin).
Vec3 centreOfMass(const TriangleMesh& model) {
  Vec3 sum = Vec3::Zero();
  double volume = 0;
  for (std::size_t f = 0; f < model.faceCount(); ++f) {
    const Vec3& a = model.corner(f, 0);
    const Vec3& b = model.corner(f, 1);
    const Vec3& c = model.corner(f, 2);
    const double v = a.dot(b.cross(c)) / 6.0;
    volume += v;
    sum += v * (a + b + c) / 4.0;
  }
  return volume != 0 ? Vec3(sum / volume) : Vec3::Zero();
}

// Signed distance of p (on the facet's plane) inside the facet's convex outline: > 0 inside.
double marginInside(const HullFacet& facet, const Vec3& p) {
  const std::size_t n = facet.polygon.size();
  if (n < 3) return -1.0;
  double margin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = facet.polygon[i];
    const Vec3& b = facet.polygon[(i + 1) % n];
    const Vec3 inward = facet.normal.cross(b - a);  // CCW seen from outside: n x edge points inside
    if (inward.norm() <= 0) continue;
    margin = std::min(margin, inward.normalized().dot(p - a));
  }
  return margin;
}

bool closeToAny(const std::vector<PoseCandidate>& poses, const Vec3& up) {
  const double cosDistinct = std::cos(kDistinctDegrees * kPi / 180.0);
  return std::any_of(poses.begin(), poses.end(), [&](const PoseCandidate& p) { return p.up.dot(up) > cosDistinct; });
}

double riskyAreaFor(const TriangleMesh& model, const Vec3& up, const SearchOptions& options) {
  OverhangOptions o;
  o.alphaMaxDegrees = options.alphaMaxDegrees;
  o.supportedBandMm = options.supportedBandMm;
  o.base = RegionBase::Platform;
  const auto analysis = analyzeOverhang(model, up, o);
  return analysis.ok() ? analysis->riskyAreaMm2 : 0.0;
}

// The better of two finished searches: least J_G, then fewer regions, then larger contact, then earlier.
bool better(const PoseTrial& a, const PoseTrial& b) {
  constexpr double kTie = 1e-6;  // mm^2
  if (a.jgAfterMm2 < b.jgAfterMm2 - kTie) return true;
  if (a.jgAfterMm2 > b.jgAfterMm2 + kTie) return false;
  if (a.regions != b.regions) return a.regions < b.regions;
  return a.pose.contactAreaMm2 > b.pose.contactAreaMm2 + kTie;
}

}  // namespace

const char* poseSourceName(PoseSource source) {
  switch (source) {
    case PoseSource::Given: return "given";
    case PoseSource::Resting: return "resting";
    case PoseSource::Sampled: return "sampled";
  }
  return "given";
}

Status validate(const PoseOptions& options) {
  if (options.poses < 1 || options.poses > 200) return outOfRange("the number of poses", "must be between 1 and 200");
  if (options.fullSearches < 1 || options.fullSearches > options.poses)
    return outOfRange("the number of fully searched poses", "must be between 1 and the number of poses");
  if (!(options.mergeDegrees >= 0 && options.mergeDegrees <= 30))
    return outOfRange("the facet merge angle", "must be between 0 and 30 degrees");
  return Done{};
}

Result<std::vector<PoseCandidate>> restingPoses(const TriangleMesh& model, double mergeDegrees,
                                                const SearchOptions& options) {
  if (model.empty()) return Error{ErrorCode::EmptyMesh, "the model has no faces: load a closed mesh first", "model"};
  std::vector<Vec3> used;
  std::vector<char> seen(model.vertexCount(), 0);
  for (const Triangle& t : model.triangles)
    for (std::int32_t v : t)
      if (!seen[v]) seen[v] = 1, used.push_back(model.vertices[v]);
  auto hull = convexHull(used);
  if (!hull.ok()) return hull.error();
  const Vec3 centre = centreOfMass(model);
  std::vector<PoseCandidate> poses;
  const std::vector<HullFacet> facets = mergedFacets(*hull, mergeDegrees);
  double hullArea = 0;
  for (const HullFacet& facet : facets) hullArea += facet.areaMm2;
  for (const HullFacet& facet : facets) {
    // Slivers along hull edges (near-collinear corners) have normals that rounding decides: no pose.
    if (facet.polygon.size() < 3 || facet.areaMm2 < 1e-6 * hullArea) continue;
    const Vec3 onPlane = centre - facet.normal * facet.normal.dot(centre - facet.polygon.front());
    const double margin = marginInside(facet, onPlane);
    if (!(margin > 0)) continue;
    PoseCandidate pose;
    pose.up = -facet.normal;
    pose.source = PoseSource::Resting;
    pose.contactAreaMm2 = facet.areaMm2;
    pose.stabilityMarginMm = margin;
    pose.riskyAreaMm2 = riskyAreaFor(model, pose.up, options);
    poses.push_back(pose);
  }
  std::stable_sort(poses.begin(), poses.end(), [](const PoseCandidate& a, const PoseCandidate& b) {
    constexpr double kTie = 1e-6;
    if (std::abs(a.contactAreaMm2 - b.contactAreaMm2) > kTie * std::max(1.0, a.contactAreaMm2))
      return a.contactAreaMm2 > b.contactAreaMm2;
    return a.stabilityMarginMm > b.stabilityMarginMm;
  });
  return poses;
}

Result<std::vector<PoseCandidate>> candidatePoses(const TriangleMesh& model, const Vec3& givenUp,
                                                  const PoseOptions& poseOptions, const SearchOptions& options) {
  if (Status s = validate(poseOptions); !s) return s.error();
  if (!givenUp.allFinite() || givenUp.norm() < 1e-12) return outOfRange("the given up", "must be a non-zero direction");
  std::vector<PoseCandidate> poses;
  PoseCandidate given;
  given.up = givenUp.normalized();
  given.source = PoseSource::Given;
  given.riskyAreaMm2 = riskyAreaFor(model, given.up, options);
  poses.push_back(given);
  auto resting = restingPoses(model, poseOptions.mergeDegrees, options);
  if (!resting.ok()) return resting.error();
  // Resting poses take up to two thirds of the slots; sampled directions cover what no flat patch offers
  // (a bunny rests on its belly, but its best pose may balance on its back).
  const int restingSlots = 1 + (2 * (poseOptions.poses - 1) + 2) / 3;
  for (const PoseCandidate& pose : *resting) {
    if (static_cast<int>(poses.size()) >= std::min(poseOptions.poses, restingSlots)) break;
    if (!closeToAny(poses, pose.up)) poses.push_back(pose);
  }
  const int free = poseOptions.poses - static_cast<int>(poses.size());
  for (const Vec3& up : fibonacciSphere(std::max(0, free))) {
    if (closeToAny(poses, up)) continue;
    PoseCandidate pose;
    pose.up = up;
    pose.source = PoseSource::Sampled;
    pose.riskyAreaMm2 = riskyAreaFor(model, up, options);
    poses.push_back(pose);
  }
  return poses;
}

Eigen::Matrix3d poseRotation(const Vec3& up, const Vec3& platformUp) {
  return Eigen::Quaterniond::FromTwoVectors(up.normalized(), platformUp.normalized()).toRotationMatrix();
}

MachineSpec machineForPose(const MachineSpec& machine, const Vec3& up) {
  MachineSpec spec = machine;
  const Eigen::Matrix3d turn = poseRotation(machine.up, up);
  spec.up = up.normalized();
  spec.rotationAxis = (turn * machine.rotationAxis).normalized();
  for (ForbiddenCone& cone : spec.forbiddenCones) cone.axis = (turn * cone.axis).normalized();
  return spec;
}

Result<PoseSearchResult> decomposeWithPoseSearch(const TriangleMesh& model, const MachineSpec& machine,
                                                 const SearchOptions& options, const PoseOptions& poseOptions,
                                                 JobContext& job) {
  if (Status s = validate(poseOptions); !s) return s.error();
  if (Status s = detail::checkSearchInputs(model, machine, options); !s) return s.error();
  const auto start = std::chrono::steady_clock::now();
  auto candidates = candidatePoses(model, machine.up, poseOptions, options);
  if (!candidates.ok()) return candidates.error();
  const int count = static_cast<int>(candidates->size());
  const int threads = detail::resolveThreadCount(options.threads);
  SearchOptions single = options;
  single.threads = 1;  // parallel across poses instead
  SearchOptions cheap = single;
  cheap.scheme = poseOptions.cheapScheme;

  std::vector<PoseTrial> trials(count);
  std::vector<std::optional<Decomposition>> plans(count);
  const int searches = std::min(poseOptions.fullSearches, count);
  std::atomic<int> finished{0};
  const double steps = count + 4.0 * searches;  // a full search costs a few cheap ones
  // 1. Cheap score per pose.
  detail::parallelFor(count, threads, [&](int i) {
    if (job.isCancelled()) return;
    const auto t0 = std::chrono::steady_clock::now();
    PoseTrial& trial = trials[i];
    trial.pose = (*candidates)[i];
    Decomposition plan = detail::runDecomposition(model, machineForPose(machine, trial.pose.up), cheap, job, {});
    trial.cheapJgMm2 = trial.jgAfterMm2 = plan.jgAfterMm2;
    trial.regions = static_cast<int>(plan.regions.size());
    trial.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    plans[i] = std::move(plan);
    job.setProgress(++finished / steps, "pose scores");
  });
  for (int i = 0; i < count; ++i) trials[i].pose = (*candidates)[i];

  // 2. The full search on the given up and the best-scored others.
  std::vector<int> order;
  for (int i = 1; i < count; ++i)
    if (plans[i]) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return trials[a].cheapJgMm2 < trials[b].cheapJgMm2; });
  std::vector<int> chosen = {0};
  for (int i : order)
    if (static_cast<int>(chosen.size()) < searches) chosen.push_back(i);
  if (options.scheme != poseOptions.cheapScheme) {
    detail::parallelFor(static_cast<int>(chosen.size()), threads, [&](int k) {
      if (job.isCancelled()) return;
      const int i = chosen[k];
      const auto t0 = std::chrono::steady_clock::now();
      Decomposition plan = detail::runDecomposition(model, machineForPose(machine, trials[i].pose.up), single, job, {});
      if (plan.cancelled) return;  // keep the finished cheap plan
      trials[i].searched = true;
      trials[i].jgAfterMm2 = plan.jgAfterMm2;
      trials[i].regions = static_cast<int>(plan.regions.size());
      trials[i].seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      plans[i] = std::move(plan);
      job.setProgress((finished += 4) / steps, "pose searches");
    });
  } else {
    for (int i : chosen) trials[i].searched = static_cast<bool>(plans[i]);
  }

  // 3. The best fully searched plan; when cancelled, the best plan that finished.
  int best = -1;
  for (int i = 0; i < count; ++i) {
    if (!plans[i] || (!trials[i].searched && std::any_of(trials.begin(), trials.end(), [](const PoseTrial& t) { return t.searched; })))
      continue;
    if (best < 0 || better(trials[i], trials[best])) best = i;
  }
  if (best < 0) return Error{ErrorCode::Cancelled, "the pose search was cancelled before any pose finished", "pose search"};
  PoseSearchResult result;
  result.plan = std::move(*plans[best]);
  result.plan.cancelled = job.isCancelled();
  result.chosen = trials[best].pose;
  result.chosenTrial = best;
  result.rotation = poseRotation(result.chosen.up, machine.up);
  result.trials = std::move(trials);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.plan.statistics.seconds = result.seconds;  // the whole pose search, as the time it took to get the plan
  result.plan.statistics.threads = threads;
  job.setProgress(1.0, "pose search done");
  return result;
}

}  // namespace multidir::core
