// The split of a step into runs: a cheap upper bound on how far each orientation gets (the inverse kinematics,
// joint limits and margins at the moves' ends, the conditions every full check also makes there), then the full
// check of the orientations in the order of that bound, stopping once no bound can beat the best run found.
#include "step_reorientation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

bool isTravel(const StepPath& path, std::size_t i) { return !path.moves[i]->extrudes(); }

// The last travel move t with from < t <= failed (the run can be re-oriented before it), or `from` when none.
std::size_t lastTravelUpTo(const StepPath& path, std::size_t from, std::size_t failed) {
  for (std::size_t t = failed; t > from; --t)
    if (isTravel(path, t)) return t;
  return from;
}

// For each branch of `rotationRad`: how far from move `from` a run could at most get (the moves' ends reached on
// the branch within the joint limits, with the reach and wrist margins): path.moves.size() when all.
std::array<std::size_t, 8> reachBounds(const StepPath& path, double rotationRad, std::size_t from) {
  const Cell& cell = *path.cell;
  const ArmModel& arm = cell.arm;
  const std::size_t n = path.moves.size();
  std::array<std::size_t, 8> bound{};
  std::array<bool, 8> alive{};
  alive.fill(true);
  bound.fill(n);
  int living = 8;
  const Eigen::Matrix3d turn = nozzleFrame(cell.nozzleAxis) * Eigen::AngleAxisd(rotationRad, Eigen::Vector3d::UnitZ());
  for (std::size_t i = from; i < n && living > 0; ++i) {
    Eigen::Isometry3d fileToBase = Eigen::Isometry3d::Identity();
    fileToBase.linear() = turn;
    fileToBase.translation() = cell.nozzleTipMm - turn * path.points[i];
    const Eigen::Isometry3d flange = fileToBase * path.input->platformToFile * path.platformToFlange;
    std::array<IkSolution, 8> solutions{};
    const int count = inverseKinematics(arm, flange, solutions);
    std::array<bool, 8> ok{};
    for (int k = 0; k < count; ++k) {
      const IkSolution& s = solutions[static_cast<std::size_t>(k)];
      if (!nearestWithinLimits(arm, &s, 1, cell.home)) continue;
      const double wrist = std::asin(std::min(1.0, std::abs(std::sin(s.joints[4])))) / kDeg;
      if (reachMarginMm(arm, s.joints) < cell.margins.minReachMm || wrist < cell.margins.minWristDegrees) continue;
      ok[static_cast<std::size_t>(s.branch)] = true;
    }
    for (std::size_t b = 0; b < 8; ++b)
      if (alive[b] && !ok[b]) {
        alive[b] = false;
        bound[b] = lastTravelUpTo(path, from, i);
        --living;
      }
  }
  return bound;
}

struct Evaluation {
  std::size_t end = 0;           // the run gets to move `end` (re-oriented before it) or the step's end
  Joints lifted{};               // the arm with the part lifted off the nozzle there
  std::optional<RunFailure> failure;
};

// The full check of one orientation from move `from` (after a turn from `liftedBefore` when from > 0).
Evaluation evaluate(const StepPath& path, const Orientation& o, std::size_t from, const Joints& liftedBefore,
                    const core::JobContext& context) {
  const std::size_t n = path.moves.size();
  StepRun run(path, o, false);
  Evaluation result;
  result.end = from;
  result.failure = from == 0 ? run.startAtApproach() : run.startAfterTurn(from, liftedBefore);
  if (result.failure) return result;
  struct Snapshot {
    std::size_t travel;
    StepRun::State state;
  };
  std::vector<Snapshot> snapshots;
  std::size_t failedAt = n;
  for (std::size_t i = from == 0 ? 0 : from + 1; i < n; ++i) {
    if (i > from && isTravel(path, i)) snapshots.push_back({i, run.state()});
    result.failure = run.advance(i, context);
    if (result.failure) {
      failedAt = i;
      break;
    }
  }
  if (!result.failure) {
    result.failure = run.retreat();
    if (!result.failure) {
      result.end = n;
      return result;
    }
    failedAt = n - 1;
  }
  if (result.failure->fatal) return result;
  for (auto it = snapshots.rbegin(); it != snapshots.rend(); ++it) {
    if (it->travel > failedAt) continue;
    run.restore(it->state);
    if (run.liftOff(it->travel - 1)) continue;
    result.end = it->travel;
    result.lifted = run.joints();
    return result;
  }
  return result;
}

// The nozzle points a run from `from` to `end` asks for: its moves, where it starts (the approach or the lifted
// point) and where it ends (the retreat or the lifted point).
Eigen::AlignedBox3d runBox(const StepPath& path, std::size_t from, std::size_t end) {
  const Eigen::Vector3d lift(0, 0, kStepApproachLiftMm);
  Eigen::AlignedBox3d box(from == 0 ? path.approach : Eigen::Vector3d(path.points[from - 1] + lift));
  box.extend(end == path.moves.size() ? path.retreat : Eigen::Vector3d(path.points[end - 1] + lift));
  for (std::size_t i = from; i < end; ++i) box.extend(path.points[i]);
  return box;
}

}  // namespace

RunPlan planRuns(const StepPath& path, const RunFailure& wholeStep, const core::JobContext& context) {
  const std::size_t n = path.moves.size();
  RunPlan plan;
  std::size_t from = 0;
  Joints lifted{};
  std::optional<Orientation> previous;
  while (from < n) {
    // Today's order over what is left, and each orientation's bound.
    const std::vector<OrientationScore> scores = scoreOrientations(path, runBox(path, from, n));
    std::vector<std::size_t> bound(scores.size(), from);
    for (std::size_t r = 0; r < scores.size(); r += 8) {
      const std::array<std::size_t, 8> b = reachBounds(path, scores[r].orientation.rotationRad, from);
      for (std::size_t k = 0; k < 8 && r + k < scores.size(); ++k)
        bound[r + k] = b[static_cast<std::size_t>(scores[r + k].orientation.branch)];
    }
    std::vector<std::size_t> order(scores.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (bound[a] != bound[b]) return bound[a] > bound[b];
      return betterOrientation(scores[a], scores[b]);
    });
    std::size_t bestEnd = from;
    std::vector<std::pair<std::size_t, Evaluation>> winners;
    for (std::size_t index : order) {
      if (bound[index] <= from || bound[index] < bestEnd) break;
      const Orientation& o = scores[index].orientation;
      if (previous && o == *previous) continue;
      Evaluation e = evaluate(path, o, from, lifted, context);
      if (e.failure && e.failure->fatal) {
        plan.failure = e.failure;
        return plan;
      }
      if (e.end > bestEnd) {
        bestEnd = e.end;
        winners.clear();
      }
      if (e.end == bestEnd && e.end > from) winners.emplace_back(index, std::move(e));
      if (bestEnd == n) break;  // the first in today's order of those reaching the end
    }
    if (bestEnd == from) {
      // Refused as the step's own orientation refuses it, saying where the split got stuck.
      plan.failure = wholeStep;
      plan.failure->reason += "; re-orienting the part at a travel move does not help: no rotation about the nozzle "
                              "axis (every " + fixedText(path.options->rotationStepDegrees, 0) +
                              " deg) and arm configuration gets from line " + std::to_string(path.moves[from]->line) +
                              " to a later travel move";
      return plan;
    }
    // Of those that get equally far, the one today's choice ranks first over the run's own moves.
    std::size_t chosen = 0;
    if (winners.size() > 1 && bestEnd < n) {
      const std::vector<OrientationScore> own = scoreOrientations(path, runBox(path, from, bestEnd));
      for (std::size_t w = 1; w < winners.size(); ++w)
        if (betterOrientation(own[winners[w].first], own[winners[chosen].first])) chosen = w;
    }
    const Orientation o = scores[winners[chosen].first].orientation;
    plan.runs.push_back({o, from, bestEnd});
    lifted = winners[chosen].second.lifted;
    previous = o;
    from = bestEnd;
  }
  return plan;
}

}  // namespace multidir::robot::detail
