// One run of a step on one orientation: the orientation is fixed within it, so the platform only translates and
// every move is a straight movel of the TCP on one arm configuration (branch).
#include "step_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "joint_move_check.h"

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
// Before the first move and after the last, the platform stands this far from the nozzle along its axis; a
// re-orientation lifts the part by the same.
constexpr double kRetreatMm = kStepApproachLiftMm;
// Below this much path between two poses the links' check stops splitting (docs/robot-cell.md, "Collisions").
constexpr double kFinestLinkSplitMm = 0.05;

double maxJointGap(const Joints& a, const Joints& b, int* joint = nullptr) {
  double worst = 0.0;
  for (int j = 0; j < 6; ++j) {
    const double gap = std::abs(a[static_cast<std::size_t>(j)] - b[static_cast<std::size_t>(j)]);
    if (gap > worst) {
      worst = gap;
      if (joint != nullptr) *joint = j;
    }
  }
  return worst;
}

double wristDegrees(const Joints& q) { return std::asin(std::min(1.0, std::abs(std::sin(q[4])))) / kDeg; }

bool insideCylinder(const CollisionCylinder& c, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - c.baseMm;
  const double h = d.dot(c.axis);
  if (h < 0.0 || h > c.lengthMm) return false;
  return (d - h * c.axis).norm() <= c.radiusMm;
}

Eigen::AlignedBox3d boxBounds(const CollisionBox& b) {
  Eigen::AlignedBox3d box;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner((i & 1 ? 0.5 : -0.5) * b.sizeMm.x(), (i & 2 ? 0.5 : -0.5) * b.sizeMm.y(),
                                 (i & 4 ? 0.5 : -0.5) * b.sizeMm.z());
    box.extend(b.pose * corner);
  }
  return box;
}

Eigen::AlignedBox3d cylinderBounds(const CollisionCylinder& c) {
  Eigen::AlignedBox3d box;
  box.extend(c.baseMm);
  box.extend(c.baseMm + c.lengthMm * c.axis);
  box.min().array() -= c.radiusMm;
  box.max().array() += c.radiusMm;
  return box;
}

const char* kindName(CarriedPoint::Kind kind) {
  switch (kind) {
    case CarriedPoint::Kind::Platform:
      return "the platform";
    case CarriedPoint::Kind::EarlierStep:
      return "the part printed in earlier steps";
    case CarriedPoint::Kind::ThisStep:
      return "this step's part";
  }
  return "the part";
}

// platformPoseFor with the turn (nozzle frame times the rotation about the axis) computed once per run.
Eigen::Isometry3d poseWithTurn(const Cell& cell, const Eigen::Isometry3d& platformToFile, const Eigen::Matrix3d& turn,
                               const Eigen::Vector3d& fileMm) {
  Eigen::Isometry3d fileToBase = Eigen::Isometry3d::Identity();
  fileToBase.linear() = turn;
  fileToBase.translation() = cell.nozzleTipMm - turn * fileMm;
  return fileToBase * platformToFile;
}

std::string describeArmHit(const Cell& cell, const Joints& q, const ArmClearance& c, const Eigen::Vector3d& f) {
  const std::string link = armLinkSolids(cell.arm, q)[static_cast<std::size_t>(c.link)].name;
  const std::string at = " with the nozzle at the part's (" + fixedText(f.x(), 2) + ", " + fixedText(f.y(), 2) + ", " +
                         fixedText(f.z(), 2) + ")";
  if (c.body == "the table")
    return "the arm's " + link + " would come within " + fixedText(cell.margins.tableClearanceMm, 1) +
           " mm of the table" + at + "; move the nozzle higher (nozzleTipMm) or the table lower";
  return "the arm's " + link + " would hit the extruder's body \"" + c.body + "\"" + at +
         "; move the body or the nozzle (multidir cell reach), or turn the step another way";
}

// The arm's links between two poses of a straight move: clear when the clearances at the ends add up to more than
// the most any link point can move between them (armMotionBoundMm), else split the path in two and look again,
// down to kFinestLinkSplitMm. The first hit, or an empty string.
std::string armLinksBetween(const Cell& cell, const Eigen::Isometry3d& platformToFile, const Eigen::Matrix3d& turn,
                            const Eigen::Isometry3d& platformToFlange, int branch, const Eigen::Vector3d& fa,
                            const Joints& qa, const ArmClearance& ca, const Eigen::Vector3d& fb, const Joints& qb,
                            const ArmClearance& cb) {
  if (cb.mm <= 0.0) return describeArmHit(cell, qb, cb, fb);
  if (ca.mm + cb.mm > armMotionBoundMm(cell.arm, qa, qb)) return {};
  if ((fb - fa).norm() < kFinestLinkSplitMm) return {};
  const Eigen::Vector3d fm = 0.5 * (fa + fb);
  Joints qm{};
  if (solveOnBranch(cell.arm, poseWithTurn(cell, platformToFile, turn, fm) * platformToFlange, branch, qa, qm) !=
      Solve::Ok)
    return {};  // the move's own samples report what is out of reach
  const ArmClearance cm = armClearance(cell, qm);
  if (cm.mm <= 0.0) return describeArmHit(cell, qm, cm, fm);
  std::string hit = armLinksBetween(cell, platformToFile, turn, platformToFlange, branch, fa, qa, ca, fm, qm, cm);
  if (hit.empty()) hit = armLinksBetween(cell, platformToFile, turn, platformToFlange, branch, fm, qm, cm, fb, qb, cb);
  return hit;
}

}  // namespace

std::string fixedText(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string s(buffer);
  if (s == "-0" || s.find_first_not_of("-0.") == std::string::npos) s = decimals > 0 ? "0." + std::string(static_cast<std::size_t>(decimals), '0') : "0";
  return s;
}

Solve solveOnBranch(const ArmModel& arm, const Eigen::Isometry3d& flange, int branch, const Joints& near,
                    Joints& out) {
  std::array<IkSolution, 8> solutions{};
  const int count = inverseKinematics(arm, flange, solutions);
  if (count == 0) return Solve::OutOfReach;
  for (int i = 0; i < count; ++i) {
    if (solutions[static_cast<std::size_t>(i)].branch != branch) continue;
    const auto chosen = nearestWithinLimits(arm, &solutions[static_cast<std::size_t>(i)], 1, near);
    if (!chosen) return Solve::BeyondLimits;
    out = *chosen;
    return Solve::Ok;
  }
  return Solve::OtherBranchOnly;
}

// The rotation about the nozzle axis and the branch: every corner of the box reachable on the branch within the
// limits, the least margin (each over the cell's minimum) the largest.
std::vector<OrientationScore> scoreOrientations(const StepPath& path, const Eigen::AlignedBox3d& box) {
  const Cell& cell = *path.cell;
  const ArmModel& arm = cell.arm;
  const CellMargins& margins = cell.margins;
  std::vector<OrientationScore> scores;
  const int rotations = std::max(1, static_cast<int>(std::lround(360.0 / path.options->rotationStepDegrees)));
  for (int r = 0; r < rotations; ++r) {
    const double rotation = r * path.options->rotationStepDegrees * kDeg;
    for (int branch = 0; branch < 8; ++branch) {
      int reached = 0;
      int clearCorners = 0;
      double score = std::numeric_limits<double>::infinity();
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d corner = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
        const Eigen::Isometry3d flange =
            platformPoseFor(cell, path.input->platformToFile, rotation, corner) * path.platformToFlange;
        Joints q{};
        if (solveOnBranch(arm, flange, branch, cell.home, q) != Solve::Ok) continue;
        if (!armOnTable(cell, q).empty()) continue;  // a configuration with its elbow under the table
        ++reached;
        if (armClearance(cell, q).mm > 0.0) ++clearCorners;  // no link in the extruder's body or on the table
        const double reach = reachMarginMm(arm, q) / std::max(margins.minReachMm, 1.0);
        const double wrist = wristDegrees(q) / std::max(margins.minWristDegrees, 1.0);
        score = std::min({score, reach, wrist});
      }
      OrientationScore s;
      s.orientation = {rotation, branch};
      s.reached = reached;
      s.clear = reached == 8 && clearCorners == 8;
      s.score = reached == 8 ? score : -std::numeric_limits<double>::infinity();
      scores.push_back(s);
    }
  }
  return scores;
}

bool betterOrientation(const OrientationScore& a, const OrientationScore& b) {
  if (a.reached != b.reached) return a.reached > b.reached;
  if (a.reached < 8) return false;
  if (a.clear != b.clear) return a.clear;
  return a.score > b.score;
}

const OrientationScore& bestOrientation(const std::vector<OrientationScore>& scores) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < scores.size(); ++i)
    if (betterOrientation(scores[i], scores[best])) best = i;
  return scores[best];
}

// The run's collision set-up: what the platform carries, in the files' frame, with the points that could touch a
// body or the table for some nozzle point within the step's swept bounds (the rest can never, the orientation
// being fixed within the run).
struct StepRun::Collisions {
  struct Candidate {
    Eigen::Vector3d fileMm;
    CarriedPoint::Kind kind;
  };
  struct Body {
    std::string name;
    bool box = true;
    Eigen::Isometry3d baseToBox = Eigen::Isometry3d::Identity();  // boxes
    Eigen::Vector3d halfSizeMm = Eigen::Vector3d::Zero();
    CollisionCylinder cylinder;                                    // cylinders
    // The body's extent along the nozzle axis from the tip: a point is inside only if its height above the tip,
    // the files' z difference (the axis is the files' +Z), lies within; the one comparison that rules most out.
    double axisMinMm = 0.0, axisMaxMm = 0.0;
    std::vector<Candidate> candidates;
  };
  std::vector<Body> bodies;
  std::vector<Candidate> nearTable;
};

StepRun::StepRun(const StepPath& path, Orientation orientation, bool keep)
    : m_path(path), m_orientation(orientation), m_keep(keep), m_collisions(std::make_unique<Collisions>()) {
  const Cell& cell = *path.cell;
  m_turn = nozzleFrame(cell.nozzleAxis) * Eigen::AngleAxisd(orientation.rotationRad, Eigen::Vector3d::UnitZ());
  m_stats.reachMarginMm = std::numeric_limits<double>::infinity();
  m_stats.wristMarginDegrees = std::numeric_limits<double>::infinity();
  // Collision candidates: per body, the points that could meet it for some nozzle point within the bounds.
  Collisions& collisions = *m_collisions;
  for (const auto& b : cell.boxes) {
    Collisions::Body body;
    body.name = b.name;
    body.baseToBox = b.pose.inverse();
    body.halfSizeMm = b.sizeMm / 2;
    collisions.bodies.push_back(body);
  }
  for (const auto& c : cell.cylinders) {
    Collisions::Body body;
    body.name = c.name;
    body.box = false;
    body.cylinder = c;
    collisions.bodies.push_back(body);
  }
  std::vector<Eigen::AlignedBox3d> bodyBounds;
  for (const auto& b : cell.boxes) bodyBounds.push_back(boxBounds(b));
  for (const auto& c : cell.cylinders) bodyBounds.push_back(cylinderBounds(c));
  for (std::size_t b = 0; b < bodyBounds.size(); ++b) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int c = 0; c < 8; ++c) {
      const double h = (bodyBounds[b].corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - cell.nozzleTipMm)
                           .dot(cell.nozzleAxis);
      low = std::min(low, h);
      high = std::max(high, h);
    }
    collisions.bodies[b].axisMinMm = low;
    collisions.bodies[b].axisMaxMm = high;
  }
  const Eigen::AlignedBox3d& bounds = path.sweptBounds;
  for (const auto& p : path.input->carried) {
    const Eigen::Vector3d s = path.input->platformToFile * p.platformMm;
    // world = tip + turn (s - f), f within bounds
    Eigen::AlignedBox3d swept;
    for (int c = 0; c < 8; ++c)
      swept.extend(cell.nozzleTipMm + m_turn * (s - bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c))));
    for (std::size_t b = 0; b < bodyBounds.size(); ++b)
      if (swept.intersects(bodyBounds[b])) collisions.bodies[b].candidates.push_back({s, p.kind});
    if (swept.min().z() < cell.tableZMm + cell.margins.tableClearanceMm) collisions.nearTable.push_back({s, p.kind});
  }
  // Sorted by height, so a sample tests only the candidates within the body's extent along the axis.
  for (auto& body : collisions.bodies)
    std::sort(body.candidates.begin(), body.candidates.end(),
              [](const Collisions::Candidate& a, const Collisions::Candidate& b) { return a.fileMm.z() < b.fileMm.z(); });
}

StepRun::~StepRun() = default;

RunFailure StepRun::failure(std::size_t move, const std::string& reason, bool fatal) const {
  return RunFailure{move, m_path.moves[move]->line, reason, fatal};
}

// A collision at nozzle point f (files' frame), or an empty string.
std::string StepRun::collisionAt(const Eigen::Vector3d& f) const {
  const Cell& cell = *m_path.cell;
  auto inNozzleZone = [&](const Eigen::Vector3d& world) {
    const Eigen::Vector3d d = world - cell.nozzleTipMm;
    const double h = d.dot(cell.nozzleAxis);
    return h <= cell.nozzleZoneHeightMm && (d - h * cell.nozzleAxis).norm() <= cell.nozzleZoneRadiusMm;
  };
  auto where = [](const Eigen::Vector3d& w) {
    return "(at base x " + fixedText(w.x(), 1) + " y " + fixedText(w.y(), 1) + " z " + fixedText(w.z(), 1) + " mm)";
  };
  for (const auto& body : m_collisions->bodies) {
    const auto first = std::lower_bound(
        body.candidates.begin(), body.candidates.end(), f.z() + body.axisMinMm,
        [](const Collisions::Candidate& c, double z) { return c.fileMm.z() < z; });
    for (auto it = first; it != body.candidates.end(); ++it) {
      const Collisions::Candidate& c = *it;
      const double height = c.fileMm.z() - f.z();
      if (height > body.axisMaxMm) break;
      if (c.kind == CarriedPoint::Kind::ThisStep && height > 1e-6) continue;  // not printed yet
      const Eigen::Vector3d world = cell.nozzleTipMm + m_turn * (c.fileMm - f);
      bool inside = false;
      if (body.box) {
        const Eigen::Vector3d local = body.baseToBox * world;
        inside = (local.cwiseAbs().array() <= body.halfSizeMm.array()).all();
      } else {
        inside = insideCylinder(body.cylinder, world);
      }
      if (inside && !inNozzleZone(world))
        return std::string(kindName(c.kind)) + " would hit the extruder's body \"" + body.name + "\" " + where(world) +
               (c.kind == CarriedPoint::Kind::Platform
                    ? "; a platform larger than the plan's platform region swings into the extruder on tilted "
                      "steps: decompose with the machine's platformRadiusMm set to the cell's platformRadiusMm"
                    : "");
    }
  }
  for (const auto& c : m_collisions->nearTable) {
    if (c.kind == CarriedPoint::Kind::ThisStep && c.fileMm.z() > f.z() + 1e-6) continue;
    const Eigen::Vector3d world = cell.nozzleTipMm + m_turn * (c.fileMm - f);
    if (world.z() < cell.tableZMm + cell.margins.tableClearanceMm)
      return std::string(kindName(c.kind)) + " would come within " + fixedText(cell.margins.tableClearanceMm, 1) +
             " mm of the table " + where(world) + ", table at z " + fixedText(cell.tableZMm, 1) +
             "; move the nozzle higher (nozzleTipMm) or the table lower";
  }
  return {};
}

std::optional<RunFailure> StepRun::startAtApproach() {
  const Cell& cell = *m_path.cell;
  const Eigen::Isometry3d approachTcp =
      platformPoseFor(cell, m_path.input->platformToFile, m_orientation.rotationRad, m_path.approach);
  switch (solveOnBranch(cell.arm, approachTcp * m_path.platformToFlange, m_orientation.branch, cell.home, m_joints)) {
    case Solve::Ok:
      break;
    case Solve::BeyondLimits:
      return failure(0, "the step's first point, " + fixedText(kRetreatMm, 0) +
                            " mm off the nozzle, needs a joint beyond the cell's joint limits (jointLimitsDegrees) with "
                            "any rotation about the nozzle axis");
    default:
      return failure(0, "the step's first point, " + fixedText(kRetreatMm, 0) +
                            " mm off the nozzle, is out of the arm's reach with any rotation about the nozzle axis; "
                            "move the nozzle (multidir cell reach) or scale the part down");
  }
  m_startJoints = m_joints;
  m_lastClearance = armClearance(cell, m_joints);
  std::string hit = armOnTable(cell, m_joints);
  if (hit.empty() && m_lastClearance.mm <= 0.0) hit = describeArmHit(cell, m_joints, m_lastClearance, m_path.approach);
  if (!hit.empty()) return failure(0, hit);
  m_current = m_path.approach;
  return std::nullopt;
}

std::optional<RunFailure> StepRun::startAfterTurn(std::size_t first, const Joints& liftedJoints) {
  const Cell& cell = *m_path.cell;
  const Eigen::Vector3d point = m_path.points[first];
  const Eigen::Vector3d lifted = point + Eigen::Vector3d(0, 0, kRetreatMm);
  const Eigen::Isometry3d tcp = poseWithTurn(cell, m_path.input->platformToFile, m_turn, lifted);
  switch (solveOnBranch(cell.arm, tcp * m_path.platformToFlange, m_orientation.branch, liftedJoints, m_joints)) {
    case Solve::Ok:
      break;
    case Solve::BeyondLimits:
      return failure(first, "turned about the nozzle axis off the part, the pose needs a joint beyond the cell's "
                            "joint limits (jointLimitsDegrees)");
    default:
      return failure(first, "turned about the nozzle axis off the part, the platform is out of the arm's reach");
  }
  m_startJoints = m_joints;
  m_lastClearance = armClearance(cell, m_joints);
  std::string hit = armOnTable(cell, m_joints);
  if (hit.empty()) hit = collisionAt(lifted);
  if (hit.empty()) {
    const JointMoveScene scene{&cell, &m_path.input->carried, m_path.input->platformToFile, m_path.points[first - 1].z()};
    hit = jointMoveCollision(scene, liftedJoints, m_joints);
    if (!hit.empty()) hit += " while the platform turns about the nozzle axis";
  }
  if (!hit.empty()) return failure(first, hit);
  m_current = lifted;
  if (m_keep) {
    Converted c;
    c.line = m_path.moves[first]->line;
    c.fileMm = lifted;
    c.tcp = tcp;
    c.turn = true;
    c.turnFrom = liftedJoints;
    c.turnTo = m_joints;
    if (m_path.input->recordMotion) m_motion.push_back({c.line, lifted, tcp.translation(), m_joints, false});
    m_converted.push_back(std::move(c));
  }
  // Down onto the nozzle at the travel's end.
  return straightTo(point, first, m_path.moves[first]->line);
}

std::optional<RunFailure> StepRun::liftOff(std::size_t last) {
  return straightTo(m_path.points[last] + Eigen::Vector3d(0, 0, kRetreatMm), last, m_path.moves[last]->line);
}

// A straight travel of the nozzle's point to `target` (a lift or a descent), checked as a move is.
std::optional<RunFailure> StepRun::straightTo(const Eigen::Vector3d& target, std::size_t move, int line) {
  const double requested = m_path.cell->motion.travelSpeedMmPerS;
  double load = 0.0;
  int loadJoint = 0;
  Eigen::Isometry3d endTcp = Eigen::Isometry3d::Identity();
  const std::string hit = followTo(target, requested, load, loadJoint, endTcp);
  if (!hit.empty()) return failure(move, hit);
  convertLine(target, line, false, 0.0, requested, load, loadJoint, endTcp);
  return std::nullopt;
}

// Samples along the way from the current point to `target`: reach, branch, limits, jumps, margins, collisions,
// joint speeds at `requested` (the most any joint asks of its limit: `load`). The first problem, or "".
std::string StepRun::followTo(const Eigen::Vector3d& target, double requested, double& load, int& loadJoint,
                              Eigen::Isometry3d& endTcp) {
  const Cell& cell = *m_path.cell;
  const ArmModel& arm = cell.arm;
  const CellMargins& margins = cell.margins;
  const double jointStepLimit = margins.maxJointStepDegrees * kDeg;
  const double length = (target - m_current).norm();
  const int samples = std::max(1, static_cast<int>(std::ceil(length / m_path.options->sampleMm)));
  load = 0.0;
  loadJoint = 0;
  for (int s = 1; s <= samples; ++s) {
    const Eigen::Vector3d f = m_current + (target - m_current) * (static_cast<double>(s) / samples);
    const Eigen::Isometry3d tcp = poseWithTurn(cell, m_path.input->platformToFile, m_turn, f);
    const Eigen::Isometry3d flange = tcp * m_path.platformToFlange;
    Joints q{};
    switch (solveOnBranch(arm, flange, m_orientation.branch, m_joints, q)) {
      case Solve::Ok:
        break;
      case Solve::OutOfReach:
        return "the platform pose for nozzle point (" + fixedText(f.x(), 2) + ", " + fixedText(f.y(), 2) + ", " +
               fixedText(f.z(), 2) + ") is out of the arm's reach; move the nozzle (multidir cell reach) or scale the "
               "part down";
      case Solve::OtherBranchOnly:
        return "unreachable on the step's arm configuration (branch " + std::to_string(m_orientation.branch) +
               "): only another configuration reaches it, and changing it mid-step is a wrist or elbow flip; move the "
               "nozzle or split the step";
      case Solve::BeyondLimits:
        return "the pose needs a joint beyond the cell's joint limits (jointLimitsDegrees)";
    }
    int jumpJoint = 0;
    const double jump = maxJointGap(q, m_joints, &jumpJoint);
    if (jump > jointStepLimit)
      return "joint " + std::to_string(jumpJoint + 1) + " jumps " + fixedText(jump / kDeg, 1) + " deg within " +
             fixedText(length / samples, 1) + " mm of path (over the cell's " + fixedText(margins.maxJointStepDegrees, 1) +
             " deg, margins.maxJointStepDegrees): a wrist flip near a singularity";
    const double reach = reachMarginMm(arm, q);
    const double wrist = wristDegrees(q);
    m_stats.reachMarginMm = std::min(m_stats.reachMarginMm, reach);
    m_stats.wristMarginDegrees = std::min(m_stats.wristMarginDegrees, wrist);
    if (reach < margins.minReachMm)
      return "reach margin " + fixedText(reach, 1) + " mm, under the cell's " + fixedText(margins.minReachMm, 1) +
             " mm (margins.minReachMm): the arm is near the edge of its workspace or the shoulder singularity";
    if (wrist < margins.minWristDegrees)
      return "wrist 2 at " + fixedText(wrist, 1) + " deg from the wrist singularity, under the cell's " +
             fixedText(margins.minWristDegrees, 1) + " deg (margins.minWristDegrees)";
    std::string hit = collisionAt(f);
    if (hit.empty()) hit = armOnTable(cell, q);
    if (hit.empty()) {
      const ArmClearance clearance = armClearance(cell, q);
      const Eigen::Vector3d before = m_current + (target - m_current) * (static_cast<double>(s - 1) / samples);
      hit = armLinksBetween(cell, m_path.input->platformToFile, m_turn, m_path.platformToFlange, m_orientation.branch,
                            before, m_joints, m_lastClearance, f, q, clearance);
      m_lastClearance = clearance;
    }
    if (!hit.empty()) return hit;
    const double seconds = (length / samples) / requested;
    for (int j = 0; j < 6; ++j) {
      const double speed = std::abs(q[static_cast<std::size_t>(j)] - m_joints[static_cast<std::size_t>(j)]) / seconds;
      const double ratio = speed / arm.limits[static_cast<std::size_t>(j)].maxSpeedRadPerS;
      if (ratio > load) {
        load = ratio;
        loadJoint = j;
      }
    }
    m_joints = q;
    if (s == samples) endTcp = tcp;
  }
  return {};
}

// The move to `target` converted: its speed (slowed where a joint or the extruder cannot follow) and filament.
void StepRun::convertLine(const Eigen::Vector3d& target, int line, bool extrudes, double filamentMm, double requested,
                          double load, int loadJoint, const Eigen::Isometry3d& endTcp) {
  const Cell& cell = *m_path.cell;
  const double length = (target - m_current).norm();
  Converted c;
  c.line = line;
  c.fileMm = target;
  c.lengthMm = length;
  c.extrudes = extrudes;
  c.tcp = endTcp;
  if (m_keep && m_path.input->recordMotion)
    m_motion.push_back({line, target, c.tcp.translation(), m_joints, c.extrudes});
  if (load > m_stats.worstLoad) {
    m_stats.worstLoad = load;
    m_stats.worstLoadJoint = loadJoint;
  }
  double speed = requested;
  if (c.extrudes) {
    const double filamentSpeed = filamentMm / length * requested;
    load = std::max(load, filamentSpeed / cell.maxFilamentMmPerS);
  }
  if (load > 1.0) {
    speed = requested / load;
    ++m_stats.slowdowns;
    m_stats.slowdownSeconds += trapezoidSeconds(length, speed, cell.motion.toolAccelMmPerS2) -
                               trapezoidSeconds(length, requested, cell.motion.toolAccelMmPerS2);
  }
  // The written values, rounded as written, so the program's filament is what the controller will drive.
  speed = std::stod(fixedText(speed / 1000.0, 6)) * 1000.0;
  c.speedMmPerS = speed;
  if (c.extrudes) c.filamentMm = filamentMm;
  m_stats.gcodeFilamentMm += c.extrudes ? filamentMm : 0.0;
  if (m_keep) m_converted.push_back(std::move(c));
  m_current = target;
}

std::optional<RunFailure> StepRun::advance(std::size_t i, const core::JobContext& context) {
  if ((i & 4095) == 0 && context.isCancelled()) return failure(i, "cancelled", true);
  const slicing::GcodeMove& move = *m_path.moves[i];
  const Eigen::Vector3d target = m_path.points[i];
  const std::size_t lineIndex = static_cast<std::size_t>(move.line);
  const auto& feeds = m_path.side->feedMmPerMinByLine;
  const double feed = lineIndex < feeds.size() ? feeds[lineIndex] : 0.0;
  double requested = m_path.cell->motion.travelSpeedMmPerS;
  if (move.extrudes()) {
    if (!(feed > 0.0)) return failure(i, "an extrusion with no feed rate (F) in effect", true);
    requested = feed / 60.0;
  }
  double load = 0.0;
  int loadJoint = 0;
  Eigen::Isometry3d endTcp = Eigen::Isometry3d::Identity();
  const std::string hit = followTo(target, requested, load, loadJoint, endTcp);
  if (!hit.empty()) return failure(i, hit);
  convertLine(target, move.line, move.extrudes(), move.filamentMm, requested, load, loadJoint, endTcp);
  return std::nullopt;
}

std::optional<RunFailure> StepRun::retreat() {
  const Cell& cell = *m_path.cell;
  const std::size_t last = m_path.moves.size() - 1;
  Converted back;
  back.line = m_path.moves.back()->line;
  back.fileMm = m_path.retreat;
  back.lengthMm = (m_path.retreat - m_current).norm();
  back.speedMmPerS = cell.motion.travelSpeedMmPerS;
  back.tcp = platformPoseFor(cell, m_path.input->platformToFile, m_orientation.rotationRad, m_path.retreat);
  Joints retreatJoints{};
  if (solveOnBranch(cell.arm, back.tcp * m_path.platformToFlange, m_orientation.branch, m_joints, retreatJoints) !=
      Solve::Ok)
    return failure(last, "the platform cannot back " + fixedText(kRetreatMm, 0) + " mm off the nozzle after the step");
  const std::string hit =
      armLinksBetween(cell, m_path.input->platformToFile, m_turn, m_path.platformToFlange, m_orientation.branch,
                      m_current, m_joints, m_lastClearance, m_path.retreat, retreatJoints,
                      armClearance(cell, retreatJoints));
  if (!hit.empty()) return failure(last, hit);
  m_joints = retreatJoints;
  m_current = m_path.retreat;
  if (m_keep) m_converted.push_back(std::move(back));
  return std::nullopt;
}

StepRun::State StepRun::state() const {
  return State{m_current, m_joints, m_lastClearance, m_stats.reachMarginMm, m_stats.wristMarginDegrees};
}

void StepRun::restore(const State& state) {
  m_current = state.current;
  m_joints = state.joints;
  m_lastClearance = state.lastClearance;
  m_stats.reachMarginMm = state.reachMarginMm;
  m_stats.wristMarginDegrees = state.wristMarginDegrees;
}

}  // namespace multidir::robot::detail
