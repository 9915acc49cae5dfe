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
#include "search/apart_search.h"
#include "search/unavoidable_risky_area.h"
#include "search/run_decomposition.h"
#include "search/staged_progress.h"

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

// The poses named for a note: "the given up and 2 other poses", "2 poses (ups (0.014, -0.961, -0.277), ...)".
std::string posesText(const std::vector<PoseCandidate>& poses, const std::vector<int>& which) {
  const bool given = poses[which.front()].source == PoseSource::Given;
  const std::size_t others = which.size() - (given ? 1 : 0);
  if (given)
    return others == 0 ? "the given up"
                       : "the given up and " + std::to_string(others) + (others == 1 ? " other pose" : " other poses");
  std::string ups;
  for (int i : which) {
    const Vec3& up = poses[i].up;
    ups += std::string(ups.empty() ? "" : ", ") + "(" + detail::fixedText(up.x(), 3) + ", " +
           detail::fixedText(up.y(), 3) + ", " + detail::fixedText(up.z(), 3) + ")";
  }
  return std::to_string(others) + (others == 1 ? " pose (up " : " poses (ups ") + ups + ")";
}

// The plan's first note on a huge model: the mesh each pose was searched on, the poses grouped by it.
std::string proxySummary(const TriangleMesh& model, const std::vector<PoseCandidate>& poses,
                         const std::vector<Result<detail::SearchProxy>>& proxies) {
  std::vector<const Result<detail::SearchProxy>*> meshes;  // in the order first used; an error: the full mesh
  std::vector<std::vector<int>> posesOn;
  const auto meshOf = [](const Result<detail::SearchProxy>& p) { return p.ok() ? p->mesh.get() : nullptr; };
  for (int i = 0; i < static_cast<int>(proxies.size()); ++i) {
    std::size_t k = 0;
    while (k < meshes.size() && meshOf(*meshes[k]) != meshOf(proxies[i])) ++k;
    if (k == meshes.size()) meshes.push_back(&proxies[i]), posesOn.emplace_back();
    posesOn[k].push_back(i);
  }
  const auto meshText = [](const Result<detail::SearchProxy>& p) {
    if (!p.ok()) return "the full mesh (no faithful proxy: " + p.error().message + ")";
    char text[256];
    std::snprintf(text, sizeof text, "a proxy of %zu faces (volume within %.3f %%, tolerance %.2f mm; made in %.2f s)",
                  p->mesh->faceCount(), p->volumeChangePercent, p->toleranceMm, p->seconds);
    return std::string(text);
  };
  std::string text = "searched the poses on ";
  if (meshes.size() == 1) {
    text += meshText(*meshes.front());
  } else {
    text += "proxies: ";
    for (std::size_t k = 0; k < meshes.size(); ++k)
      text += (k > 0 ? "; " : "") + posesText(poses, posesOn[k]) + " on " + meshText(*meshes[k]);
  }
  return text + "; each fully searched pose as the plain search at its up (polished on the mesh searched, its plan cut "
                "on the full mesh of " + std::to_string(model.faceCount()) +
         " faces); the other poses' J_G are their cheap scores on the mesh searched";
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
  const std::vector<PoseCandidate>& candidates = standing;
  const int count = static_cast<int>(candidates.size());
  const int threads = detail::resolveThreadCount(options.threads);
  SearchOptions single = options;
  single.threads = 1;  // parallel across poses instead
  SearchOptions cheap = single;
  cheap.scheme = poseOptions.cheapScheme;
  // The cheap plan is this pose's search when the search asked for is the cheap scheme: then it is kept, with
  // the finalists polishing needs, and polished as the plain search polishes its own.
  const bool reuseCheap = options.scheme == poseOptions.cheapScheme;
  const bool keepStarts = reuseCheap && options.polish && options.polishFinalists;

  // A huge model: each pose is searched on the proxy the plain search at its up uses (the tolerant one, or the
  // strict one where the tolerant moved too much of that up's risky area), each made once; each fully searched
  // pose's plan is then cut on the full mesh, so the plans compared and the one returned are the full mesh's
  // (docs/search.md, "The pose search").
  const bool onProxies = detail::needsProxy(model, options);
  std::vector<Result<detail::SearchProxy>> proxies;
  if (onProxies) {
    std::vector<Vec3> ups;
    for (const PoseCandidate& pose : candidates) ups.push_back(pose.up);
    SearchOptions making = options;
    making.threads = threads;
    proxies = detail::makeSearchProxies(model, ups, making);
  }
  const auto proxyOf = [&](int i) { return onProxies && proxies[i].ok() ? proxies[i]->mesh.get() : nullptr; };
  // Per pose on a proxy: the options and platform region there (the full model's).
  std::vector<std::optional<detail::ProxySearchSetup>> setups(count);
  for (int i = 0; i < count; ++i)
    if (proxyOf(i))
      setups[i] = detail::proxySearchSetup(model, *proxyOf(i), machineForPose(machine, candidates[i].up), single);

  std::vector<PoseTrial> trials(count);
  for (int i = 0; i < count; ++i) trials[i].pose = candidates[i];
  std::vector<std::optional<Decomposition>> cheapPlans(count);  // of the mesh searched: the model or its proxy
  std::vector<std::vector<Decomposition>> polishStarts(count);   // the cheap searches' finalists, when kept
  std::vector<std::optional<Decomposition>> plans(count);       // of the model, searched in full
  const int searches = std::min(poseOptions.fullSearches, count);
  std::atomic<int> finished{0};
  const double steps = count - 1 + 4.0 * searches;  // a full search costs a few cheap ones
  // The plan of pose i on the model: a proxy's plan cut on the full mesh, else the plan itself.
  auto onModel = [&](int i, Decomposition plan) {
    if (!setups[i]) return plan;
    plan = detail::cutOnFullMesh(model, machineForPose(machine, candidates[i].up), single, job, setups[i]->platform,
                                 plan);
    plan.statistics.proxyFaces = static_cast<int>(proxyOf(i)->faceCount());
    return plan;
  };
  // The cheap score of pose i (on a proxy: the proxy's J_G, which only ranks the poses).
  const auto scoreCheaply = [&](int i) {
    const auto t0 = std::chrono::steady_clock::now();
    PoseTrial& trial = trials[i];
    const MachineSpec posed = machineForPose(machine, candidates[i].up);
    std::vector<Decomposition>* starts = keepStarts ? &polishStarts[i] : nullptr;
    Decomposition plan;
    if (setups[i]) {
      SearchOptions onProxy = setups[i]->options;
      onProxy.scheme = cheap.scheme;
      plan = detail::runDecomposition(*proxyOf(i), posed, onProxy, job, {}, setups[i]->platform, nullptr, starts);
    } else {
      plan = detail::runDecomposition(model, posed, cheap, job, {}, std::nullopt, nullptr, starts);
    }
    trial.cheapJgMm2 = trial.jgAfterMm2 = plan.jgAfterMm2;
    trial.regions = static_cast<int>(plan.regions.size());
    trial.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cheapPlans[i] = std::move(plan);
  };
  // Pose i's plan as the plain search delivers it, polished on `mesh` (the model, or its proxy with the full
  // model's platform region); from the cheap plan when that is the search asked for.
  // `mustBeat`: the first pose's J_G, for the others (none for the first): a polish that falls too slowly to get
  // below it is given up part-way (PolishRace), since that pose could not win.
  auto polishedOn = [&](int i, const TriangleMesh& mesh, const SearchOptions& o,
                        const std::optional<PlatformRegion>& platform, double mustBeat) {
    const MachineSpec posed = machineForPose(machine, candidates[i].up);
    if (!reuseCheap) return detail::searchedPolishedChoice(mesh, posed, o, job, {}, platform, mustBeat);
    return detail::polishedChoice(mesh, posed, o, *cheapPlans[i], std::move(polishStarts[i]), job, {}, platform,
                                  mustBeat);
  };
  double firstSearchedJg = INFINITY;
  auto fullSearch = [&](int i, const SearchOptions& o) -> Result<Decomposition> {
    // The apart machine's plain search is its own (decompose: the apart search bounded by the 5-DOF plan, both
    // on the proxy decompose at that up makes: this pose's), so a pose of it is searched the same way.
    if (machine.kind == MachineKind::Apart)
      return detail::decomposeApart(model, machineForPose(machine, candidates[i].up), o, job,
                                    detail::StagedProgress({}, {1.0, 1.0}, maxSearchLevels(o)),
                                    onProxies ? &proxies[i] : nullptr);
    // On the model the first pose's J_G is raced against; on a proxy the J_G polished is the proxy's, which the
    // full mesh's plan may differ from, so every pose there is polished in full.
    if (!onProxies) return polishedOn(i, model, o, std::nullopt, firstSearchedJg);
    return detail::searchedOnProxy(model, machineForPose(machine, candidates[i].up), o, job, proxies[i],
                                   [&](const TriangleMesh& mesh, const SearchOptions& onMesh, const PlatformRegion& p) {
                                     return Result<Decomposition>(polishedOn(i, mesh, onMesh, p, INFINITY));
                                   });
  };
  std::mutex resultsMutex;
  const auto searchPose = [&](int i, const SearchOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<Decomposition> plan = fullSearch(i, o);
    if (!plan.ok()) return;
    std::lock_guard<std::mutex> lock(resultsMutex);
    // A search cancelled part-way still returns its best plan so far: kept, but not as a finished search.
    trials[i].searched = !plan->cancelled;
    trials[i].jgAfterMm2 = plan->jgAfterMm2;
    trials[i].regions = static_cast<int>(plan->regions.size());
    trials[i].seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    plans[i] = std::move(*plan);
    job.setProgress((finished += 4) / steps, i == 0 ? "given up search" : "pose searches");
  };

  // 1. The first pose, the given up, is searched in full first, on every thread (its plan does not depend on
  // them), so that its J_G is known before any other pose is looked at.
  if (job.isCancelled())
    return Error{ErrorCode::Cancelled, "the pose search was cancelled before any pose finished", "pose search"};
  {
    job.setProgress(0.0, "given up search");
    SearchOptions first = single;
    first.threads = threads;
    if (reuseCheap) scoreCheaply(0);
    searchPose(0, first);
    if (trials[0].searched) firstSearchedJg = plans[0]->jgAfterMm2;
  }

  // 2. Which other poses could win, and their cheap scores. No plan of a pose has a J_G below that pose's
  // unavoidable risky area (search/unavoidable_risky_area.h: the faces no direction the machine prints along can
  // save, with every plane clear of the platform region; measured on the full mesh): a pose whose bound is above
  // the first pose's J_G could not win, so it is neither scored nor searched (the kitten's other four: bounds of
  // 731 mm^2 and more against its given up's 11.71). Asking only whether the bound is above that J_G stops its sum
  // there. One thread per pose; each pose is compared with the first only, so which poses are scored does not
  // depend on the thread count or the order they finish in.
  detail::parallelFor(count - 1, threads, [&](int k) {
    const int i = k + 1;
    if (job.isCancelled()) return;
    const auto t0 = std::chrono::steady_clock::now();
    if (std::isfinite(firstSearchedJg)) {
      const MachineSpec posed = machineForPose(machine, candidates[i].up);
      const double bound = detail::unavoidableRiskyAreaMm2(
          model, posed, platformRegionFor(model, posed, options.platformToleranceMm), options.alphaMaxDegrees,
          options.supportedBandMm, firstSearchedJg + kTieMm2);
      trials[i].ruledOut = bound > firstSearchedJg + kTieMm2;
      if (trials[i].ruledOut) trials[i].unavoidableMm2 = bound;
    }
    trials[i].seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!trials[i].ruledOut) scoreCheaply(i);
    job.setProgress(++finished / steps, "pose scores");
  });

  // 3. The full search on the best-scored of the poses that could win, side by side, one thread each: each the
  // plain search at its up, on the proxy it would use, racing the first pose's plan.
  std::vector<int> order;
  for (int i = 1; i < count; ++i)
    if (cheapPlans[i]) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return trials[a].cheapJgMm2 < trials[b].cheapJgMm2; });
  if (static_cast<int>(order.size()) > searches - 1) order.resize(searches - 1);
  detail::parallelFor(static_cast<int>(order.size()), threads, [&](int k) {
    if (!job.isCancelled()) searchPose(order[k], single);
  });
  const int ruledOut = static_cast<int>(
      std::count_if(trials.begin(), trials.end(), [](const PoseTrial& t) { return t.ruledOut; }));
  // Cancelled before any pose was searched in full: the best cheap plan, on the model.
  if (std::none_of(plans.begin(), plans.end(), [](const auto& p) { return p.has_value(); })) {
    int cheapest = -1;
    for (int i = 0; i < count; ++i)
      if (cheapPlans[i] && (cheapest < 0 || better(trials[i], trials[cheapest]))) cheapest = i;
    if (cheapest >= 0) {
      plans[cheapest] = onModel(cheapest, *cheapPlans[cheapest]);
      trials[cheapest].jgAfterMm2 = plans[cheapest]->jgAfterMm2;
      trials[cheapest].regions = static_cast<int>(plans[cheapest]->regions.size());
    }
  }
  std::vector<std::string> notes;
  if (onProxies) notes.push_back(proxySummary(model, candidates, proxies));
  if (ruledOut > 0)
    notes.push_back(std::to_string(ruledOut) + (ruledOut == 1 ? " pose" : " poses") +
                    " neither scored nor searched: the risky area no plan of " + (ruledOut == 1 ? "it" : "theirs") +
                    " can avoid is above the J_G of the given up's plan (" + formatFixed(firstSearchedJg) + " mm^2)");

  // 4. The best fully searched plan; when cancelled, the best plan that finished.
  int best = -1;
  for (int i = 0; i < count; ++i)
    if (plans[i] && (best < 0 || better(trials[i], trials[best]))) best = i;
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
  std::vector<std::string>& planNotes = result.plan.statistics.notes;
  planNotes.insert(planNotes.begin(), notes.begin(), notes.end());
  if (!refusal.empty()) planNotes.push_back(refusal);
  job.setProgress(1.0, "pose search done");
  return result;
}

}  // namespace multidir::core
