#include "multidir/core/search/pose_search.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <string>

#include "common/fixed_text.h"
#include "detail/parallel.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/contact_patch.h"
#include "search/axis_bound.h"
#include "search/run_decomposition.h"

namespace multidir::core {
namespace {

// Two ups closer than this are one pose: the search would cut them alike.
constexpr double kDistinctDegrees = 5.0;

Error outOfRange(const std::string& what, const std::string& range) {
  return Error{ErrorCode::InvalidParameter, what + " " + range, "pose search"};
}

std::string formatFixed(double value) { return detail::fixedText(value, 2); }

bool closeToAny(const std::vector<PoseCandidate>& poses, const Vec3& up) {
  const double cosDistinct = std::cos(kDistinctDegrees * kPi / 180.0);
  return std::any_of(poses.begin(), poses.end(), [&](const PoseCandidate& p) { return p.up.dot(up) > cosDistinct; });
}

// The hull a model stands on and its centre of mass, found once for all its poses.
struct StandingModel {
  ConvexHull hull;
  Vec3 centreOfMass = Vec3::Zero();

  static Result<StandingModel> of(const TriangleMesh& model) {
    if (model.empty())
      return Error{ErrorCode::EmptyMesh, "the model has no faces: load a closed mesh first", "model"};
    std::vector<Vec3> used;
    std::vector<char> seen(model.vertexCount(), 0);
    for (const Triangle& t : model.triangles)
      for (std::int32_t v : t)
        if (!seen[v]) seen[v] = 1, used.push_back(model.vertices[v]);
    auto hull = convexHull(used);
    if (!hull.ok()) return hull.error();
    return StandingModel{std::move(*hull), solidCentreOfMass(model)};
  }
};

Result<PoseCandidate> candidateOn(const ContactPatch& patch, PoseSource source, const TriangleMesh& model,
                                  const SearchOptions& options) {
  auto risky = riskyAreaOnPlatform(model, patch.up, options.alphaMaxDegrees, options.supportedBandMm);
  if (!risky.ok()) return risky.error();
  PoseCandidate pose;
  pose.up = patch.up;
  pose.source = source;
  pose.contactAreaMm2 = patch.areaMm2;
  pose.stabilityMarginMm = patch.stabilityMarginMm;
  pose.riskyAreaMm2 = *risky;
  return pose;
}

// The better of two finished searches: least J_G, then fewer regions, then larger contact, then earlier.
// J_G closer than this are equal (mm^2).
constexpr double kTieMm2 = 1e-6;

bool better(const PoseTrial& a, const PoseTrial& b) {
  if (a.jgAfterMm2 < b.jgAfterMm2 - kTieMm2) return true;
  if (a.jgAfterMm2 > b.jgAfterMm2 + kTieMm2) return false;
  if (a.regions != b.regions) return a.regions < b.regions;
  return a.pose.contactAreaMm2 > b.pose.contactAreaMm2 + kTieMm2;
}

}  // namespace

const char* poseSourceName(PoseSource source) {
  switch (source) {
    case PoseSource::Given: return "given";
    case PoseSource::Resting: return "resting";
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
  auto standing = StandingModel::of(model);
  if (!standing.ok()) return standing.error();
  std::vector<PoseCandidate> poses;
  for (const ContactPatch& patch : standingPatches(standing->hull, standing->centreOfMass, mergeDegrees)) {
    auto pose = candidateOn(patch, PoseSource::Resting, model, options);
    if (!pose.ok()) return pose.error();
    poses.push_back(std::move(*pose));
  }
  return poses;
}

Result<std::vector<PoseCandidate>> candidatePoses(const TriangleMesh& model, const Vec3& givenUp,
                                                  const PoseOptions& poseOptions, const SearchOptions& options) {
  if (Status s = validate(poseOptions); !s) return s.error();
  if (!givenUp.allFinite() || givenUp.norm() < 1e-12) return outOfRange("the given up", "must be a non-zero direction");
  auto standing = StandingModel::of(model);
  if (!standing.ok()) return standing.error();
  std::vector<PoseCandidate> poses;
  auto given = candidateOn(contactPatch(standing->hull, givenUp, standing->centreOfMass), PoseSource::Given, model,
                           options);
  if (!given.ok()) return given.error();
  poses.push_back(std::move(*given));
  std::vector<ContactPatch> resting =
      standingPatches(standing->hull, standing->centreOfMass, poseOptions.mergeDegrees);
  // The largest contacts take up to two thirds of the slots; the rest go to the standing poses farthest from
  // every pose taken so far, so the candidates cover the directions (a bunny rests on its belly, but its best
  // pose may be on its side).
  const int restingSlots = 1 + (2 * (poseOptions.poses - 1) + 2) / 3;
  std::vector<char> taken(resting.size(), 0);
  for (std::size_t i = 0; i < resting.size(); ++i) {
    if (static_cast<int>(poses.size()) >= std::min(poseOptions.poses, restingSlots)) break;
    if (closeToAny(poses, resting[i].up)) continue;
    auto pose = candidateOn(resting[i], PoseSource::Resting, model, options);
    if (!pose.ok()) return pose.error();
    poses.push_back(std::move(*pose));
    taken[i] = 1;
  }
  while (static_cast<int>(poses.size()) < poseOptions.poses) {
    int farthest = -1;
    double farthestCos = 2.0;  // the cosine of its angle to the nearest pose taken: least is farthest
    for (std::size_t i = 0; i < resting.size(); ++i) {
      if (taken[i] || closeToAny(poses, resting[i].up)) continue;
      double nearestCos = -1.0;
      for (const PoseCandidate& p : poses) nearestCos = std::max(nearestCos, p.up.dot(resting[i].up));
      if (nearestCos < farthestCos) farthestCos = nearestCos, farthest = static_cast<int>(i);
    }
    if (farthest < 0) break;
    taken[farthest] = 1;
    auto pose = candidateOn(resting[farthest], PoseSource::Resting, model, options);
    if (!pose.ok()) return pose.error();
    poses.push_back(std::move(*pose));
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
  auto all = candidatePoses(model, machine.up, poseOptions, options);
  if (!all.ok()) return all.error();
  // The poses MultiDir proposes all stand on a patch of the hull (candidatePoses). The given up is the user's
  // choice: it is always tried, so that --pose auto never ends worse than the given up alone, and where the
  // model would not stand in it (a point or an edge on the bed, or its centre of mass outside the patch) the
  // plan says so: it then stays on the bed only by the first layer's adhesion and the supports under it.
  std::vector<PoseCandidate> standing;
  std::string refusal;
  for (const PoseCandidate& pose : *all) {
    if (!pose.stands() && pose.source != PoseSource::Given) continue;
    standing.push_back(pose);
    if (!pose.stands())
      refusal = "the given up does not stand: the model touches the bed in " +
                (pose.contactAreaMm2 > 0 ? "a patch of " + formatFixed(pose.contactAreaMm2) + " mm^2" : std::string("a point or an edge")) +
                " with its centre of mass " + formatFixed(-pose.stabilityMarginMm) +
                " mm outside it; it was tried as given (it holds only by its first layer and supports), every other "
                "pose tried stands";
  }
  const bool givenStands = !standing.empty() && standing.front().source == PoseSource::Given;
  const std::vector<PoseCandidate>& candidates = standing;
  const int count = static_cast<int>(candidates.size());
  const int threads = detail::resolveThreadCount(options.threads);
  SearchOptions single = options;
  single.threads = 1;  // parallel across poses instead
  SearchOptions cheap = single;
  cheap.scheme = poseOptions.cheapScheme;

  // A huge model is searched on one proxy, made once for every pose (its tolerance checked along each
  // candidate's up); each fully searched pose's plan is then cut on the full mesh, so the plans compared and the
  // one returned are the full mesh's (docs/search.md, "The pose search").
  std::optional<detail::SearchProxy> proxy;
  std::vector<std::string> notes;
  if (detail::needsProxy(model, options)) {
    std::vector<Vec3> ups;
    for (const PoseCandidate& pose : candidates) ups.push_back(pose.up);
    SearchOptions making = options;
    making.threads = threads;
    auto made = detail::makeSearchProxy(model, ups, making);
    if (made.ok()) proxy = std::move(*made);
    else notes.push_back("searched the full mesh: no faithful proxy (" + made.error().message + ")");
  }
  // Per pose: the mesh searched, with its options and platform region (the full model's, on a proxy).
  std::vector<std::optional<detail::ProxySearchSetup>> setups(count);
  if (proxy)
    for (int i = 0; i < count; ++i)
      setups[i] = detail::proxySearchSetup(model, proxy->mesh, machineForPose(machine, candidates[i].up), single);
  auto searchPose = [&](int i, const SearchOptions& o) {
    const MachineSpec posed = machineForPose(machine, candidates[i].up);
    if (!setups[i]) return detail::runDecomposition(model, posed, o, job, {});
    SearchOptions onProxy = setups[i]->options;
    onProxy.scheme = o.scheme;
    return detail::runDecomposition(proxy->mesh, posed, onProxy, job, {}, setups[i]->platform);
  };

  std::vector<PoseTrial> trials(count);
  std::vector<std::optional<Decomposition>> cheapPlans(count);  // on a proxy, the proxy's cheap plans
  std::vector<std::optional<Decomposition>> plans(count);       // of the model
  const int searches = std::min(poseOptions.fullSearches, count);
  std::atomic<int> finished{0};
  const double steps = count + 4.0 * searches;  // a full search costs a few cheap ones
  // The plan of pose i on the model: a proxy's plan cut on the full mesh, else the plan itself.
  auto onModel = [&](int i, Decomposition plan) {
    if (!setups[i]) return plan;
    return detail::cutOnFullMesh(model, machineForPose(machine, candidates[i].up), single, job, setups[i]->platform,
                                 plan);
  };
  // 1. Cheap score per pose (on a proxy: the proxy's J_G, which only ranks the poses).
  detail::parallelFor(count, threads, [&](int i) {
    if (job.isCancelled()) return;
    const auto t0 = std::chrono::steady_clock::now();
    PoseTrial& trial = trials[i];
    trial.pose = candidates[i];
    Decomposition plan = searchPose(i, cheap);
    trial.cheapJgMm2 = trial.jgAfterMm2 = plan.jgAfterMm2;
    trial.regions = static_cast<int>(plan.regions.size());
    trial.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    (proxy ? cheapPlans[i] : plans[i]) = std::move(plan);  // without a proxy, the model's own plan
    job.setProgress(++finished / steps, "pose scores");
  });
  for (int i = 0; i < count; ++i) trials[i].pose = candidates[i];

  // 2. The full search on the given up and the best-scored others.
  std::vector<int> order;
  for (int i = givenStands ? 1 : 0; i < count; ++i)
    if (cheapPlans[i] || plans[i]) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return trials[a].cheapJgMm2 < trials[b].cheapJgMm2; });
  std::vector<int> chosen;
  if (givenStands) chosen.push_back(0);
  for (int i : order)
    if (static_cast<int>(chosen.size()) < searches) chosen.push_back(i);
  // On a rotary platform no plan of a pose has a J_G below that pose's unavoidable risky area (search/axis_bound.h,
  // measured on the full mesh): a pose whose bound is above the best searched plan's J_G is not searched, which
  // cannot change the choice (it could not win), whatever order the searches finish in.
  std::vector<double> bounds(count, 0.0);
  if (machine.kind == MachineKind::RotaryPlatform)
    detail::parallelFor(static_cast<int>(chosen.size()), threads, [&](int k) {
      const MachineSpec posed = machineForPose(machine, candidates[chosen[k]].up);
      bounds[chosen[k]] =
          detail::unavoidableRiskyAreaMm2(model, posed, platformRegionFor(model, posed, options.platformToleranceMm),
                                          options.alphaMaxDegrees, options.supportedBandMm);
    });
  std::mutex bestMutex;
  double bestSearchedJg = INFINITY;
  int skipped = 0;
  detail::parallelFor(static_cast<int>(chosen.size()), threads, [&](int k) {
    if (job.isCancelled()) return;
    const int i = chosen[k];
    {
      std::lock_guard<std::mutex> lock(bestMutex);
      if (bounds[i] > bestSearchedJg + kTieMm2) {
        ++skipped;
        job.setProgress((finished += 4) / steps, "pose searches");
        return;
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    // The cheap scheme's plan is already this pose's search when the search asked for is that scheme.
    Decomposition plan = options.scheme != poseOptions.cheapScheme ? searchPose(i, single)
                                                                   : *(proxy ? cheapPlans[i] : plans[i]);
    if (plan.cancelled) return;  // keep the finished cheap plan
    plan = onModel(i, std::move(plan));
    std::lock_guard<std::mutex> lock(bestMutex);
    trials[i].searched = true;
    trials[i].jgAfterMm2 = plan.jgAfterMm2;
    trials[i].regions = static_cast<int>(plan.regions.size());
    trials[i].seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    bestSearchedJg = std::min(bestSearchedJg, plan.jgAfterMm2);
    plans[i] = std::move(plan);
    job.setProgress((finished += 4) / steps, "pose searches");
  });
  // Cancelled on a proxy before any pose was searched in full: the best cheap plan, cut on the model.
  if (proxy && std::none_of(plans.begin(), plans.end(), [](const auto& p) { return p.has_value(); })) {
    int cheapest = -1;
    for (int i = 0; i < count; ++i)
      if (cheapPlans[i] && (cheapest < 0 || trials[i].cheapJgMm2 < trials[cheapest].cheapJgMm2)) cheapest = i;
    if (cheapest >= 0) {
      plans[cheapest] = onModel(cheapest, *cheapPlans[cheapest]);
      trials[cheapest].jgAfterMm2 = plans[cheapest]->jgAfterMm2;
      trials[cheapest].regions = static_cast<int>(plans[cheapest]->regions.size());
    }
  }
  if (proxy) {
    char summary[512];
    std::snprintf(summary, sizeof summary,
                  "searched the poses on a proxy of %zu faces (volume within %.3f %%, %s; made in %.2f s), each "
                  "fully searched pose's plan cut on the full mesh of %zu faces; the other poses' J_G are the "
                  "proxy's cheap scores",
                  proxy->mesh.faceCount(), proxy->volumeChangePercent, proxy->toleranceNote.c_str(), proxy->seconds,
                  model.faceCount());
    notes.insert(notes.begin(), summary);
  }
  if (skipped > 0)
    notes.push_back(std::to_string(skipped) +
                    " poses not searched in full: their unavoidable risky area is above the best plan's J_G");

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
  if (proxy) result.plan.statistics.proxyFaces = static_cast<int>(proxy->mesh.faceCount());
  std::vector<std::string>& planNotes = result.plan.statistics.notes;
  planNotes.insert(planNotes.begin(), notes.begin(), notes.end());
  if (!refusal.empty()) planNotes.push_back(refusal);
  job.setProgress(1.0, "pose search done");
  return result;
}

}  // namespace multidir::core
