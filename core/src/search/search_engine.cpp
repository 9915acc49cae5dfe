#include "search/search_engine.h"

#include <algorithm>
#include <cmath>

#include "detail/parallel.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/plane_sweep.h"

namespace multidir::core::detail {

SearchEngine::SearchEngine(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                           JobContext& job)
    : m_machine(machine), m_options(options), m_job(job) {
  m_normals = candidateNormals(machine, options.candidates);
  m_latticeSize = static_cast<int>(m_normals.size());
  m_platform = platformRegionFor(model, machine, options.platformToleranceMm);
  m_sinAlpha = std::sin(degToRad(options.alphaMaxDegrees));
  m_modelVolume = signedVolume(model);
  m_minRegionVolume = m_modelVolume / options.minVolumeDivisor;
  m_threads = resolveThreadCount(options.threads);
  m_root = makeNode(std::make_shared<const TriangleMesh>(model));
}

std::shared_ptr<SearchNode> SearchEngine::makeNode(std::shared_ptr<const TriangleMesh> remaining) const {
  auto node = std::make_shared<SearchNode>();
  // The remaining part always stands on the original platform (Criterion II), so its platform height is
  // the model's; analyzeOverhang finds the same lowest point.
  const auto analysis = analyzeOverhang(*remaining, m_machine.up, overhangOptions());
  if (analysis.ok()) {
    node->riskyUpShare.resize(remaining->triangles.size(), 0.0);
    for (std::size_t f = 0; f < remaining->triangles.size(); ++f)
      if (analysis->risky[f]) node->riskyUpShare[f] = analysis->riskyFaceAreaMm2[f] / remaining->faceArea(f);
    node->riskyUpAreaMm2 = analysis->riskyAreaMm2;
  }
  node->volumeMm3 = signedVolume(*remaining);
  node->remaining = std::move(remaining);
  return node;
}

std::vector<ScoredCandidate> SearchEngine::score(const SearchNode& node, int beamIndex, bool& cancelled) {
  std::vector<int> lattice(m_latticeSize);
  for (int i = 0; i < m_latticeSize; ++i) lattice[i] = i;
  const long long before = m_candidatesScored;
  std::vector<ScoredCandidate> all = scoreNormals(node, beamIndex, lattice, cancelled);
  if (m_firstLevelCandidates < 0) m_firstLevelCandidates = static_cast<int>(m_candidatesScored - before);
  return all;
}

std::vector<ScoredCandidate> SearchEngine::scoreNormals(const SearchNode& node, int beamIndex,
                                                        const std::vector<int>& normalIndices, bool& cancelled) {
  const int count = static_cast<int>(normalIndices.size());
  std::vector<std::vector<ScoredCandidate>> perNormal(count);
  std::vector<long long> offered(count, 0);
  const double volumeSlack = 1e-9 * m_modelVolume;
  const PlaneSweeper sweeper(*node.remaining, node.riskyUpShare, m_sinAlpha, m_options.supportedBandMm);

  parallelFor(count, m_threads, [&](int k) {
    if (m_job.isCancelled()) return;
    const int i = normalIndices[k];
    const Vec3& n = m_normals[i];
    const OffsetGrid grid = candidateOffsets(*node.remaining, n, m_platform, m_machine.up, m_options.candidates);
    if (grid.count == 0) return;
    offered[k] = grid.count;
    const SweepProfile profile = sweeper.sweep(n, grid);
    for (int j = 0; j < grid.count; ++j) {
      const double above = profile.volumeAboveMm3[j];
      if (above < m_minRegionVolume || node.volumeMm3 - above < volumeSlack) continue;
      ScoredCandidate c;
      c.beam = beamIndex;
      c.normal = i;
      c.offsetMm = grid.offsetAt(j);
      c.riskyAboveMm2 = std::max(0.0, profile.riskyAreaAlongNormalMm2[j]);
      c.riskyUpAboveMm2 = std::max(0.0, profile.riskyAreaFlaggedMm2[j]);
      c.volumeAboveMm3 = above;
      c.jgMm2 = node.prefixJgMm2 + c.riskyAboveMm2 + std::max(0.0, node.riskyUpAreaMm2 - c.riskyUpAboveMm2);
      perNormal[k].push_back(c);
    }
  });
  cancelled = m_job.isCancelled();

  std::vector<ScoredCandidate> all;
  for (int k = 0; k < count; ++k) {
    m_candidatesScored += offered[k];
    all.insert(all.end(), perNormal[k].begin(), perNormal[k].end());
  }
  return all;
}

int SearchEngine::addNormal(const Vec3& normal) {
  for (std::size_t i = 0; i < m_normals.size(); ++i)
    if (m_normals[i].dot(normal) > 1.0 - 1e-12) return static_cast<int>(i);
  m_normals.push_back(normal);
  return static_cast<int>(m_normals.size()) - 1;
}

std::shared_ptr<SearchNode> SearchEngine::makeChild(const std::shared_ptr<const SearchNode>& node, const Plane& plane,
                                                  ClipResult clipped, double regionRiskyMm2) const {
  auto child = makeNode(std::make_shared<const TriangleMesh>(std::move(clipped.below)));
  child->parent = node;
  child->plane = plane;
  child->region = std::make_shared<const TriangleMesh>(std::move(clipped.above));
  child->prefixJgMm2 = node->prefixJgMm2 + regionRiskyMm2;
  child->level = node->level + 1;
  return child;
}

std::optional<std::shared_ptr<const SearchNode>> SearchEngine::extend(const std::shared_ptr<const SearchNode>& node,
                                                                      const ScoredCandidate& candidate) {
  const Plane plane{m_normals[candidate.normal], candidate.offsetMm};
  ++m_clips;
  auto clipped = clipByPlane(*node->remaining, plane, node->level);
  if (!clipped.ok() || clipped->below.empty() || clipped->above.empty()) return std::nullopt;
  if (!standsOnPlatform(clipped->below)) return std::nullopt;
  // The sweep's risky area of the part above equals the clipped region's (tested to 1e-6), and keeps J_G
  // exactly what the candidate was ranked by.
  return std::shared_ptr<const SearchNode>(makeChild(node, plane, std::move(*clipped), candidate.riskyAboveMm2));
}

Result<std::shared_ptr<const SearchNode>> SearchEngine::cut(const std::shared_ptr<const SearchNode>& node,
                                                          const Plane& plane) {
  const std::string where = "plane " + std::to_string(node->level + 1);
  if (!isRealizable(m_machine, plane.normal, degToRad(0.01)))
    return Error{ErrorCode::InvalidParameter,
                 "the machine cannot print along this plane's normal: tilt it back within the machine's limits", where};
  if (!planeClearsPlatform(plane, m_platform, m_machine.up))
    return Error{ErrorCode::InvalidParameter,
                 "the plane cuts the platform region (Criterion III): move it up or tilt it less", where};
  ++m_clips;
  auto clipped = clipByPlane(*node->remaining, plane, node->level);
  if (!clipped.ok()) return Error{clipped.error().code, clipped.error().message, where};
  if (clipped->above.empty())
    return Error{ErrorCode::InvalidParameter, "the plane passes above what is left of the model: it cuts nothing off",
                 where};
  if (clipped->below.empty())
    return Error{ErrorCode::InvalidParameter, "the plane leaves nothing below it to stand on the platform", where};
  if (!standsOnPlatform(clipped->below))
    return Error{ErrorCode::InvalidParameter,
                 "after this cut a piece below the plane no longer stands on the platform (Criterion II): move or "
                 "tilt the plane so the part below stays in one piece on the platform",
                 where};
  const auto risky = analyzeOverhang(clipped->above, plane.normal, overhangOptions());
  if (!risky.ok()) return Error{risky.error().code, risky.error().message, where};
  const double regionRisky = risky->riskyAreaMm2;
  return std::shared_ptr<const SearchNode>(makeChild(node, plane, std::move(*clipped), regionRisky));
}

OverhangOptions SearchEngine::overhangOptions() const {
  OverhangOptions overhang;
  overhang.alphaMaxDegrees = m_options.alphaMaxDegrees;
  overhang.supportedBandMm = m_options.supportedBandMm;
  return overhang;
}

bool SearchEngine::standsOnPlatform(const TriangleMesh& solid) const {
  // Criterion II: every connected solid must reach down to the platform plane.
  const FaceComponents components = faceComponents(solid);
  std::vector<double> lowest(components.count, INFINITY);
  for (std::size_t f = 0; f < solid.triangles.size(); ++f) {
    double& low = lowest[components.componentOfFace[f]];
    for (std::int32_t v : solid.triangles[f]) low = std::min(low, m_machine.up.dot(solid.vertices[v]));
  }
  for (double low : lowest)
    if (low - m_platform.heightMm > m_options.platformToleranceMm) return false;
  return true;
}

bool SearchEngine::isTerminal(const SearchNode& node) const {
  return node.volumeMm3 < m_minRegionVolume || node.riskyUpAreaMm2 <= 0.0;
}

Decomposition SearchEngine::planOf(const SearchNode& node) const {
  std::vector<const SearchNode*> chain;  // from this node back to the first cut
  for (const SearchNode* n = &node; n && n->parent; n = n->parent.get()) chain.push_back(n);

  Decomposition plan;
  const OverhangOptions overhang = overhangOptions();

  auto addRegion = [&](const TriangleMesh& mesh, const Vec3& direction, std::optional<Plane> base, int index) {
    Region region;
    region.mesh = mesh;
    region.basePlane = base;
    region.clippingIndex = index;
    region.printingDirection = direction;
    region.angles = machineAnglesFor(m_machine, direction);
    region.volumeMm3 = signedVolume(mesh);
    // Printed on its base plane (or the platform), which is its lowest level along the direction: the
    // overhang analysis then treats the base as supported, as it is.
    const auto analysis = analyzeOverhang(mesh, direction, overhang);
    region.riskyAreaMm2 = analysis.ok() ? analysis->riskyAreaMm2 : 0.0;
    plan.regions.push_back(std::move(region));
  };

  addRegion(*node.remaining, m_machine.up, std::nullopt, -1);
  // Printing order is the inverse of the clipping order: the last cut region is printed second.
  for (const SearchNode* n : chain) addRegion(*n->region, n->plane.normal, n->plane, n->level - 1);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) plan.clippingPlanes.push_back((*it)->plane);
  plan.jgBeforeMm2 = m_root->riskyUpAreaMm2;
  // The search's own value, from the plane sweep; the regions' risky areas above are measured on their meshes.
  plan.jgAfterMm2 = node.jg();
  return plan;
}

}  // namespace multidir::core::detail
