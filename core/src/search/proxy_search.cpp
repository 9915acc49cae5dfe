// Search on a proxy, cut the full mesh exactly.
//
// A scan of a million triangles has the shape of a 50k-triangle version of itself to within a fraction of a
// millimetre, and the search's candidates are a millimetre apart: the extra triangles change which plane
// wins by nothing but cost time linearly (docs/search.md). So the search runs on a quadric-decimated proxy;
// its planes are then cut through the full mesh one by one, each offset first polished on the full mesh (a
// 1-D sweep around it), every criterion checked again there, and J_G, volumes and risky areas measured on the
// full mesh's regions.
#include <chrono>
#include <cstdio>
#include <string>

#include "multidir/core/mesh/mesh_resolution.h"
#include "search/run_decomposition.h"
#include "search/search_engine.h"

namespace multidir::core::detail {
namespace {

// How far and how finely a proxy plane's offset is polished on the full mesh: the proxy's surface lies
// within a fraction of a millimetre of the full one, so a millimetre either way covers the shift.
constexpr double kPolishRangeMm = 0.3;
constexpr double kPolishStepMm = 0.05;

std::string planeName(std::size_t index) { return "plane " + std::to_string(index + 1); }

std::string millimetres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.2f mm", value);
  return text;
}

}  // namespace

Decomposition runProxyDecomposition(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                                    JobContext& job, const SearchProgressSink& progress) {
  const auto start = std::chrono::steady_clock::now();
  const auto proxy = decimated(model, static_cast<std::size_t>(options.proxyFaces));
  if (!proxy.ok()) {
    Decomposition plan = runDecomposition(model, machine, options, job, progress);
    plan.statistics.notes.push_back("searched the full mesh: no faithful proxy (" + proxy.error().message + ")");
    return plan;
  }
  SearchOptions onProxy = options;
  onProxy.proxyFaces = 0;
  const Decomposition proxyPlan = runDecomposition(proxy->mesh, machine, onProxy, job, progress);

  SearchOptions evaluation = options;
  evaluation.candidates.normalSamples = 1;  // the engine only cuts given planes here
  SearchEngine engine(model, machine, evaluation, job);
  std::vector<std::string> notes;
  char summary[160];
  std::snprintf(summary, sizeof summary, "searched a proxy of %zu faces (volume within %.3f %%), cut the full mesh of %zu",
                proxy->mesh.faceCount(), proxy->volumeChangePercent, model.faceCount());
  notes.emplace_back(summary);
  std::shared_ptr<const SearchNode> node = engine.root();
  for (std::size_t k = 0; k < proxyPlan.clippingPlanes.size(); ++k) {
    const Plane& found = proxyPlan.clippingPlanes[k];
    const Plane polished = engine.polished(*node, found, kPolishRangeMm, kPolishStepMm);
    auto child = engine.cut(node, polished);
    if (child.ok() && polished.offset != found.offset)
      notes.push_back(planeName(k) + " moved " + millimetres(polished.offset - found.offset) + " on the full mesh");
    if (!child.ok() && polished.offset != found.offset) child = engine.cut(node, found);
    if (!child.ok()) {
      notes.push_back(planeName(k) + " of the proxy dropped on the full mesh: " + child.error().message);
      continue;
    }
    node = *child;
  }
  node = withoutUnpaidPlanes(engine, node, options);

  Decomposition plan = engine.planOf(*node);
  plan.cancelled = proxyPlan.cancelled;
  plan.rotationAxis = machine.rotationAxis;
  plan.statistics = proxyPlan.statistics;
  plan.statistics.clipsPerformed += engine.clipsPerformed();
  plan.statistics.proxyFaces = static_cast<int>(proxy->mesh.faceCount());
  plan.statistics.notes = std::move(notes);
  plan.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

}  // namespace multidir::core::detail
