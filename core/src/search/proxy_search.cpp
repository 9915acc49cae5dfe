// Search on a proxy, cut the full mesh exactly.
//
// A scan of a million triangles has the shape of a 50k-triangle version of itself to within a fraction of a
// millimetre, and the search's candidates are a millimetre apart: the extra triangles add no shape the search
// could use, but cost time linearly (docs/architecture.md, "Million-triangle models"). So the search runs on a
// quadric-decimated proxy;
// its planes are then cut through the full mesh one by one at the proxy's offsets, every criterion checked
// again there (a plane that fails moves to the nearest offset within 0.3 mm that passes, or is dropped), and
// J_G, volumes and risky areas measured on the full mesh's regions.
//
// Why not move each plane to the offset that scores best on the full mesh: the score of one level only sees
// the region it cuts off, not the later planes chosen for the proxy's offset. Tried on the 16x kitten, it moved
// the first plane 0.3 mm and raised J_G after from 11.55 to 12.51 mm^2.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "multidir/core/analysis/overhang.h"
#include "common/fixed_text.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "search/run_decomposition.h"
#include "search/search_engine.h"

namespace multidir::core::detail {
namespace {

// How far and how finely a proxy plane's offset may move on the full mesh when the proxy's own offset fails a
// criterion there: the proxy's surface lies within a fraction of a millimetre of the full one.
constexpr double kSettleRangeMm = 0.3;
constexpr double kSettleStepMm = 0.05;
// Below the proxy's face count, collapses that move the surface by at most this much are still taken: half
// the thinnest layer MultiDir's printer profiles print (0.2 mm, resources/printers), a quarter of their
// narrowest nozzle (0.4 mm). A printer does not resolve such a step, and a scan's noise is of that size or
// less (the bench's noisy knight: 0.02 mm along the normals, facets tilted by up to 15 degrees), so the noise
// goes and the proxy keeps the shape a printer sees (a sharp edge's quadric error is far above it); the
// search's planes are a millimetre apart, and its volumes and areas are measured on the full mesh in the end.
// What the collapses did to the objective is then measured (below). Tried on the noisy million-face knight:
// 0.01 mm kept the 50,000 faces of the face count (CPU 42.8 s for the whole command), 0.05 mm 27,164 (22.9 s),
// 0.1 mm 7,846 (12.4 s; 5.4 % of the risky area moved), J_G after 12.98, 11.89 and 11.87 % of before.
constexpr double kProxyToleranceMm = 0.1;
// ... down to this many faces; below it only collapses within the strict tolerance: the resolution of the
// paper's and the shared models (10,000 to 16,000 faces) on which the search's results were measured. Without
// it a smooth model went far below its own detail (the 64x kitten to 2,922 faces, the 64x bunny to 5,800,
// against 10,040 and 7,018 at 0.01 mm) and the searches on those proxies drew different plans (64x bunny 1.91 %
// against 1.51 %).
constexpr std::size_t kProxyFloorFaces = 10000;
// The proxy's J_G before (its risky area printed along up) must stay within this share of the model's: the
// proxy must show the search the overhangs the model has. When the tolerance above moved more risky area than
// that (a shape whose overhangs are finer than a layer), the proxy is made again with the strict tolerance.
constexpr double kProxyMaxRiskyChangePercent = 10.0;
constexpr double kStrictProxyToleranceMm = 0.01;
// A proxy whose volume differs more than this from the model's is not faithful: the full mesh is searched.
constexpr double kProxyMaxVolumeChangePercent = 0.5;

// J_G before of a mesh: its risky area printed along up on the bed (docs/jg-definition.md).
double riskyAlongUp(const TriangleMesh& mesh, const Vec3& up, const SearchOptions& options) {
  OverhangOptions overhang;
  overhang.alphaMaxDegrees = options.alphaMaxDegrees;
  overhang.supportedBandMm = options.supportedBandMm;
  const auto analysis = analyzeOverhang(mesh, up, overhang);
  return analysis.ok() ? analysis->riskyAreaMm2 : 0.0;
}

// How much of the model's risky area along an up a proxy's differs by, in percent.
double riskyChangePercent(double modelRisky, double proxyRisky) {
  return 100.0 * std::abs(proxyRisky - modelRisky) / std::max(modelRisky, 1e-9);
}

std::string tolerance(double toleranceMm, double riskyChangePercent) {
  char text[128];
  std::snprintf(text, sizeof text, "tolerance %.2f mm moved %.1f %% of the risky area along up", toleranceMm,
                riskyChangePercent);
  return text;
}

std::string planeName(std::size_t index) { return "plane " + std::to_string(index + 1); }

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string millimetres(double value) { return detail::fixedText(value, 2, true) + " mm"; }

}  // namespace

std::vector<Result<SearchProxy>> makeSearchProxies(const TriangleMesh& model, const std::vector<Vec3>& ups,
                                                  const SearchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto made = decimated(model, static_cast<std::size_t>(options.proxyFaces), kProxyToleranceMm,
                        kProxyMaxVolumeChangePercent, options.threads, kProxyFloorFaces, kStrictProxyToleranceMm);
  if (!made.ok()) return std::vector<Result<SearchProxy>>(ups.size(), made.error());
  const SearchProxy tolerant{std::make_shared<const TriangleMesh>(std::move(made->mesh)), kProxyToleranceMm,
                             made->volumeChangePercent, "", secondsSince(start)};
  // The strict proxy, made once, for the first up whose search needs it.
  std::optional<Result<SearchProxy>> strict;
  std::vector<Result<SearchProxy>> proxies;
  for (const Vec3& up : ups) {
    // The share of the risky area along this up the collapses moved: the proxy must show the search the
    // overhangs it has.
    const double modelRisky = riskyAlongUp(model, up, options);
    const double change = riskyChangePercent(modelRisky, riskyAlongUp(*tolerant.mesh, up, options));
    std::string note = tolerance(kProxyToleranceMm, change);
    if (!(modelRisky > options.minPlaneGainMm2 && change > kProxyMaxRiskyChangePercent)) {
      SearchProxy proxy = tolerant;
      proxy.toleranceNote = std::move(note);
      proxies.emplace_back(std::move(proxy));
      continue;
    }
    if (!strict) {
      const auto strictStart = std::chrono::steady_clock::now();
      auto remade = decimated(model, static_cast<std::size_t>(options.proxyFaces), kStrictProxyToleranceMm,
                              kProxyMaxVolumeChangePercent, options.threads);
      if (remade.ok())
        strict = SearchProxy{std::make_shared<const TriangleMesh>(std::move(remade->mesh)), kStrictProxyToleranceMm,
                             remade->volumeChangePercent, "", tolerant.seconds + secondsSince(strictStart)};
      else
        strict = remade.error();
    }
    if (!strict->ok()) {
      proxies.emplace_back(strict->error());
      continue;
    }
    SearchProxy proxy = **strict;
    proxy.toleranceNote = std::move(note) + ", more than " +
                          std::to_string(static_cast<int>(kProxyMaxRiskyChangePercent)) + " %: made again, " +
                          tolerance(kStrictProxyToleranceMm,
                                    riskyChangePercent(modelRisky, riskyAlongUp(*proxy.mesh, up, options)));
    proxies.emplace_back(std::move(proxy));
  }
  return proxies;
}

Result<SearchProxy> makeSearchProxy(const TriangleMesh& model, const Vec3& up, const SearchOptions& options) {
  return std::move(makeSearchProxies(model, {up}, options).front());
}

ProxySearchSetup proxySearchSetup(const TriangleMesh& model, const TriangleMesh& proxy, const MachineSpec& machine,
                                  const SearchOptions& options) {
  // One platform region, the full model's, for both searches: Criterion III then refuses the same planes on
  // both. The proxy's lowest point may lie a little above the model's (decimation moved it), so on the proxy a
  // piece counts as standing on the platform within that much more (Criterion II).
  ProxySearchSetup setup{options, platformRegionFor(model, machine, options.platformToleranceMm)};
  double proxyLowest = INFINITY;
  for (const Vec3& v : proxy.vertices) proxyLowest = std::min(proxyLowest, machine.up.dot(v));
  setup.options.proxyFaces = 0;
  setup.options.platformToleranceMm += std::max(0.0, proxyLowest - setup.platform.heightMm);
  return setup;
}

Decomposition cutOnFullMesh(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                            JobContext& job, const PlatformRegion& platform, const Decomposition& proxyPlan) {
  SearchOptions evaluation = options;
  evaluation.candidates.normalSamples = 1;  // the engine only cuts given planes here
  MachineSpec chosen = machine;
  chosen.rotationAxis = proxyPlan.rotationAxis;  // an axis search's choice
  SearchEngine engine(model, chosen, evaluation, job, platform);
  // decimated() accepted the model, so it is a closed, oriented 2-manifold (the verdict clipByPlane's check
  // would reach), and the callers' checkSearchInputs found its volume positive.
  engine.trustModelClosed();
  engine.measureCutsOnTwoThreads();  // one cut after the other: nothing else runs beside them
  std::vector<std::string> notes;
  bool dropped = false;
  std::shared_ptr<const SearchNode> node = engine.root();
  for (std::size_t k = 0; k < proxyPlan.clippingPlanes.size(); ++k) {
    const Plane& found = proxyPlan.clippingPlanes[k];
    auto child = engine.cut(node, found);
    const std::string refusal = child.ok() ? "" : child.error().message;
    // The proxy's offset failed a criterion on the full mesh (a sliver left floating, a region a hair too
    // thin): the nearest offset within kSettleRangeMm that passes them all stands in for it.
    for (int step = 1; !child.ok() && step * kSettleStepMm <= kSettleRangeMm + 1e-9; ++step) {
      for (const int sign : {-1, +1}) {
        Plane moved = found;
        moved.offset += sign * step * kSettleStepMm;
        child = engine.cut(node, moved);
        if (child.ok()) {
          notes.push_back(planeName(k) + " moved " + millimetres(moved.offset - found.offset) +
                          " on the full mesh: at the proxy's offset " + refusal);
          break;
        }
      }
    }
    if (!child.ok()) {
      notes.push_back(planeName(k) + " of the proxy dropped on the full mesh: " + refusal);
      dropped = true;
      continue;
    }
    node = *child;
  }
  // The proxy's search already removed the planes that do not pay; once a plane is dropped here, the others'
  // gains have changed, so that is checked again (on the full mesh: it re-cuts the chain without each plane).
  if (dropped) node = withoutUnpaidPlanes(engine, node, options);

  Decomposition plan = engine.planOf(*node);
  plan.cancelled = proxyPlan.cancelled;
  plan.rotationAxis = chosen.rotationAxis;
  plan.statistics = proxyPlan.statistics;
  plan.statistics.clipsPerformed += engine.clipsPerformed();
  plan.statistics.notes = std::move(notes);
  return plan;
}

Result<Decomposition> searchedOnProxy(const TriangleMesh& model, const MachineSpec& machine,
                                      const SearchOptions& options, JobContext& job, const Result<SearchProxy>& proxy,
                                      const ProxySearchRun& search) {
  const auto start = std::chrono::steady_clock::now();
  if (!proxy.ok()) {
    SearchOptions full = options;
    full.proxyFaces = 0;
    auto plan = search(model, full, platformRegionFor(model, machine, options.platformToleranceMm));
    if (plan.ok())
      plan->statistics.notes.push_back("searched the full mesh: no faithful proxy (" + proxy.error().message + ")");
    return plan;
  }
  const TriangleMesh& mesh = *proxy->mesh;
  const ProxySearchSetup setup = proxySearchSetup(model, mesh, machine, options);
  const Result<Decomposition> searched = search(mesh, setup.options, setup.platform);
  if (!searched.ok()) return searched.error();
  const Decomposition& proxyPlan = *searched;
  const auto cutsStart = std::chrono::steady_clock::now();
  Decomposition plan = cutOnFullMesh(model, machine, options, job, setup.platform, proxyPlan);
  plan.statistics.proxyFaces = static_cast<int>(mesh.faceCount());
  std::vector<std::string>& notes = plan.statistics.notes;
  char summary[512];
  std::snprintf(summary, sizeof summary,
                "searched a proxy of %zu faces (volume within %.3f %%, %s; made in %.2f s, searched in %.2f s), "
                "then cut the full mesh of %zu faces (%.2f s)",
                mesh.faceCount(), proxy->volumeChangePercent, proxy->toleranceNote.c_str(), proxy->seconds,
                proxyPlan.statistics.seconds, model.faceCount(), secondsSince(cutsStart));
  notes.insert(notes.begin(), summary);
  // The proxy search's own notes (its polishing) after the summary, before what the full mesh changed.
  notes.insert(notes.begin() + 1, proxyPlan.statistics.notes.begin(), proxyPlan.statistics.notes.end());
  plan.statistics.seconds = secondsSince(start);
  return plan;
}

Result<Decomposition> runProxyDecomposition(const TriangleMesh& model, const MachineSpec& machine,
                                            const SearchOptions& options, JobContext& job, const ProxySearchRun& search) {
  const auto start = std::chrono::steady_clock::now();
  const Result<SearchProxy> proxy = makeSearchProxy(model, machine.up, options);
  Result<Decomposition> plan = searchedOnProxy(model, machine, options, job, proxy, search);
  if (plan.ok() && proxy.ok()) plan->statistics.seconds = secondsSince(start);  // the proxy's making too
  return plan;
}

}  // namespace multidir::core::detail
