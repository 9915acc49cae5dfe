// Via points for joint moves: natural candidates first, then a seeded RRT-connect in joint space, shortcut.
// Every segment of every candidate goes through jointMoveCollision, the check every movej of the programs passes.
#include "joint_path_planner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>

#include "step_run.h"

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The part backed off the nozzle along its axis (beyond the step's own 30 mm) by these distances, in mm.
constexpr std::array<double, 4> kBackOffMm = {60.0, 120.0, 200.0, 300.0};
// The search: a fixed seed, this many joint sets at most, each tree grown by at most this turn of any joint at a
// time, within the joint limits and at most this far beyond the joints the move spans.
constexpr std::uint64_t kSearchSeed = 25;
constexpr int kSearchSamples = 2000;
constexpr double kSearchStepRad = 0.15;
constexpr double kSearchMarginRad = kPi / 2.0;

// The arm configuration (branch) of `q`: the IK solution of its own pose nearest it.
std::optional<int> branchOf(const ArmModel& arm, const Joints& q) {
  std::array<IkSolution, 8> solutions{};
  const int count = inverseKinematics(arm, forwardKinematics(arm, q), solutions);
  int branch = -1;
  if (!nearestWithinLimits(arm, solutions.data(), count, q, &branch)) return std::nullopt;
  return branch;
}

// `q` with the platform moved `mm` away from the nozzle along its axis (the orientation kept), on q's branch.
std::optional<Joints> backedOff(const Cell& cell, const Joints& q, double mm) {
  const std::optional<int> branch = branchOf(cell.arm, q);
  if (!branch) return std::nullopt;
  Eigen::Isometry3d tcp = platformPose(cell, q);
  tcp.pretranslate(-mm * cell.nozzleAxis.normalized());
  Joints out{};
  if (solveOnBranch(cell.arm, tcp * cell.flangeToPlatform.inverse(), *branch, q, out) != Solve::Ok) return std::nullopt;
  return out;
}

// Joints 1-3 from `big`, 4-6 from `wrists`.
Joints mixed(const Joints& big, const Joints& wrists) {
  return {big[0], big[1], big[2], wrists[3], wrists[4], wrists[5]};
}

struct Candidate {
  std::string method;
  std::vector<Joints> vias;
};

std::vector<Candidate> naturalCandidates(const Cell& cell, const Joints& from, const Joints& to) {
  std::vector<Candidate> list;
  const Joints wristsFirst = mixed(from, to), bigFirst = mixed(to, from);
  list.push_back({"the wrists first", {wristsFirst}});
  list.push_back({"the big joints first", {bigFirst}});
  for (const double mm : kBackOffMm) {
    const std::optional<Joints> offTo = backedOff(cell, to, mm), offFrom = backedOff(cell, from, mm);
    const std::string by = fixedText(mm, 0) + " mm";
    if (offTo) list.push_back({"backed off the nozzle " + by + " at the end", {*offTo}});
    if (offFrom) list.push_back({"backed off the nozzle " + by + " at the start", {*offFrom}});
    if (offTo && offFrom) list.push_back({"backed off the nozzle " + by + " at both ends", {*offFrom, *offTo}});
    if (offTo) list.push_back({"the wrists first, then backed off " + by, {mixed(from, *offTo), *offTo}});
    if (offTo) list.push_back({"the big joints first, then backed off " + by, {mixed(*offTo, from), *offTo}});
    if (offFrom) list.push_back({"backed off " + by + ", then the wrists first", {*offFrom, mixed(*offFrom, to)}});
    if (offFrom) list.push_back({"backed off " + by + ", then the big joints first", {*offFrom, mixed(to, *offFrom)}});
  }
  return list;
}

bool withinLimits(const ArmModel& arm, const Joints& q) {
  for (std::size_t j = 0; j < 6; ++j)
    if (q[j] < arm.limits[j].minRad || q[j] > arm.limits[j].maxRad) return false;
  return true;
}

// Every segment of from, vias..., to clear.
bool pathClear(const JointMoveScene& scene, const Joints& from, const std::vector<Joints>& vias, const Joints& to) {
  Joints at = from;
  for (const Joints& v : vias) {
    if (!withinLimits(scene.cell->arm, v) || !jointMoveCollision(scene, at, v).empty()) return false;
    at = v;
  }
  return jointMoveCollision(scene, at, to).empty();
}

double distance(const Joints& a, const Joints& b) {
  double s = 0.0;
  for (std::size_t j = 0; j < 6; ++j) s += (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(s);
}

// From `a` towards `b`, no joint turning more than kSearchStepRad.
Joints steer(const Joints& a, const Joints& b) {
  double worst = 0.0;
  for (std::size_t j = 0; j < 6; ++j) worst = std::max(worst, std::abs(b[j] - a[j]));
  if (worst <= kSearchStepRad) return b;
  Joints q{};
  for (std::size_t j = 0; j < 6; ++j) q[j] = a[j] + (b[j] - a[j]) * (kSearchStepRad / worst);
  return q;
}

struct Tree {
  std::vector<Joints> nodes;
  std::vector<int> parent;
  int nearest(const Joints& q) const {
    int best = 0;
    double bestDistance = distance(nodes[0], q);
    for (std::size_t i = 1; i < nodes.size(); ++i)
      if (const double d = distance(nodes[i], q); d < bestDistance) {
        bestDistance = d;
        best = static_cast<int>(i);
      }
    return best;
  }
  int add(const Joints& q, int from) {
    nodes.push_back(q);
    parent.push_back(from);
    return static_cast<int>(nodes.size()) - 1;
  }
  std::vector<Joints> chainToRoot(int i) const {  // node i first, the root last
    std::vector<Joints> chain;
    for (; i >= 0; i = parent[static_cast<std::size_t>(i)]) chain.push_back(nodes[static_cast<std::size_t>(i)]);
    return chain;
  }
};

// RRT-connect (Kuffner and LaValle 2000) from both ends; the joint path from `from` to `to`, ends included.
std::optional<std::vector<Joints>> search(const JointMoveScene& scene, const Joints& from, const Joints& to,
                                          int& drawn) {
  const ArmModel& arm = scene.cell->arm;
  std::array<double, 6> lo{}, hi{};
  for (std::size_t j = 0; j < 6; ++j) {
    lo[j] = std::max(arm.limits[j].minRad, std::min(from[j], to[j]) - kSearchMarginRad);
    hi[j] = std::min(arm.limits[j].maxRad, std::max(from[j], to[j]) + kSearchMarginRad);
  }
  // mt19937_64's sequence is fixed by the standard; the doubles are made from it here (the standard's
  // distributions may differ between libraries).
  std::mt19937_64 random(kSearchSeed);
  auto uniform = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  std::array<Tree, 2> trees;
  trees[0].add(from, -1);
  trees[1].add(to, -1);
  auto clear = [&scene](const Joints& a, const Joints& b) { return jointMoveCollision(scene, a, b).empty(); };
  for (drawn = 1; drawn <= kSearchSamples; ++drawn) {
    Joints sample{};
    for (std::size_t j = 0; j < 6; ++j) sample[j] = lo[j] + uniform() * (hi[j] - lo[j]);
    Tree& grown = trees[static_cast<std::size_t>(drawn % 2)];
    Tree& other = trees[static_cast<std::size_t>(1 - drawn % 2)];
    const int near = grown.nearest(sample);
    const Joints reached = steer(grown.nodes[static_cast<std::size_t>(near)], sample);
    if (!clear(grown.nodes[static_cast<std::size_t>(near)], reached)) continue;
    const int added = grown.add(reached, near);
    // The other tree grows towards it until it gets there or is blocked.
    int at = other.nearest(reached);
    while (true) {
      const Joints step = steer(other.nodes[static_cast<std::size_t>(at)], reached);
      if (!clear(other.nodes[static_cast<std::size_t>(at)], step)) break;
      at = other.add(step, at);
      if (step == reached) {
        std::vector<Joints> fromSide = trees[0].chainToRoot(&grown == &trees[0] ? added : at);
        std::vector<Joints> toSide = trees[1].chainToRoot(&grown == &trees[1] ? added : at);
        std::reverse(fromSide.begin(), fromSide.end());
        fromSide.insert(fromSide.end(), toSide.begin() + 1, toSide.end());  // the meeting point once
        return fromSide;
      }
    }
  }
  drawn = kSearchSamples;
  return std::nullopt;
}

// From each point the farthest later point it reaches clear, in order: the fewest vias the path allows greedily.
std::vector<Joints> shortcut(const JointMoveScene& scene, const std::vector<Joints>& path) {
  std::vector<Joints> kept{path.front()};
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t next = i + 1;
    for (std::size_t j = path.size() - 1; j > i + 1; --j)
      if (jointMoveCollision(scene, path[i], path[j]).empty()) {
        next = j;
        break;
      }
    kept.push_back(path[next]);
    i = next;
  }
  return kept;
}

}  // namespace

JointPathPlan planJointPath(const JointMoveScene& scene, const Joints& from, const Joints& to, bool allowVias) {
  JointPathPlan plan;
  plan.straightHit = jointMoveCollision(scene, from, to);
  if (plan.straightHit.empty()) {
    plan.found = true;
    plan.method = "straight";
    return plan;
  }
  if (!allowVias) return plan;
  for (const Candidate& c : naturalCandidates(*scene.cell, from, to)) {
    ++plan.candidatesTried;
    if (pathClear(scene, from, c.vias, to)) {
      plan.found = true;
      plan.method = c.method;
      plan.vias = c.vias;
      return plan;
    }
  }
  const std::optional<std::vector<Joints>> path = search(scene, from, to, plan.searchSamples);
  if (!path) return plan;
  const std::vector<Joints> shortest = shortcut(scene, *path);
  plan.found = true;
  plan.method = "search";
  plan.vias.assign(shortest.begin() + 1, shortest.end() - 1);
  return plan;
}

}  // namespace multidir::robot::detail
