// Polishing: the found plan's planes moved continuously, past the sampled candidates (docs/search.md,
// "Polishing").
//
// The search chooses among sampled planes (a lattice of normals, offsets on a 1 mm grid) and the paper's
// Discussion says as much: "we may miss the real optimal clipping planes ... future work should consider
// further adjusting clipping planes via continuous optimization by using the planes determined in our approach
// as an initial guess". This is that adjustment.
//
// The objective is J_G of the whole plan as the final plan measures it: every candidate plan is cut and its
// regions' risky areas measured by the same code that makes and scores the search's plan (SearchEngine::cut,
// analyzeOverhang on each region), so polishing cannot exploit a count the plan does not use. J_G is piecewise
// smooth in a plane's parameters, with jumps where the plane crosses a vertex or a face turns risky, and each
// plane's region constrains the next: no gradient is available and a gradient would not see the jumps. So a
// pattern search (compass search): for one plane, the offset moved by +-h and the normal turned by the angle a
// on six directions around it (4-DOF: whole stepper steps about the axis), pivoting on the centre of the cut's
// cross-section; the best move that lowers J_G is taken and followed further while that lowers J_G (a pattern
// move); planes in printing order, one pass per step size, then a and h halve. Every move is a whole plan
// re-cut from that plane on, with every criterion checked, so every plan polishing passes through is valid.
#include "multidir/core/search/plan_polish.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "common/fixed_text.h"
#include "detail/parallel.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/search/candidate_planes.h"
#include "search/run_decomposition.h"
#include "plan/stl_image.h"
#include "search/search_engine.h"
#include "search/search_schemes.h"

namespace multidir::core {
namespace detail {
namespace {

using NodePtr = std::shared_ptr<const SearchNode>;

// The first steps: 2 degrees is a sixth of the 250-normal lattice's spacing (the refinement between lattice
// normals reached a sixteenth for the best candidates of each level, but for the plan of that level, not the
// final one); half the offset step is as far as the nearest untried offset.
constexpr double kFirstAngleStepDegrees = 2.0;
// At one step size: passes over the planes, this many (a second pass while planes still move gained 0.1 to
// 4 % of J_G at up to 40 % more evaluations, once moves are followed as below: docs/search.md); improving moves
// of one plane in a row, at most this many. Bounds the cost on a plan whose J_G falls slowly.
constexpr int kPassesPerLevel = 1;
constexpr int kMaxMovesPerPlane = 4;
// After a move that lowered J_G, the same move again (the offset shifted by as much, the normal turned by the
// same rotation about the new cut's centre) and twice that, up to this many times while one of them lowers J_G:
// a pattern move (Hooke and Jeeves). The polished plans showed why: on the fertility statue and the
// cheburashka most planes took all four moves in a row at the first step, the polish far from converged, each
// move costing the ten trial moves; following a direction that works costs two.
constexpr int kMaxPatternMoves = 4;
// A plan polished only to beat another is given up when, after a share f of its polish, it has lost less than
// this x f of what it must lose: a quarter of the pace that gets there. The bunny's finalists that won (on the
// 254- and 256-normal lattices) had lost 35 and 46 % of what they needed after their first fifth and sixth;
// the fertility statue's, which lost 5 % of its needed J_G in all, had lost nothing after its first seventh.
constexpr double kLeastPace = 0.25;

std::vector<Plane> planesOf(const std::vector<NodePtr>& chain) {
  std::vector<Plane> planes;
  for (std::size_t k = 1; k < chain.size(); ++k) planes.push_back(chain[k]->plane);
  return planes;
}

// Where a turned plane pivots: the centre of the cut's corners on the plane (the region's cap), so that a turn
// moves the cut least where it cuts.
Vec3 pivotOf(const SearchNode& cut) {
  const TriangleMesh& region = *cut.region;
  const double tolerance = inPlaneToleranceMm(region);
  Vec3 sum = Vec3::Zero();
  int count = 0;
  for (const Vec3& v : region.vertices)
    if (std::abs(cut.plane.signedDistance(v)) <= tolerance) {
      sum += v;
      ++count;
    }
  if (count == 0) {  // cannot happen for a clip, whose cap lies on its plane; the region's corners then
    for (const Vec3& v : region.vertices) sum += v;
    count = static_cast<int>(region.vertices.size());
  }
  return cut.plane.project(sum / std::max(1, count));
}

// The moves of one plane at steps (angle, offset): the offset down and up by the step, and to the nearest corner
// of `solid` (what the plane cuts) within the step below and above (J_G's smooth pieces end where the plane
// crosses a corner, and a piece's end is where an optimum often lies: a plane along a wall); then the normal
// turned on the machine's neighbours (5-DOF six on a cone, turned by `turn`; 4-DOF the stepper angles either
// side), pivoting on `pivot`.
std::vector<Plane> movesOf(const MachineSpec& machine, const TriangleMesh& solid, const Plane& plane, const Vec3& pivot,
                           double angle, double offsetStep, double turn) {
  std::vector<Plane> moves{{plane.normal, plane.offset - offsetStep}, {plane.normal, plane.offset + offsetStep}};
  // Corners nearer than this are the ones the plane was kept off (micrometres): moving there changes nothing.
  const double minimum = 1e-3 * offsetStep;
  double below = -INFINITY, above = INFINITY;
  for (const Vec3& v : solid.vertices) {
    const double d = plane.signedDistance(v);
    if (d <= -minimum && d > -offsetStep) below = std::max(below, d);
    if (d >= minimum && d < offsetStep) above = std::min(above, d);
  }
  if (std::isfinite(below)) moves.push_back({plane.normal, plane.offset + below});
  if (std::isfinite(above)) moves.push_back({plane.normal, plane.offset + above});
  for (const Vec3& n : neighbourNormals(machine, plane.normal, angle, turn)) moves.push_back(Plane::throughPoint(n, pivot));
  return moves;
}

// Whether every region cut from level k on, and the part left on the platform, survive a binary STL as they are
// (no corners merged or faces flattened by float rounding): what saving the plan requires.
bool savableFrom(const SearchNode& last, std::size_t k) {
  // What saving checks first (plan_file.cpp, regionOnDisk): no corner merged (a cut can also land exactly on
  // a corner it did not make), no face dropped or flattened, still closed.
  auto savable = [](const TriangleMesh& mesh) {
    const StlImage image = stlImage(mesh);
    if (image.mergedCorners != 0 || image.droppedFaces != 0) return false;
    for (std::size_t f = 0; f < image.mesh.triangles.size(); ++f)
      if (!(image.mesh.faceArea(f) > 0.0)) return false;
    return edgeCensus(image.mesh).closedOriented();
  };
  if (!savable(*last.remaining)) return false;
  for (const SearchNode* n = &last; n && n->parent && static_cast<std::size_t>(n->level) > k; n = n->parent.get())
    if (!savable(*n->region)) return false;
  return true;
}

// Whether moving plane k can lower J_G at all: only the regions on either side of it (those holding faces of its
// cap) change when it moves a little, and when they hold no risky area there is nothing to gain.
bool touchesRiskyRegion(const std::vector<NodePtr>& chain, std::size_t k) {
  const FaceOrigin cap = FaceOrigin::cap(static_cast<std::int32_t>(k));
  auto holdsCap = [&](const TriangleMesh& mesh) {
    return std::find(mesh.origins.begin(), mesh.origins.end(), cap) != mesh.origins.end();
  };
  const SearchNode& last = *chain.back();
  if (last.riskyUpAreaMm2 > 0 && holdsCap(*last.remaining)) return true;
  for (std::size_t j = 1; j < chain.size(); ++j) {
    const double risky = chain[j]->prefixJgMm2 - chain[j - 1]->prefixJgMm2;
    if (risky > 0 && holdsCap(*chain[j]->region)) return true;
  }
  return false;
}

class Polisher {
 public:
  Polisher(SearchEngine& engine, double minRegionVolume) : m_engine(engine), m_minRegionVolume(minRegionVolume) {}

  int evaluations() const { return m_evaluations; }

  // The plan with the planes `planes[k]` (moved) and `planes[k+1..]` (as they are) cut from chain[k], or null
  // when any cut is refused or leaves a region smaller than the search's smallest.
  // Also null as soon as the regions cut so far hold `bound` of risky area or more: J_G only grows with the
  // regions still to cut, so such a plan cannot be better.
  NodePtr evaluate(const std::vector<NodePtr>& chain, const std::vector<Plane>& planes, std::size_t k,
                   const Plane& moved, double bound) {
    NodePtr node = chain[k];
    for (std::size_t j = k; j < planes.size(); ++j) {
      // Refused also when its regions reach the bound (before the part below is measured).
      auto child = m_engine.cut(node, j == k ? moved : planes[j], bound);
      if (!child.ok()) return nullptr;
      if (node->volumeMm3 - (*child)->volumeMm3 < m_minRegionVolume) return nullptr;
      node = *child;
    }
    return node;
  }

  // One plane's best improving move at the given steps, or null.
  NodePtr improve(const std::vector<NodePtr>& chain, std::size_t k, double angle, double offsetStep, double turn) {
    const std::vector<Plane> planes = planesOf(chain);
    return bestOf(chain, k,
                  movesOf(m_engine.machine(), *chain[k]->remaining, planes[k], pivotOf(*chain[k + 1]), angle,
                          offsetStep, turn));
  }

  // `better` (plane k moved from `from`) followed further in the direction of that move while that lowers J_G:
  // the move repeated once and twice (one step or two further), the better taken, at most kMaxPatternMoves
  // times. Both trials are fixed by the plans, so the result does not depend on the thread count.
  NodePtr followed(NodePtr better, std::size_t k, Plane from) {
    for (int step = 0; step < kMaxPatternMoves && !m_engine.job().isCancelled(); ++step) {
      const std::vector<NodePtr> chain = chainOf(better);
      const Plane to = chain[k + 1]->plane;
      std::vector<Plane> further;
      if ((to.normal - from.normal).norm() < 1e-12) {
        const double shift = to.offset - from.offset;
        further = {{to.normal, to.offset + shift}, {to.normal, to.offset + 2 * shift}};
      } else {
        // 4-DOF: a turn about the axis by whole stepper steps, repeated, is whole steps again.
        const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(from.normal, to.normal);
        const Vec3 pivot = pivotOf(*chain[k + 1]);
        const Vec3 once = (turn * to.normal).normalized(), twice = (turn * once).normalized();
        further = {Plane::throughPoint(once, pivot), Plane::throughPoint(twice, pivot)};
      }
      NodePtr extended = bestOf(chain, k, further);
      if (!extended) break;
      from = to;
      better = std::move(extended);
    }
    return better;
  }

  // The best of `moves` of plane k that lowers J_G and saves, or null.
  NodePtr bestOf(const std::vector<NodePtr>& chain, std::size_t k, const std::vector<Plane>& moves) {
    const std::vector<Plane> planes = planesOf(chain);
    std::vector<NodePtr> results(moves.size());
    // A gain below rounding is not one: the same plan cut a micrometre elsewhere measures a hair differently.
    const double noise = 1e-9 * std::max(1.0, m_engine.root()->riskyUpAreaMm2);
    const double bound = chain.back()->jg() - noise;
    // Each move writes its own slot and the best is chosen in move order: the same for any thread count.
    parallelFor(static_cast<int>(moves.size()), m_engine.threads(), [&](int m) {
      if (!m_engine.job().isCancelled()) results[m] = evaluate(chain, planes, k, moves[m], bound);
    });
    m_evaluations += static_cast<int>(moves.size());
    // The best that a binary STL can hold (what the plan saves; a search plan's regions pass this by
    // construction of the cuts, but polishing tries many more planes close to the model's corners).
    std::vector<std::size_t> order;
    for (std::size_t m = 0; m < results.size(); ++m)
      if (results[m] && results[m]->jg() < bound) order.push_back(m);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return results[a]->jg() < results[b]->jg(); });
    for (std::size_t m : order)
      if (savableFrom(*results[m], k)) return results[m];
    return nullptr;
  }

 private:
  SearchEngine& m_engine;
  double m_minRegionVolume;
  int m_evaluations = 0;
};

std::string areaText(double mm2) { return detail::fixedText(mm2, 2) + " mm^2"; }

}  // namespace

Result<Decomposition> polishDecomposition(const TriangleMesh& model, const MachineSpec& machine,
                                          const SearchOptions& options, Decomposition plan, JobContext& job,
                                          const SearchProgressSink& progress,
                                          const std::optional<PlatformRegion>& platform, PolishRace* race) {
  if (plan.clippingPlanes.empty() || job.isCancelled()) return plan;
  const auto start = std::chrono::steady_clock::now();
  SearchOptions evaluation = options;
  evaluation.candidates.normalSamples = 1;  // the engine only cuts given planes here
  MachineSpec axis = machine;
  axis.rotationAxis = plan.rotationAxis;  // an axis search's choice
  SearchEngine engine(model, axis, evaluation, job, platform);
  Polisher polisher(engine, engine.minRegionVolume(finestVolumeDivisor(options)));

  const Result<NodePtr> cut = cutInTurn(engine, engine.root(), plan.clippingPlanes);
  if (!cut.ok()) return cut.error();
  NodePtr node = *cut;
  const NodePtr found = node;

  auto report = [&](double fraction) {
    if (!progress) return;
    SearchProgress p;
    p.level = node->level;
    p.bestJgMm2 = node->jg();
    p.polishing = true;
    p.polishFraction = std::clamp(fraction, 0.0, 1.0);
    progress(p);
  };
  report(0.0);
  // Racing another plan: given up once the J_G falls too slowly to beat it (kLeastPace).
  const double mustLose = race ? found->jg() - race->mustBeatMm2 : 0.0;
  bool gaveUp = false;
  auto tooSlow = [&](double fraction) {
    return mustLose > 0 && found->jg() - node->jg() < kLeastPace * fraction * mustLose;
  };
  const int levels = options.polishEffort;
  // One pass over the planes at steps (angle, offsetStep); `pass` turns the trial normals. Whether a plane moved.
  auto polishPass = [&](int pass, double angle, double offsetStep, double done, double share) {
    bool moved = false;
    // Printing order: the last plane cut is the first printed after the platform's region, and the cheapest
    // to move (only its own cut is made again).
    const std::size_t count = static_cast<std::size_t>(node->level);
    for (std::size_t step = 0; step < count && !job.isCancelled() && !gaveUp; ++step) {
      const std::size_t k = count - 1 - step;
      if (!touchesRiskyRegion(chainOf(node), k)) continue;
      for (int m = 0; m < kMaxMovesPerPlane; ++m) {
        // Each move turns the cone of trial normals by 30 degrees, as the refinement between lattice normals
        // does, so that repeated moves look in twelve directions.
        const double turn = (pass * kMaxMovesPerPlane + m) * kPi / 6;
        NodePtr better = polisher.improve(chainOf(node), k, angle, offsetStep, turn);
        if (!better || job.isCancelled()) break;
        node = polisher.followed(better, k, chainOf(node)[k + 1]->plane);
        moved = true;
      }
      const double fraction = done + share * static_cast<double>(step + 1) / count;
      report(fraction);
      gaveUp = tooSlow(fraction);
    }
    return moved;
  };
  double angle = 0.0, offsetStep = 0.0;
  for (int level = 0; level < levels && !job.isCancelled() && !gaveUp; ++level) {
    angle = degToRad(kFirstAngleStepDegrees) / std::ldexp(1.0, level);
    offsetStep = options.candidates.offsetStepMm / 2 / std::ldexp(1.0, level);
    for (int pass = 0; pass < kPassesPerLevel && !job.isCancelled() && !gaveUp; ++pass) {
      const double share = 1.0 / kPassesPerLevel / levels;
      if (!polishPass(pass, angle, offsetStep, static_cast<double>(level) / levels + pass * share, share)) break;
    }
    report(static_cast<double>(level + 1) / levels);
  }
  // Moving planes changes what each one gains: those that no longer pay for themselves go.
  if (node != found) {
    const int before = node->level;
    node = withoutUnpaidPlanes(engine, node, options);
    // A removed plane leaves its neighbours' regions changed, and the planes were placed for the plan with it:
    // one more pass at the last steps (the cheburashka: 20.2 mm^2 after the removal, 16.5 after this pass).
    if (node->level < before && !job.isCancelled() && !gaveUp &&
        polishPass(kPassesPerLevel, angle, offsetStep, 1.0, 0.0))
      node = withoutUnpaidPlanes(engine, node, options);
    if (!savableFrom(*node, 0)) node = found;  // a re-cut without a plane landed on a corner: the search's plan
  }
  if (race) race->gaveUp = gaveUp;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  plan.statistics.jgBeforePolishMm2 = plan.jgAfterMm2;
  plan.statistics.polishEvaluations = polisher.evaluations();
  plan.statistics.polishSeconds = seconds;
  plan.statistics.seconds += seconds;
  plan.statistics.clipsPerformed += engine.clipsPerformed();
  // Compared as the plans report it (each region measured again): removing an unpaid plane may have raised
  // J_G by less than the plane-gain threshold, and polishing never returns a plan worse than the one found.
  Decomposition polished = engine.planOf(*node);
  if (node == found || !(polished.jgAfterMm2 < plan.jgAfterMm2)) {
    plan.statistics.notes.push_back("polishing found no better plan than the search's (" +
                                    std::to_string(polisher.evaluations()) + " plans evaluated)");
    return plan;
  }
  polished.cancelled = plan.cancelled;
  polished.rotationAxis = plan.rotationAxis;
  polished.statistics = plan.statistics;
  char note[200];
  std::snprintf(note, sizeof note, "polishing lowered J_G from %s to %s (%d plans evaluated, %.2f s)",
                areaText(plan.jgAfterMm2).c_str(), areaText(polished.jgAfterMm2).c_str(), polisher.evaluations(),
                seconds);
  polished.statistics.notes.push_back(note);
  return polished;
}

Decomposition polishedIfAsked(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                             Decomposition plan, JobContext& job, const SearchProgressSink& progress,
                             const std::optional<PlatformRegion>& platform, PolishRace* race) {
  if (!options.polish || plan.cancelled) return plan;
  auto polished = polishDecomposition(model, machine, options, plan, job, progress, platform, race);
  if (polished.ok()) return std::move(*polished);
  // The search's own planes are cut by the same engine code; a refusal here would be a bug, reported, not hidden.
  plan.statistics.notes.push_back("not polished: " + polished.error().describe());
  return plan;
}

}  // namespace detail

Result<Decomposition> polishPlan(const TriangleMesh& model, const MachineSpec& machine, const SearchOptions& options,
                                 const Decomposition& plan, JobContext& job, const SearchProgressSink& progress) {
  if (Status s = detail::checkSearchInputs(model, machine, options); !s) return s.error();
  return detail::polishDecomposition(model, machine, options, plan, job, progress, std::nullopt);
}

}  // namespace multidir::core
