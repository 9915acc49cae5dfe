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
#include <string>

#include "multidir/core/mesh/mesh_resolution.h"
#include "search/run_decomposition.h"
#include "search/search_engine.h"

namespace multidir::core::detail {
namespace {

// How far and how finely a proxy plane's offset may move on the full mesh when the proxy's own offset fails a
// criterion there: the proxy's surface lies within a fraction of a millimetre of the full one.
constexpr double kSettleRangeMm = 0.3;
constexpr double kSettleStepMm = 0.05;
// Below the proxy's face count, collapses that move the surface by at most this much are still taken: a
// scan's or subdivided model's redundant faces go (the search's planes are a millimetre apart, its volumes
// and areas are measured on the full mesh in the end), its real detail stays.
constexpr double kProxyToleranceMm = 0.01;
// A proxy whose volume differs more than this from the model's is not faithful: the full mesh is searched.
constexpr double kProxyMaxVolumeChangePercent = 0.5;

std::string planeName(std::size_t index) { return "plane " + std::to_string(index + 1); }

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string millimetres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.2f mm", value);
  return text;
}

}  // namespace

Result<Decomposition> runProxyDecomposition(const TriangleMesh& model, const MachineSpec& machine,
                                            const SearchOptions& options, JobContext& job, const ProxySearchRun& search) {
  const auto start = std::chrono::steady_clock::now();
  const auto proxy = decimated(model, static_cast<std::size_t>(options.proxyFaces), kProxyToleranceMm,
                               kProxyMaxVolumeChangePercent, options.threads);
  if (!proxy.ok()) {
    SearchOptions full = options;
    full.proxyFaces = 0;
    auto plan = search(model, full, platformRegionFor(model, machine, options.platformToleranceMm));
    if (plan.ok())
      plan->statistics.notes.push_back("searched the full mesh: no faithful proxy (" + proxy.error().message + ")");
    return plan;
  }
  const double decimationSeconds = secondsSince(start);
  // One platform region, the full model's, for both searches: Criterion III then refuses the same planes on
  // both. The proxy's lowest point may lie a little above the model's (decimation moved it), so on the proxy a
  // piece counts as standing on the platform within that much more (Criterion II).
  const PlatformRegion platform = platformRegionFor(model, machine, options.platformToleranceMm);
  double proxyLowest = INFINITY;
  for (const Vec3& v : proxy->mesh.vertices) proxyLowest = std::min(proxyLowest, machine.up.dot(v));
  SearchOptions onProxy = options;
  onProxy.proxyFaces = 0;
  onProxy.platformToleranceMm += std::max(0.0, proxyLowest - platform.heightMm);
  const Result<Decomposition> searched = search(proxy->mesh, onProxy, platform);
  if (!searched.ok()) return searched.error();
  const Decomposition& proxyPlan = *searched;
  const auto cutsStart = std::chrono::steady_clock::now();

  SearchOptions evaluation = options;
  evaluation.candidates.normalSamples = 1;  // the engine only cuts given planes here
  MachineSpec chosen = machine;
  chosen.rotationAxis = proxyPlan.rotationAxis;  // an axis search's choice
  SearchEngine engine(model, chosen, evaluation, job, platform);
  // decimated() accepted the model, so it is a closed, oriented 2-manifold (the verdict clipByPlane's check
  // would reach), and the callers' checkSearchInputs found its volume positive.
  engine.trustModelClosed();
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
  plan.statistics.proxyFaces = static_cast<int>(proxy->mesh.faceCount());
  char summary[256];
  std::snprintf(summary, sizeof summary,
                "searched a proxy of %zu faces (volume within %.3f %%; made in %.2f s, searched in %.2f s), then cut "
                "the full mesh of %zu faces (%.2f s)",
                proxy->mesh.faceCount(), proxy->volumeChangePercent, decimationSeconds, proxyPlan.statistics.seconds,
                model.faceCount(), secondsSince(cutsStart));
  notes.insert(notes.begin(), summary);
  // The proxy search's own notes (its polishing) after the summary, before what the full mesh changed.
  notes.insert(notes.begin() + 1, proxyPlan.statistics.notes.begin(), proxyPlan.statistics.notes.end());
  plan.statistics.notes = std::move(notes);
  plan.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

}  // namespace multidir::core::detail
