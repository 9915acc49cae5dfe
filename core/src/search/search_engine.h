#pragma once
// What every search scheme shares: the candidate normals, the platform, scoring a beam's candidates with the
// plane sweep, and extending a beam by one clip (where Criterion II is checked).
#include <atomic>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/common/job_context.h"
#include "multidir/core/geometry/clipping.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/search/search_options.h"
#include "search/search_node.h"

namespace multidir::core::detail {

class SearchEngine {
 public:
  // `platform`: the platform region to use instead of the model's own (a proxy's search uses the full
  // model's, so that Criterion III means the same on both).
  SearchEngine(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options, JobContext& job,
               const std::optional<PlatformRegion>& platform = std::nullopt);

  // Another engine on the same model and platform, with other options (another thread count or beam width;
  // the same model-dependent ones): it shares `base`'s root and the root's scored candidates and sweeps, so
  // several searches can start from one scoring of the uncut model and run side by side. `base` must have
  // scored its root (or the fork scores it again) and outlive the fork.
  SearchEngine(const SearchEngine& base, const SearchOptions& options);

  std::shared_ptr<const SearchNode> root() const { return m_root; }

  // The caller has already verified that the model is a closed, consistently oriented 2-manifold with a
  // positive volume (the proxy search: decimated() checked the same mesh): its clips then skip that check,
  // which is half the time of a clip of a million faces. Debug builds check anyway.
  void trustModelClosed() { m_modelChecked = true; }
  // The engine's cuts run one at a time (the proxy's plan cut on the full mesh): cut() then measures the part
  // below (Criterion II, its risky area along up, its volume) on a second thread while it measures the region
  // above. Each measurement writes its own result, so the node is the same for any thread count. Off by
  // default: the search and polishing call cut() and extend() on every thread already.
  void measureCutsOnTwoThreads() { m_measureCutsOnTwoThreads = true; }

  // Every admissible candidate of a node (Criterion III by construction, minimal volume above), in a
  // fixed order (normal, then offset). Sets `cancelled` and returns early when the job is cancelled.
  std::vector<ScoredCandidate> score(const SearchNode& node, int beamIndex, bool& cancelled);
  // The same for some normals only (indices into normals()), in the order given; `sweeps`, when given,
  // receives each normal's grid and profile. A node whose parent still holds its lattice sweeps is scored
  // from them (the profile of the faces it differs by), which is exact up to rounding and much cheaper.
  std::vector<ScoredCandidate> scoreNormals(const SearchNode& node, int beamIndex, const std::vector<int>& normalIndices,
                                            bool& cancelled, std::vector<NormalSweep>* sweeps = nullptr);
  // Adds a normal beyond the lattice (refinement) and returns its index; a normal already there keeps its own.
  int addNormal(const Vec3& normal);
  const MachineSpec& machine() const { return m_machine; }
  // The apart machine: no Criterion II or III, and every region stands on the bed (docs/jg-definition.md).
  bool sequenceFree() const { return m_machine.kind == MachineKind::Apart; }
  const SearchOptions& options() const { return m_options; }

  // Clips the node by the candidate. Empty when the part below would not stand on the platform
  // (Criterion II) or the clip failed. extend() and cut() may run on several threads at once.
  std::optional<std::shared_ptr<const SearchNode>> extend(const std::shared_ptr<const SearchNode>& node,
                                                          const ScoredCandidate& candidate);

  // Clips the node by a given plane (plan editing): every criterion is checked and a refusal says which.
  // The region's risky area is measured on its mesh. Errors name the plane as "plane K" (K = level + 1).
  // `riskyBoundMm2` (polishing's trials): when the regions cut off so far, this one included, hold that much
  // risky area or more, the cut is refused as soon as that is known, before the part below is checked and
  // measured (a trial whose regions already hold the incumbent's J_G cannot win). A cut below the bound gives
  // the same node and a refusal the same error as without it.
  Result<std::shared_ptr<const SearchNode>> cut(const std::shared_ptr<const SearchNode>& node, const Plane& plane,
                                                double riskyBoundMm2 = kNoRiskyBound);
  static constexpr double kNoRiskyBound = std::numeric_limits<double>::infinity();

  // Criterion II: whether every connected solid of `solid` touches the platform.
  bool standsOnPlatform(const TriangleMesh& solid) const;

  // The plane moved (by at most a few micrometres, deterministically) so that no vertex of `solid` lies within
  // rounding distance of it. A plane through vertices would leave cap corners closer to them than a binary
  // STL can keep apart, and model faces lying in the plane that no cap supports (docs/jg-definition.md).
  Plane keptOffVertices(const Plane& plane, const TriangleMesh& solid) const;

  // Whether a node needs no further cut at the scale whose smallest region is `minRegionVolume`: too small
  // to cut again, or self-supported along up.
  bool isTerminal(const SearchNode& node, double minRegionVolume) const;
  // The smallest region a search at volume divisor w may cut off: V/w. Candidates are offered down to the
  // finest scale's; a search at a coarser scale skips the smaller ones.
  double minRegionVolume(double divisor) const { return m_modelVolume / divisor; }

  // The plan of a node: regions in printing order, risky areas recomputed from the region meshes.
  Decomposition planOf(const SearchNode& node) const;

  const std::vector<Vec3>& normals() const { return m_normals; }
  int latticeSize() const { return m_latticeSize; }
  int threads() const { return m_threads.load(std::memory_order_relaxed); }
  // More threads for the engine's next parallel steps (a search beside it finished). Results do not depend on
  // the thread count, only the time does.
  void addThreads(int more) { m_threads.fetch_add(more, std::memory_order_relaxed); }
  long long candidatesScored() const { return m_candidatesScored; }
  int clipsPerformed() const { return m_clips; }
  int firstLevelCandidates() const { return m_firstLevelCandidates; }
  JobContext& job() { return m_job; }

 private:
  OverhangOptions overhangOptions(RegionBase base) const;
  // What a region cut off stands on when its risky area is measured: the material below (a multi-directional
  // machine) or the bed (apart).
  RegionBase cutRegionBase() const;
  // Clips by `plane`, moved a few micrometres more where the first placement would not survive a binary STL;
  // `plane` becomes the placement used. `keepsFloat` says whether the clip returned survives it (false: no
  // placement did, and the first clip is returned for unprintableReason to refuse).
  Result<ClipResult> clipSavably(const TriangleMesh& solid, Plane& plane, int planeId, bool& keepsFloat);
  bool keepsFloatPrecision(const ClipResult& clipped, const Plane& plane) const;
  // Why a clip's two parts cannot be regions (too thin, not savable: clipSavably's `keepsFloat`), or empty
  // when they can.
  std::string unprintableReason(const ClipResult& clipped, const Plane& plane, bool keepsFloat) const;
  // What a node keeps of its remaining part along up: each face's risky share, the risky area, the volume.
  struct RemainingMeasures {
    std::vector<double> riskyUpShare;
    double riskyUpAreaMm2 = 0.0;
    double volumeMm3 = 0.0;
  };
  RemainingMeasures measureRemaining(const TriangleMesh& remaining) const;
  std::shared_ptr<SearchNode> makeNode(std::shared_ptr<const TriangleMesh> remaining) const;
  std::shared_ptr<SearchNode> makeNode(std::shared_ptr<const TriangleMesh> remaining, RemainingMeasures measures) const;
  std::shared_ptr<SearchNode> makeChild(const std::shared_ptr<const SearchNode>& node, const Plane& plane,
                                        ClipResult clipped, double regionRiskyMm2,
                                        std::optional<RemainingMeasures> measured = std::nullopt) const;

  const MachineSpec& m_machine;
  const SearchOptions& m_options;
  JobContext& m_job;
  std::vector<Vec3> m_normals;  // the lattice first, then normals added by refinement
  int m_latticeSize = 0;
  PlatformRegion m_platform;
  double m_sinAlpha = 0.0;
  double m_modelVolume = 0.0;
  double m_minRegionVolume = 0.0;
  double m_vertexClearanceMm = 0.0;  // how far planes stay from vertices
  double m_clipMarginMm = 0.0;       // how far a clip may move vertices and the plane
  bool m_checkFloatPrecision = true;  // false when the model itself has vertices float cannot tell apart
  std::atomic<int> m_threads{1};
  std::shared_ptr<const SearchNode> m_root;
  std::optional<std::vector<ScoredCandidate>> m_rootScored;  // the lattice's candidates on the uncut model
  long long m_candidatesScored = 0;
  std::atomic<bool> m_modelChecked{false};  // the model passed clipByPlane's closed-solid check once
  std::atomic<int> m_clips{0};  // extend() and cut() run on several threads at once
  int m_firstLevelCandidates = -1;
  bool m_measureCutsOnTwoThreads = false;
};

}  // namespace multidir::core::detail
