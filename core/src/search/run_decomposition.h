#pragma once
// The decomposition search without the public entry's bookkeeping, for searches that run many of them (4-DOF
// axes, poses) and report their own progress.
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::core::detail {

// Options, machine and model as decompose() checks them.
Status checkSearchInputs(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options);

// The search itself, for checked inputs; reports levels but leaves the job's overall progress alone. Always
// returns a plan (the uncut model at least); `cancelled` is set when the job was cancelled.
// `platform`: as for SearchEngine. `finalists`, when given (the apart machine's priced choice), receives the
// best plan the search found for every number of cuts, each as found and without its unpaid planes,
// unpolished, in the order of the cuts the search made, none equal to the plan returned or to another.
// `polishStarts`, when given (options.polishFinalists), receives the same finalists as found only (polishedChoice
// removes their unpaid planes from those it polishes), none equal to the plan returned or to another, while the
// plan returned is the one returned without it.
Decomposition runDecomposition(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                               JobContext& job, const SearchProgressSink& progress,
                               const std::optional<PlatformRegion>& platform = std::nullopt,
                               std::vector<Decomposition>* finalists = nullptr,
                               std::vector<Decomposition>* polishStarts = nullptr);

// The same on a decimated proxy of a huge model (options.proxyFaces), its planes then applied to the full mesh
// with their offsets polished there; every number of the plan is the full mesh's. Falls back to the full
// search (and says why in statistics.notes) when the model cannot be decimated faithfully.
// `search` runs on the proxy (or, without a faithful proxy, on the model itself), with the options and the
// platform region to use there; the rotation axis of the plan it returns is the one cut on the full mesh.
using ProxySearchRun = std::function<Result<Decomposition>(const TriangleMesh& mesh, const SearchOptions& options,
                                                           const PlatformRegion& platform)>;
Result<Decomposition> runProxyDecomposition(const TriangleMesh& model, const MachineSpec& machine,
                                            const SearchOptions& options, JobContext& job, const ProxySearchRun& search);

// The proxy a huge model is searched on along `up` (docs/search.md, "Million-triangle models"): decimated
// within the proxy's tolerance, made again with the strict one when that moved more than a tenth of the risky
// area along `up`. An error when no faithful proxy can be made.
struct SearchProxy {
  std::shared_ptr<const TriangleMesh> mesh;  // shared by the searches along several ups (makeSearchProxies)
  double toleranceMm = 0.0;                  // the collapses' tolerance below the face count
  double volumeChangePercent = 0.0;
  std::string toleranceNote;  // the tolerance used and the risky area it moved along up, for the plan's notes
  double seconds = 0.0;       // to make it
};
Result<SearchProxy> makeSearchProxy(const TriangleMesh& model, const Vec3& up, const SearchOptions& options);

// For each of `ups`, the proxy makeSearchProxy(model, up, options) makes (the pose search's poses), each mesh
// made at most once: the tolerant proxy, and the strict one only when some up needs it (the ups that share a
// mesh share its shared_ptr). The decimation of a million faces costs about 0.8 s.
std::vector<Result<SearchProxy>> makeSearchProxies(const TriangleMesh& model, const std::vector<Vec3>& ups,
                                                  const SearchOptions& options);

// runProxyDecomposition's search on a proxy already made: `search` on it, its plan cut on the full mesh, and
// the notes saying so; without a proxy (`proxy` an error), `search` on the model with the reason in the notes.
Result<Decomposition> searchedOnProxy(const TriangleMesh& model, const MachineSpec& machine,
                                      const SearchOptions& options, JobContext& job, const Result<SearchProxy>& proxy,
                                      const ProxySearchRun& search);

// The options and platform region a search of `proxy` for `machine` uses: the full model's platform region,
// Criterion II's tolerance grown by how far the proxy's lowest point lies above the model's.
struct ProxySearchSetup {
  SearchOptions options;
  PlatformRegion platform;
};
ProxySearchSetup proxySearchSetup(const TriangleMesh& model, const TriangleMesh& proxy, const MachineSpec& machine,
                                  const SearchOptions& options);

// A proxy's plan cut on the full mesh: each plane at the proxy's offset, moved within 0.3 mm or dropped when a
// criterion fails there (statistics.notes say which), unpaid planes removed again after a drop. Every number
// is the full mesh's; the statistics are the proxy search's plus the clips made here.
Decomposition cutOnFullMesh(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                            JobContext& job, const PlatformRegion& platform, const Decomposition& proxyPlan);

// Whether `model` is searched on a proxy (options.proxyFaces).
inline bool needsProxy(const TriangleMesh& model, const SearchOptions& options) {
  return options.proxyFaces > 0 && model.faceCount() > static_cast<std::size_t>(options.proxyFaces);
}

// A plan polished only to beat another (a finalist against the search's plan polished): its polish is given up
// part-way once its J_G falls too slowly to get below `mustBeatMm2` (docs/search.md, "Polishing the
// finalists"). `gaveUp` says whether it was.
struct PolishRace {
  double mustBeatMm2 = 0.0;
  bool gaveUp = false;
};

// polishPlan for checked inputs, on `platform` when given (a proxy's search polishes on the proxy, with the full
// model's platform region). An error when a plane of `plan` is refused when cut again. With `race`, the polish
// may stop part-way (above): the plan reached is still a valid plan whose planes pay for themselves.
Result<Decomposition> polishDecomposition(const TriangleMesh& model, const MachineSpec& machine,
                                          const SearchOptions& options, Decomposition plan, JobContext& job,
                                          const SearchProgressSink& progress,
                                          const std::optional<PlatformRegion>& platform,
                                          PolishRace* race = nullptr);

// The search's plan polished as polishedIfAsked does; with options.polishFinalists (and polishing on), also each
// finalist of the search without its unpaid planes, one after the other, and the least J_G after polishing
// delivered (ties: the earlier, the search's own plan first); then, with options.searchTails, its tails searched
// again (tail_search.h). Only the first polish reports progress: the others start above the J_G already
// reported. The same plan for any thread count. `mustBeatMm2`: the J_G of a plan this one competes with (another
// pose's): a polish that falls too slowly to get below it is given up (PolishRace), and no finalist is polished
// that could not get below it; the plan is then valid but may be less polished than without it.
Decomposition searchedPolishedChoice(const TriangleMesh& model, const MachineSpec& machine,
                                     const SearchOptions& options, JobContext& job,
                                     const SearchProgressSink& progress,
                                     const std::optional<PlatformRegion>& platform = std::nullopt,
                                     double mustBeatMm2 = INFINITY);

// The same for a search already run: `plan` is runDecomposition's plan for these arguments and `polishStarts`
// its polishStarts, the search's finalists as found (empty unless options.polishFinalists and polishing are
// on).
Decomposition polishedChoice(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                             Decomposition plan, std::vector<Decomposition> polishStarts, JobContext& job,
                             const SearchProgressSink& progress,
                             const std::optional<PlatformRegion>& platform = std::nullopt,
                             double mustBeatMm2 = INFINITY);

// The plan polished when options.polish is set and the search was not cancelled; else (or when polishing
// refuses the plan, which a note then says) the plan as it is. `race`: as for polishDecomposition.
Decomposition polishedIfAsked(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                             Decomposition plan, JobContext& job, const SearchProgressSink& progress,
                             const std::optional<PlatformRegion>& platform = std::nullopt,
                             PolishRace* race = nullptr);

// Whether `planes` is one of `taken` (the same planes, bit for bit, in the same order); if not, it is added.
// Plans that came out with the same planes are one plan (finalists, their starts for polishing).
bool takeIfNew(std::vector<std::vector<Plane>>& taken, std::vector<Plane> planes);

class SearchEngine;
struct SearchNode;
// Removes, one at a time, the plane whose removal raises J_G least while that rise stays below the plane-gain
// threshold (options.minPlaneGainPercent / minPlaneGainMm2) and the other planes still make a valid plan.
std::shared_ptr<const SearchNode> withoutUnpaidPlanes(SearchEngine& engine, std::shared_ptr<const SearchNode> node,
                                                      const SearchOptions& options);

// A plan as found and the plan it pays with (withoutUnpaidPlanes): removing unpaid planes re-cuts a plan's later
// planes once per plane tried (1.4 s for the fertility statue's 23 planes in one pose), so it is done once.
struct PaidPlan {
  std::shared_ptr<const SearchNode> found;
  std::shared_ptr<const SearchNode> paid;
};

// What a search that ran to its end delivers: among `best` and `searchBests` (each side-by-side search's best
// plan, in their fixed order; compared only when `compareSearches`), each without its unpaid planes, the least
// J_G, then the fewer planes, then the first. Deterministic: the order is fixed, whatever the threads.
// `paid`, when given, receives every plan whose unpaid planes were removed here, with the plan that left.
std::shared_ptr<const SearchNode> paidChoice(SearchEngine& engine, const std::shared_ptr<const SearchNode>& best,
                                             const std::vector<std::shared_ptr<const SearchNode>>& searchBests,
                                             const SearchOptions& options, bool compareSearches,
                                             std::vector<PaidPlan>* paid = nullptr);

}  // namespace multidir::core::detail
