// The 4-DOF axis search: the best rotation axis for a rotary platform, with the decomposition on it.
#include "multidir/core/search/decompose.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>

#include "detail/freed_memory.h"
#include "detail/parallel.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "multidir/core/search/plan_from_planes.h"
#include "search/unavoidable_risky_area.h"
#include "search/run_decomposition.h"

namespace multidir::core {

using detail::checkSearchInputs;
using detail::runDecomposition;

namespace {

// The axis search's second stage: the full beam search on this many axes (the given one and the best-scored),
// one more per kAxesPerExtraFullSearch axes: the more axes are screened, the more nearly equal screens compete
// for the first places. Over 36 axes, 4 and 8 gave the same plan on every shared model; over 180, 4 lost the
// kitten's best plan (1.22 % against 1.18 %) and 8 kept it (docs/search.md, "4-DOF: the axis search"). The full
// searches are most of the time left once the screen runs on a copy.
constexpr int kAxesSearchedInFull = 4;
constexpr int kAxesPerExtraFullSearch = 45;
// The first stage screens every axis on a decimated copy of about this many faces (when the model has more than
// twice as many): the screen only ranks the axes, and a beam of width 1 on a quarter of the kitten's faces ranks
// them as on the whole (the same best axis, docs/search.md "4-DOF: the axis search"); its cost is linear in the
// faces. Its volume must stay within kScreeningMaxVolumeChangePercent, else the model itself is screened.
constexpr std::size_t kScreeningFaces = 2500;
constexpr double kScreeningMaxVolumeChangePercent = 0.5;

// The mesh the first stage screens the axes on, with the options and platform region to use there: a decimated
// copy of `model` with the model's platform region (so Criterion III refuses the same planes), the platform
// tolerance of Criterion II grown by how far its lowest point lies above the model's; or none, when the model
// is small already or will not decimate faithfully.
struct ScreeningMesh {
  TriangleMesh mesh;
  SearchOptions options;
  PlatformRegion platform;
};
std::optional<ScreeningMesh> screeningMeshFor(const TriangleMesh& model, const MachineSpec& machine,
                                              const SearchOptions& screening,
                                              const std::optional<PlatformRegion>& platform) {
  if (model.faceCount() <= 2 * kScreeningFaces) return std::nullopt;
  auto proxy = decimated(model, kScreeningFaces, 0.0, kScreeningMaxVolumeChangePercent, screening.threads);
  if (!proxy.ok()) return std::nullopt;
  ScreeningMesh result{std::move(proxy->mesh), screening,
                       platform ? *platform : platformRegionFor(model, machine, screening.platformToleranceMm)};
  double lowest = INFINITY;
  for (const Vec3& v : result.mesh.vertices) lowest = std::min(lowest, machine.up.dot(v));
  result.options.platformToleranceMm += std::max(0.0, lowest - result.platform.heightMm);
  return result;
}

// The axis search proper, on `model` (the model itself or its proxy) with `platform` as the platform region
// when given.
Result<Decomposition> searchAxes(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                                 int axisCount, JobContext& job, const SearchProgressSink& progress,
                                 const std::optional<PlatformRegion>& platform) {
  const auto start = std::chrono::steady_clock::now();

  const int threads = detail::resolveThreadCount(options.threads);
  SearchOptions perAxis = options;
  perAxis.threads = 1;  // parallel across axes instead
  const Vec3 first = machine.rotationAxis;
  const Vec3 second = machine.up.cross(first);
  auto machineFor = [&](int axis) {
    const double angle = kPi * axis / axisCount;
    MachineSpec spec = machine;
    spec.rotationAxis = (std::cos(angle) * first + std::sin(angle) * second).normalized();
    return spec;
  };
  // Only the best plan so far is kept (each axis's plan holds its regions' meshes, so keeping all would make
  // memory grow with the number of axes). "Best": least J_G, then fewer regions, then the lower axis index,
  // compared exactly, so the winner does not depend on the order the threads finish in.
  std::optional<Decomposition> best;
  int bestAxis = -1;
  SearchStatistics total;
  std::mutex resultMutex;
  const auto key = [](double jg, std::size_t regions, int axis) { return std::make_tuple(jg, regions, axis); };
  auto account = [&](const Decomposition& result) {
    total.candidatesScored += result.statistics.candidatesScored;
    total.clipsPerformed += result.statistics.clipsPerformed;
    total.levels = std::max(total.levels, result.statistics.levels);
    total.candidatesPerLevel = std::max(total.candidatesPerLevel, result.statistics.candidatesPerLevel);
    total.normals = result.statistics.normals;
  };
  auto offer = [&](Decomposition result, int axis) {
    if (!best || key(result.jgAfterMm2, result.regions.size(), axis) <
                     key(best->jgAfterMm2, best->regions.size(), bestAxis)) {
      best = std::move(result);
      bestAxis = axis;
    }
  };
  auto report = [&](int axis, const Decomposition& result) {
    if (!progress) return;
    SearchProgress p;
    p.axisIndex = axis;
    p.axisCount = axisCount;
    p.bestJgMm2 = result.jgAfterMm2;
    p.candidatesScored = result.statistics.candidatesScored;
    progress(p);
  };

  // 1. Every axis scored by a beam of width 1 without refinement (about a fifth of the full search's time), on a
  // decimated copy of the model when it has many faces (the screen only ranks the axes);
  // 2. the full beam search on the given axis and the best-screened others, those whose bound (below) could
  // still beat the best plan found. Greedy schemes (cheaper than the screening) run once per axis. Measured on
  // 180 axes (bench, idle, before the screening copy): kitten 15.8 s and the same plan as the full search on
  // every axis (66 s); bunny 31.6 s for 809 mm^2 against 757 mm^2 in 104 s; the greedy schemes as screens missed
  // the bunny's best axes (977 mm^2 with 36 axes searched in full).
  const int fullSearches = kAxesSearchedInFull + axisCount / kAxesPerExtraFullSearch;
  const bool twoStages = options.scheme == SearchScheme::Beam && axisCount > fullSearches;
  SearchOptions screening = perAxis;
  if (twoStages) {
    screening.beamWidth = 1;
    screening.volumeScales = 1;
    screening.refinementRounds = 0;
  }
  // Shared by every axis: the screening copy (made once, on all threads) and the platform region.
  screening.threads = threads;
  const std::optional<ScreeningMesh> screeningMesh =
      twoStages ? screeningMeshFor(model, machine, screening, platform) : std::nullopt;
  screening.threads = 1;
  // No plan of an axis has a J_G below its bound (search/unavoidable_risky_area.h): an axis whose bound is above the best
  // plan found is not searched in full. Skipping it cannot change the result (it could not have won), so the
  // plan does not depend on the order the threads finish in.
  // The platform region the searches keep every plane above (it depends on up alone, so one serves every axis).
  const PlatformRegion platformRegion =
      platform ? *platform : platformRegionFor(model, machine, options.platformToleranceMm);
  std::vector<double> bounds(static_cast<std::size_t>(axisCount));
  detail::parallelFor(axisCount, threads, [&](int a) {
    bounds[static_cast<std::size_t>(a)] = detail::unavoidableRiskyAreaMm2(model, machineFor(a), platformRegion,
                                                                          options.alphaMaxDegrees, options.supportedBandMm);
  });
  auto cannotWin = [&](int axis) {
    std::lock_guard<std::mutex> lock(resultMutex);
    return best && bounds[static_cast<std::size_t>(axis)] > best->jgAfterMm2;
  };
  std::vector<std::tuple<double, std::size_t, int>> scores(static_cast<std::size_t>(axisCount),
                                                           {INFINITY, std::size_t{0}, 0});
  const double steps = axisCount + (twoStages ? 5.0 * fullSearches : 0.0);
  int finished = 0;
  int skipped = 0;
  // The best screen's planes: cut on the model, the plan delivered when the search is cancelled before any full
  // search finished (cancelling keeps the best plan reached).
  int bestScreenAxis = -1;
  std::vector<Plane> bestScreenPlanes;
  detail::parallelFor(axisCount, threads, [&](int a) {
    if (job.isCancelled()) return;
    if (!twoStages && a != 0 && cannotWin(a)) {
      std::lock_guard<std::mutex> lock(resultMutex);
      ++skipped;
      job.setProgress(++finished / steps, "axis search");
      return;
    }
    Decomposition result =
        screeningMesh ? runDecomposition(screeningMesh->mesh, machineFor(a), screeningMesh->options, job, {},
                                         screeningMesh->platform)
                      : runDecomposition(model, machineFor(a), screening, job, {}, platform);
    std::lock_guard<std::mutex> lock(resultMutex);
    job.setProgress(++finished / steps, "axis search");
    // After a cancel nothing more is ranked or reported (a partial screen ranks nothing); a plan of the model
    // itself still stands when it is complete or no axis finished.
    if (result.cancelled || job.isCancelled()) {
      if (!screeningMesh && (!result.cancelled || !best)) offer(std::move(result), a);
      return;
    }
    account(result);
    report(a, result);
    scores[static_cast<std::size_t>(a)] = key(result.jgAfterMm2, result.regions.size(), a);
    if (screeningMesh && (bestScreenAxis < 0 || scores[static_cast<std::size_t>(a)] <
                                                    scores[static_cast<std::size_t>(bestScreenAxis)])) {
      bestScreenAxis = a;
      bestScreenPlanes = result.clippingPlanes;
    }
    // A plan of the screening copy is not the model's: it only ranks its axis.
    if (!screeningMesh) offer(std::move(result), a);
  });
  if (twoStages && !job.isCancelled()) {
    std::vector<std::tuple<double, std::size_t, int>> ranked(scores.begin() + 1, scores.end());
    std::sort(ranked.begin(), ranked.end());
    std::vector<int> chosen{0};
    for (const auto& score : ranked)
      if (static_cast<int>(chosen.size()) < fullSearches && std::isfinite(std::get<0>(score)))
        chosen.push_back(std::get<2>(score));
    // In rank order (parallelFor hands out items in order): the likely winners first, so their J_G lets the
    // bound skip more of the others.
    detail::parallelFor(static_cast<int>(chosen.size()), threads, [&](int k) {
      if (job.isCancelled()) return;
      if (k > 0 && cannotWin(chosen[k])) {
        std::lock_guard<std::mutex> lock(resultMutex);
        ++skipped;
        finished += 5;
        job.setProgress(finished / steps, "axis search");
        return;
      }
      Decomposition result = runDecomposition(model, machineFor(chosen[k]), perAxis, job, {}, platform);
      std::lock_guard<std::mutex> lock(resultMutex);
      // A cancelled search's partial plan stands only when no axis finished; after a cancel nothing is reported.
      if (result.cancelled && best) return;
      account(result);
      finished += 5;
      job.setProgress(finished / steps, "axis search");
      if (!job.isCancelled()) report(chosen[k], result);
      offer(std::move(result), chosen[k]);
    });
  }

  if (!best && job.isCancelled() && bestScreenAxis >= 0) {
    // The copy's planes on the model, every criterion checked there; refused, the uncut model stands.
    auto cut = planFromClippingPlanes(model, machineFor(bestScreenAxis), perAxis, bestScreenPlanes);
    if (!cut.ok()) cut = planFromClippingPlanes(model, machineFor(bestScreenAxis), perAxis, {});
    if (cut.ok()) {
      total.notes.push_back("cancelled while screening: the best-screened axis's planes cut on the model");
      offer(std::move(*cut), bestScreenAxis);
    }
  }
  if (!best) {
    if (job.isCancelled()) return Error{ErrorCode::Cancelled, "the axis search was cancelled before any axis finished", "axis search"};
    return Error{ErrorCode::Internal, "no axis gave a plan", "axis search"};
  }
  detail::returnFreedMemory();
  best->cancelled = job.isCancelled();
  total.threads = threads;
  if (screeningMesh)
    total.notes.push_back("screened " + std::to_string(axisCount) + " axes on a copy of " +
                          std::to_string(screeningMesh->mesh.faceCount()) + " faces");
  if (skipped > 0)
    total.notes.push_back(std::to_string(skipped) +
                          " axes not searched in full: their unavoidable risky area is above the best plan's J_G");
  total.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The chosen axis's plan polished (not every axis's: each polish costs a good part of a search, and a
  // polished runner-up would have to overtake the polished winner).
  best->statistics = total;
  Decomposition result = detail::polishedIfAsked(model, machine, options, std::move(*best), job, progress, platform);
  result.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

Result<Decomposition> decomposeWithAxisSearch(const TriangleMesh& model, const MachineSpec& machine,
                                              const SearchOptions& options, int axisCount, JobContext& job,
                                              const SearchProgressSink& progress) {
  if (machine.kind != MachineKind::RotaryPlatform)
    return Error{ErrorCode::InvalidParameter, "the axis search needs a 4-DOF machine (--machine 4dof)", "axis search"};
  if (axisCount < 1 || axisCount > 3600)
    return Error{ErrorCode::InvalidParameter, "the number of axes must be between 1 and 3600", "axis search"};
  if (Status s = checkSearchInputs(model, machine, options); !s) return s.error();
  if (!detail::needsProxy(model, options)) return searchAxes(model, machine, options, axisCount, job, progress, std::nullopt);
  // The platform region depends on up alone, so one serves every axis.
  auto plan = detail::runProxyDecomposition(
      model, machine, options, job, [&](const TriangleMesh& mesh, const SearchOptions& o, const PlatformRegion& p) {
        return searchAxes(mesh, machine, o, axisCount, job, progress, p);
      });
  detail::returnFreedMemory();
  return plan;
}

}  // namespace multidir::core
