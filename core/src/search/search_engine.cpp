#include "search/search_engine.h"

#include <algorithm>
#include <cmath>

#include "common/fixed_text.h"
#include "detail/parallel.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/plane_sweep.h"
#include "plan/stl_image.h"
#include "search/floating_pieces.h"

namespace multidir::core::detail {

SearchEngine::SearchEngine(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                           JobContext& job, const std::optional<PlatformRegion>& platform)
    : m_machine(machine), m_options(options), m_job(job) {
  m_normals = candidateNormals(machine, options.candidates);
  m_latticeSize = static_cast<int>(m_normals.size());
  m_platform = platform ? *platform : platformRegionFor(model, machine, options.platformToleranceMm);
  m_sinAlpha = std::sin(degToRad(options.alphaMaxDegrees));
  m_modelVolume = signedVolume(model);
  m_minRegionVolume = m_modelVolume / finestVolumeDivisor(options);
  m_threads = resolveThreadCount(options.threads);
  // Several times the tolerance within which a region's corners count as lying in its base plane, so that a
  // region read back from its STL still tells its cap from its other faces.
  m_vertexClearanceMm = 4.0 * inPlaneToleranceMm(model);
  m_checkFloatPrecision = cornersMergedAtFloatPrecision(model) == 0;
  m_clipMarginMm = clipMarginMm(model);
  m_root = makeNode(std::make_shared<const TriangleMesh>(model));
}

SearchEngine::SearchEngine(const SearchEngine& base, const SearchOptions& options)
    : m_machine(base.m_machine),
      m_options(options),
      m_job(base.m_job),
      m_normals(base.m_normals.begin(), base.m_normals.begin() + base.m_latticeSize),
      m_latticeSize(base.m_latticeSize),
      m_platform(base.m_platform),
      m_sinAlpha(base.m_sinAlpha),
      m_modelVolume(base.m_modelVolume),
      m_minRegionVolume(base.m_minRegionVolume),
      m_vertexClearanceMm(base.m_vertexClearanceMm),
      m_clipMarginMm(base.m_clipMarginMm),
      m_checkFloatPrecision(base.m_checkFloatPrecision),
      m_threads(resolveThreadCount(options.threads)),
      m_root(base.m_root),
      m_rootScored(base.m_rootScored),
      m_modelChecked(base.m_modelChecked.load()),
      m_firstLevelCandidates(base.m_firstLevelCandidates) {}

SearchEngine::RemainingMeasures SearchEngine::measureRemaining(const TriangleMesh& remaining) const {
  RemainingMeasures measures;
  // The remaining part always stands on the original platform (Criterion II), so its platform height is
  // the model's; analyzeOverhang finds the same lowest point.
  const auto analysis = analyzeOverhang(remaining, m_machine.up, overhangOptions(RegionBase::Platform));
  if (analysis.ok()) {
    measures.riskyUpShare.resize(remaining.triangles.size(), 0.0);
    for (std::size_t f = 0; f < remaining.triangles.size(); ++f)
      if (analysis->risky[f]) measures.riskyUpShare[f] = analysis->riskyFaceAreaMm2[f] / remaining.faceArea(f);
    measures.riskyUpAreaMm2 = analysis->riskyAreaMm2;
  }
  measures.volumeMm3 = signedVolume(remaining);
  return measures;
}

std::shared_ptr<SearchNode> SearchEngine::makeNode(std::shared_ptr<const TriangleMesh> remaining) const {
  RemainingMeasures measures = measureRemaining(*remaining);
  return makeNode(std::move(remaining), std::move(measures));
}

std::shared_ptr<SearchNode> SearchEngine::makeNode(std::shared_ptr<const TriangleMesh> remaining,
                                                   RemainingMeasures measures) const {
  auto node = std::make_shared<SearchNode>();
  node->riskyUpShare = std::move(measures.riskyUpShare);
  node->riskyUpAreaMm2 = measures.riskyUpAreaMm2;
  node->volumeMm3 = measures.volumeMm3;
  node->remaining = std::move(remaining);
  return node;
}

std::vector<ScoredCandidate> SearchEngine::score(const SearchNode& node, int beamIndex, bool& cancelled) {
  // Greedy, constrained greedy and the beam's first level all score the uncut model: once is enough.
  const bool root = &node == m_root.get();
  if (root && m_rootScored) {
    std::vector<ScoredCandidate> copy = *m_rootScored;
    for (ScoredCandidate& c : copy) c.beam = beamIndex;
    cancelled = m_job.isCancelled();
    return copy;
  }
  std::vector<int> lattice(m_latticeSize);
  for (int i = 0; i < m_latticeSize; ++i) lattice[i] = i;
  const long long before = m_candidatesScored;
  auto sweeps = std::make_shared<std::vector<NormalSweep>>();
  std::vector<ScoredCandidate> all = scoreNormals(node, beamIndex, lattice, cancelled, sweeps.get());
  if (m_firstLevelCandidates < 0) m_firstLevelCandidates = static_cast<int>(m_candidatesScored - before);
  if (!cancelled) node.latticeSweeps = std::move(sweeps);
  if (root && !cancelled) m_rootScored = all;
  return all;
}

namespace {

// Cost per face of sweeping some faces, relative to sweeping a whole mesh (measured: kitten, bunny, fertility).
constexpr double kIncrementalSweepCost = 1.2;

// The parent's grid position of the child grid's first offset, when the child's grid lies inside it.
std::optional<int> shiftInto(const OffsetGrid& parent, const OffsetGrid& child) {
  if (parent.stepMm != child.stepMm || parent.count == 0) return std::nullopt;
  const double position = (child.firstMm - parent.firstMm) / parent.stepMm;
  const double shift = std::round(position);
  // Both grids sit on the same lattice (multiples of the step), so the position is an integer up to rounding.
  if (std::abs(position - shift) > 1e-6 || shift < 0 || shift + child.count > parent.count) return std::nullopt;
  return static_cast<int>(shift);
}

// parent (on its grid, from `shift`) - removed + added, on the child's grid.
SweepProfile updatedProfile(const SweepProfile& parent, int shift, const SweepProfile& removed,
                            const SweepProfile& added, double top) {
  auto combine = [&](const std::vector<double>& p, const std::vector<double>& r, const std::vector<double>& a) {
    std::vector<double> out(r.size());
    for (std::size_t j = 0; j < out.size(); ++j) out[j] = p[j + shift] - r[j] + a[j];
    return out;
  };
  SweepProfile out;
  out.volumeAboveMm3 = combine(parent.volumeAboveMm3, removed.volumeAboveMm3, added.volumeAboveMm3);
  out.riskyAreaAlongNormalMm2 =
      combine(parent.riskyAreaAlongNormalMm2, removed.riskyAreaAlongNormalMm2, added.riskyAreaAlongNormalMm2);
  out.riskyAreaFlaggedMm2 = combine(parent.riskyAreaFlaggedMm2, removed.riskyAreaFlaggedMm2, added.riskyAreaFlaggedMm2);
  out.topMm = top;
  return out;
}

double topAlong(const TriangleMesh& solid, const Vec3& n) {
  double top = -INFINITY;
  for (const Vec3& v : solid.vertices) top = std::max(top, n.dot(v));
  return top;
}

}  // namespace

std::vector<ScoredCandidate> SearchEngine::scoreNormals(const SearchNode& node, int beamIndex,
                                                        const std::vector<int>& normalIndices, bool& cancelled,
                                                        std::vector<NormalSweep>* sweeps) {
  const int count = static_cast<int>(normalIndices.size());
  std::vector<std::vector<ScoredCandidate>> perNormal(count);
  std::vector<long long> offered(count, 0);
  const double volumeSlack = 1e-9 * m_modelVolume;
  const PlaneSweeper sweeper(*node.remaining, node.riskyUpShare, m_sinAlpha);
  // A child differs from its parent by a few faces: its profiles are the parent's updated by those faces.
  // Worth it only when the faces it differs by are fewer than its own (a sweep of some faces costs a little
  // more per face than one of them all, which shares each vertex's height among its faces).
  const std::size_t differing = node.removedParentFaces.size() + node.addedFaces.size();
  const bool fewDiffer = static_cast<double>(differing) * kIncrementalSweepCost <
                         static_cast<double>(node.remaining->triangles.size());
  const std::vector<NormalSweep>* parentSweeps =
      node.parent && fewDiffer ? node.parent->latticeSweeps.get() : nullptr;
  // The parent holds sweeps of lattice normals only: the refinement's normals beyond it are swept whole.
  if (parentSweeps && std::none_of(normalIndices.begin(), normalIndices.end(),
                                   [&](int i) { return i < static_cast<int>(parentSweeps->size()); }))
    parentSweeps = nullptr;
  std::optional<PlaneSweeper> parentSweeper;
  PlaneSweeper::FaceSet removed, added;  // the faces the node differs by, for every normal
  if (parentSweeps) {
    parentSweeper.emplace(*node.parent->remaining, node.parent->riskyUpShare, m_sinAlpha);
    removed = parentSweeper->faceSet(node.removedParentFaces);
    added = sweeper.faceSet(node.addedFaces);
  }
  if (sweeps) sweeps->assign(count, NormalSweep{});

  parallelFor(count, threads(), [&](int k) {
    if (m_job.isCancelled()) return;
    const int i = normalIndices[k];
    const Vec3& n = m_normals[i];
    // Each vertex's level once, for the grid (the part's extent along n) and the sweep.
    const std::vector<double> levels = sweeper.levels(n);
    LevelRange range;
    for (const double level : levels) range.include(level);
    const OffsetGrid grid = sequenceFree()
                                ? candidateOffsets(range, m_options.candidates)
                                : candidateOffsets(range, n, m_platform, m_machine.up, m_options.candidates);
    if (sweeps) (*sweeps)[k].grid = grid;
    if (grid.count == 0) return;
    offered[k] = grid.count;
    std::optional<int> shift;
    if (parentSweeps && i < static_cast<int>(parentSweeps->size())) shift = shiftInto((*parentSweeps)[i].grid, grid);
    const SweepProfile profile =
        shift ? updatedProfile((*parentSweeps)[i].profile, *shift, parentSweeper->sweepFaces(n, grid, removed),
                               sweeper.sweepFaces(n, grid, added), range.highMm)
              : sweeper.sweep(n, grid, levels);
    if (sweeps) (*sweeps)[k].profile = profile;
    for (int j = 0; j < grid.count; ++j) {
      // The part above must be at least minRegionHeightMm tall along its printing direction.
      if (profile.topMm - grid.offsetAt(j) < m_options.minRegionHeightMm) continue;
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
                                                  ClipResult clipped, double regionRiskyMm2,
                                                  std::optional<RemainingMeasures> measured) const {
  auto below = std::make_shared<const TriangleMesh>(std::move(clipped.below));
  auto child = measured ? makeNode(std::move(below), std::move(*measured)) : makeNode(std::move(below));
  // The parent's faces that the child keeps unchanged (same corners, same risky share); the rest differ.
  // (Without both analyses every face counts as changed, which is still exact.)
  const bool sharesKnown = child->riskyUpShare.size() == child->remaining->triangles.size() &&
                           node->riskyUpShare.size() == node->remaining->triangles.size();
  std::vector<char> kept(node->remaining->triangles.size(), 0);
  for (std::size_t f = 0; f < child->remaining->triangles.size(); ++f) {
    const std::int32_t source = f < clipped.belowSourceFace.size() ? clipped.belowSourceFace[f] : -1;
    if (sharesKnown && source >= 0 &&
        child->riskyUpShare[f] == node->riskyUpShare[static_cast<std::size_t>(source)])
      kept[static_cast<std::size_t>(source)] = 1;
    else
      child->addedFaces.push_back(static_cast<std::int32_t>(f));
  }
  for (std::size_t f = 0; f < kept.size(); ++f)
    if (!kept[f]) child->removedParentFaces.push_back(static_cast<std::int32_t>(f));
  child->parent = node;
  child->plane = plane;
  child->region = std::make_shared<const TriangleMesh>(std::move(clipped.above));
  child->prefixJgMm2 = node->prefixJgMm2 + regionRiskyMm2;
  child->level = node->level + 1;
  return child;
}

std::optional<std::shared_ptr<const SearchNode>> SearchEngine::extend(const std::shared_ptr<const SearchNode>& node,
                                                                      const ScoredCandidate& candidate) {
  Plane plane = keptOffVertices(Plane{m_normals[candidate.normal], candidate.offsetMm}, *node->remaining);
  // Criterion II refuses most candidates on branchy models; this finds the certain refusals without a clip.
  if (!sequenceFree() && certainlyLeavesFloatingPiece(*node->remaining, plane, m_machine.up,
                                   m_platform.heightMm + m_options.platformToleranceMm, m_clipMarginMm))
    return std::nullopt;
  bool keepsFloat = true;
  auto clipped = clipSavably(*node->remaining, plane, node->level, keepsFloat);
  if (!clipped.ok() || clipped->below.empty() || clipped->above.empty()) return std::nullopt;
  if (!sequenceFree() && !standsOnPlatform(clipped->below)) return std::nullopt;
  if (!unprintableReason(*clipped, plane, keepsFloat).empty()) return std::nullopt;
  // Measured on the region itself, so J_G is what the saved region gives; the sweep ranked the candidate and
  // agrees with this up to the few micrometres the plane was moved off vertices (apart: and the band above
  // the bed the region lies on, which the sweep does not count).
  const auto risky = analyzeOverhang(clipped->above, plane.normal, overhangOptions(cutRegionBase()));
  if (!risky.ok()) return std::nullopt;
  const double regionRisky = risky->riskyAreaMm2;
  return std::shared_ptr<const SearchNode>(makeChild(node, plane, std::move(*clipped), regionRisky));
}

Result<std::shared_ptr<const SearchNode>> SearchEngine::cut(const std::shared_ptr<const SearchNode>& node,
                                                          const Plane& givenPlane, double riskyBoundMm2) {
  const std::string where = "plane " + std::to_string(node->level + 1);
  Plane plane = keptOffVertices(givenPlane, *node->remaining);
  if (!isRealizable(m_machine, plane.normal, degToRad(0.01)))
    return Error{ErrorCode::InvalidParameter,
                 "the machine cannot print along this plane's normal: tilt it back within the machine's limits", where};
  if (!sequenceFree() && !planeClearsPlatform(plane, m_platform, m_machine.up))
    return Error{ErrorCode::InvalidParameter,
                 "the plane cuts the platform region (Criterion III): move it up or tilt it less", where};
  bool keepsFloat = true;
  auto clipped = clipSavably(*node->remaining, plane, node->level, keepsFloat);
  if (!clipped.ok()) return Error{clipped.error().code, clipped.error().message, where};
  if (clipped->above.empty())
    return Error{ErrorCode::InvalidParameter, "the plane passes above what is left of the model: it cuts nothing off",
                 where};
  if (clipped->below.empty())
    return Error{ErrorCode::InvalidParameter, "the plane leaves nothing below it to stand on the platform", where};
  // The part below's measures (Criterion II, then the child node's) and the region above's (its height and
  // float image, its risky area) do not depend on each other: on two threads when the cuts run alone. The
  // checks below read them in the same order either way, so a refusal is the same.
  bool stands = true;
  std::optional<RemainingMeasures> belowMeasures;
  std::string why;
  std::optional<Result<OverhangAnalysis>> risky;
  auto measureBelow = [&] {
    stands = sequenceFree() || standsOnPlatform(clipped->below);
    if (stands) belowMeasures = measureRemaining(clipped->below);
  };
  auto measureAbove = [&] {
    why = unprintableReason(*clipped, plane, keepsFloat);
    if (why.empty()) risky = analyzeOverhang(clipped->above, plane.normal, overhangOptions(cutRegionBase()));
  };
  const bool bounded = riskyBoundMm2 < kNoRiskyBound;
  auto reachesBound = [&](double regionRisky) { return node->prefixJgMm2 + regionRisky >= riskyBoundMm2; };
  const auto boundReached = [&] {
    return Error{ErrorCode::InvalidParameter, "the regions cut so far hold as much risky area as the bound", where};
  };
  if (m_measureCutsOnTwoThreads) {
    parallelFor(2, std::min(2, threads()), [&](int task) { task == 0 ? measureBelow() : measureAbove(); });
  } else if (bounded) {
    // The region first: when it reaches the bound, neither Criterion II nor the child's measures are needed.
    measureAbove();
    if (why.empty() && risky->ok() && reachesBound((*risky)->riskyAreaMm2)) return boundReached();
    stands = sequenceFree() || standsOnPlatform(clipped->below);
  } else {  // the child's measures are taken only once every check passed (makeChild)
    stands = sequenceFree() || standsOnPlatform(clipped->below);
    if (stands) measureAbove();
  }
  if (!stands)
    return Error{ErrorCode::InvalidParameter,
                 "after this cut a piece below the plane no longer stands on the platform (Criterion II): move or "
                 "tilt the plane so the part below stays in one piece on the platform",
                 where};
  if (!why.empty()) return Error{ErrorCode::InvalidParameter, why, where};
  if (!risky->ok()) return Error{risky->error().code, risky->error().message, where};
  const double regionRisky = (*risky)->riskyAreaMm2;
  if (reachesBound(regionRisky)) return boundReached();
  return std::shared_ptr<const SearchNode>(
      makeChild(node, plane, std::move(*clipped), regionRisky, std::move(belowMeasures)));
}

RegionBase SearchEngine::cutRegionBase() const {
  // docs/jg-definition.md, "Printed apart": the bed lies under every part, so a region cut off stands on the
  // bed at its base plane, not on the material below it.
  return sequenceFree() ? RegionBase::Platform : RegionBase::CutPlane;
}

OverhangOptions SearchEngine::overhangOptions(RegionBase base) const {
  OverhangOptions overhang;
  overhang.alphaMaxDegrees = m_options.alphaMaxDegrees;
  overhang.supportedBandMm = m_options.supportedBandMm;
  overhang.base = base;
  return overhang;
}

namespace {

// Height of a solid along a direction above a level: its top along d minus the level.
double heightAbove(const TriangleMesh& solid, const Vec3& d, double level) { return topAlong(solid, d) - level; }

std::string millimetres(double value) { return detail::fixedText(value, 2) + " mm"; }

}  // namespace

bool SearchEngine::keepsFloatPrecision(const ClipResult& clipped, const Plane& plane) const {
  // Every part the engine clips keeps float precision (the model was checked, every cut since passed this),
  // so only the vertices the clip made or moved, near the plane, can merge: a sort of the cross-section's
  // vertices instead of both sides' (which was a fifth of a cut through a million faces).
  const double tolerance = ClipOptions{}.planeToleranceMm;  // clipSavably's
  return !m_checkFloatPrecision || (cornersMergedAtFloatPrecisionNearPlane(clipped.above, plane, tolerance) == 0 &&
                                    cornersMergedAtFloatPrecisionNearPlane(clipped.below, plane, tolerance) == 0);
}

Result<ClipResult> SearchEngine::clipSavably(const TriangleMesh& solid, Plane& plane, int planeId, bool& keepsFloat) {
  // Where two cuts cross near an edge, a cut vertex can land within float rounding of another one even with
  // the plane off every vertex; a few nearby placements (2, 4, 8 clearances down, then up) avoid it.
  const Plane first = plane;
  std::optional<Result<ClipResult>> firstClip;  // kept: when no placement keeps float precision, it is returned
  for (const double steps : {0.0, -2.0, 2.0, -4.0, 4.0, -8.0, 8.0}) {
    const Plane tried{first.normal, first.offset + steps * m_vertexClearanceMm};
    if (steps != 0.0 && keptOffVertices(tried, solid).offset != tried.offset) continue;
    ++m_clips;
    // What the search clips is the model (checked closed on its first clip) or a part clipByPlane made,
    // closed by construction: re-checking it was two thirds of every clip. Debug builds check every clip.
    ClipOptions options;
    const bool model = &solid == m_root->remaining.get();
    options.checkClosed = model && !m_modelChecked.load();
#ifndef NDEBUG
    options.checkClosed = true;
#endif
    Result<ClipResult> clipped = clipByPlane(solid, tried, planeId, options);
    if (model && clipped.ok()) m_modelChecked = true;
    if (!clipped.ok() || keepsFloatPrecision(*clipped, tried)) {
      plane = tried;
      keepsFloat = true;
      return clipped;
    }
    if (!firstClip) firstClip = std::move(clipped);
  }
  plane = first;
  keepsFloat = false;
  return std::move(*firstClip);  // unprintableReason names what is wrong with it
}

std::string SearchEngine::unprintableReason(const ClipResult& clipped, const Plane& plane, bool keepsFloat) const {
  const double minHeight = m_options.minRegionHeightMm;
  const double regionHeight = heightAbove(clipped.above, plane.normal, plane.offset);
  if (regionHeight < minHeight)
    return "the region above the plane is only " + millimetres(regionHeight) + " tall along its printing direction (at least " +
           millimetres(minHeight) + " are needed to print it): move the plane down or remove it";
  // Apart: what is left is laid on the bed at its own lowest point, wherever the cuts left it.
  const double platformHeight = heightAbove(clipped.below, m_machine.up,
                                            sequenceFree() ? -topAlong(clipped.below, -m_machine.up)
                                                           : m_platform.heightMm);
  if (platformHeight < minHeight)
    return "the part left on the platform would be only " + millimetres(platformHeight) + " tall (at least " +
           millimetres(minHeight) + " are needed): move the plane up or tilt it less";
  if (!keepsFloat)
    return "the plane passes so close to the model's vertices that a binary STL could not keep the cut closed: move "
           "it slightly";
  return {};
}

Plane SearchEngine::keptOffVertices(const Plane& plane, const TriangleMesh& solid) const {
  const double clearance = m_vertexClearanceMm;
  const double window = 64.0 * clearance;
  std::vector<double> near;  // vertex heights close to the plane
  bool touches = false;
  for (const Vec3& v : solid.vertices) {
    const double d = plane.normal.dot(v) - plane.offset;
    if (std::abs(d) < window) near.push_back(d);
    if (std::abs(d) < clearance) touches = true;
  }
  if (!touches) return plane;
  // The nearest shift that leaves every vertex at least `clearance` away: 0 is taken, so the shift sits just
  // beyond some vertex's clearance. Ties go down, into the part below, so the region above keeps the vertices
  // the plane went through (a plane along a wall then leaves no sliver of what the wall holds up below it),
  // and the same input always gives the same plane.
  std::vector<double> shifts;
  for (double d : near) {
    shifts.push_back(d - clearance);
    shifts.push_back(d + clearance);
  }
  std::sort(shifts.begin(), shifts.end(), [](double a, double b) {
    return std::abs(a) != std::abs(b) ? std::abs(a) < std::abs(b) : a < b;
  });
  for (double shift : shifts) {
    if (std::abs(shift) > window - clearance) break;  // beyond what `near` covers
    const bool clear = std::none_of(near.begin(), near.end(), [&](double d) { return std::abs(d - shift) < clearance * (1 - 1e-9); });
    if (clear) return Plane{plane.normal, plane.offset + shift};
  }
  return plane;  // vertices packed closer than the clearance all around: the float check decides
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

bool SearchEngine::isTerminal(const SearchNode& node, double minRegionVolume) const {
  return node.volumeMm3 < minRegionVolume || node.riskyUpAreaMm2 <= 0.0;
}

Decomposition SearchEngine::planOf(const SearchNode& node) const {
  std::vector<const SearchNode*> chain;  // from this node back to the first cut
  for (const SearchNode* n = &node; n && n->parent; n = n->parent.get()) chain.push_back(n);

  Decomposition plan;

  auto addRegion = [&](const TriangleMesh& mesh, const Vec3& direction, std::optional<Plane> base, int index) {
    Region region;
    region.mesh = mesh;
    region.basePlane = base;
    region.clippingIndex = index;
    region.printingDirection = direction;
    region.angles = machineAnglesFor(m_machine, direction);
    region.volumeMm3 = signedVolume(mesh);
    // Printed on its base plane (or the platform), which is its lowest level along the direction.
    const auto analysis =
        analyzeOverhang(mesh, direction, overhangOptions(base ? cutRegionBase() : RegionBase::Platform));
    region.riskyAreaMm2 = analysis.ok() ? analysis->riskyAreaMm2 : 0.0;
    plan.jgAfterMm2 += region.riskyAreaMm2;
    plan.regions.push_back(std::move(region));
  };

  addRegion(*node.remaining, m_machine.up, std::nullopt, -1);
  // Printing order is the inverse of the clipping order: the last cut region is printed second.
  for (const SearchNode* n : chain) addRegion(*n->region, n->plane.normal, n->plane, n->level - 1);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) plan.clippingPlanes.push_back((*it)->plane);
  plan.jgBeforeMm2 = m_root->riskyUpAreaMm2;
  // J_G after is the sum of the regions' risky areas, measured on their meshes (node.jg() is the same sum).
  return plan;
}

}  // namespace multidir::core::detail
