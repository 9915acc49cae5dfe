// One step to one URScript program. The step's orientation is fixed (its pose and the rotation about the
// nozzle axis chosen once), so the platform only translates while the step prints: every move is a straight
// movel of the TCP, and the arm stays on one configuration (branch) throughout.
#include "step_converter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "gcode_events.h"
#include "multidir/robot/arm_links.h"
#include "multidir/slicing/gcode_program.h"

namespace multidir::robot::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
// analog out 1: nozzle temperature as a fraction of this (the extruder controller's convention).
constexpr double kTemperatureFullScaleC = 300.0;
// M109 waits until analog in 0 reads this much below the set point.
constexpr double kHeatWaitBelowC = 2.0;
// Before the first move and after the last, the platform stands this far from the nozzle along its axis.
constexpr double kRetreatMm = kStepApproachLiftMm;

struct Converted {
  int line = 0;
  Eigen::Vector3d fileMm;        // the nozzle's point, files' frame
  Eigen::Isometry3d tcp;         // platform pose, base frame
  double lengthMm = 0.0;
  double speedMmPerS = 0.0;      // after any slowdown
  double filamentMm = 0.0;       // the G-code's E of this move
  bool extrudes = false;
  std::vector<std::string> before;  // statements to write before the movel (outputs, messages)
};

double trapezoidSeconds(double distance, double speed, double accel) {
  if (distance <= 0.0) return 0.0;
  if (distance >= speed * speed / accel) return distance / speed + speed / accel;
  return 2.0 * std::sqrt(distance / accel);
}

std::string number(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string s(buffer);
  if (s == "-0" || s.find_first_not_of("-0.") == std::string::npos) s = decimals > 0 ? "0." + std::string(static_cast<std::size_t>(decimals), '0') : "0";
  return s;
}

std::string poseText(const Eigen::Isometry3d& pose) {
  const Eigen::AngleAxisd turn(pose.linear());
  const Eigen::Vector3d rv = turn.axis() * turn.angle();
  const Eigen::Vector3d t = pose.translation() / 1000.0;
  return "p[" + number(t.x(), 7) + ", " + number(t.y(), 7) + ", " + number(t.z(), 7) + ", " + number(rv.x(), 7) +
         ", " + number(rv.y(), 7) + ", " + number(rv.z(), 7) + "]";
}

std::string jointsText(const Joints& q) {
  std::string s = "[";
  for (int j = 0; j < 6; ++j) s += (j ? ", " : "") + number(q[static_cast<std::size_t>(j)], 7);
  return s + "]";
}

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

std::string fixed(double v, int decimals) { return number(v, decimals); }

// The solution of `branch` for the flange pose, turned to lie nearest `near` within the limits.
enum class Solve { Ok, OutOfReach, OtherBranchOnly, BeyondLimits };
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

double wristDegrees(const Joints& q) { return std::asin(std::min(1.0, std::abs(std::sin(q[4])))) / kDeg; }

// The step's collision set-up: what the platform carries, in the files' frame, with the points that could
// touch a body or the table anywhere within the step's bounds (the rest can never, the orientation being fixed).
struct CollisionSet {
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

}  // namespace

// The arm's joint housings (the DH origins from the elbow to the flange) held above the table by the table
// clearance plus this radius, an estimate of the housings' size (not a published figure): about 80 mm across on
// the UR3s, 100 mm on the UR5s, 120 mm on the larger arms. docs/robot-cell.md, "Collisions".
double housingRadiusMm(const ArmModel& arm) {
  const double reach = std::abs(arm.a[1]) + std::abs(arm.a[2]);
  if (reach < 600.0) return 40.0;
  if (reach < 900.0) return 50.0;
  return 60.0;
}

namespace {
const char* const kJointNames[] = {"shoulder", "elbow", "wrist 1", "wrist 2", "wrist 3", "flange"};
}  // namespace

// The first joint housing (elbow to flange) that comes down on the table, or an empty string.
std::string armOnTable(const Cell& cell, const Joints& q) {
  const ArmModel& arm = cell.arm;
  const double floor = cell.tableZMm + cell.margins.tableClearanceMm + housingRadiusMm(arm);
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  for (std::size_t j = 0; j < 6; ++j) {
    const double ct = std::cos(q[j]), st = std::sin(q[j]), ca = std::cos(arm.alpha[j]), sa = std::sin(arm.alpha[j]);
    Eigen::Matrix4d m;
    m << ct, -st * ca, st * sa, arm.a[j] * ct, st, ct * ca, -ct * sa, arm.a[j] * st, 0.0, sa, ca, arm.d[j], 0.0, 0.0,
        0.0, 1.0;
    t = t * m;
    if (j >= 1 && t(2, 3) < floor) {
      char text[160];
      std::snprintf(text, sizeof text, "the arm's %s would come down to z %.1f mm, within %.1f mm of the table (its housing "
                    "about %.0f mm, the clearance %.1f mm)", kJointNames[j], t(2, 3), t(2, 3) - cell.tableZMm,
                    housingRadiusMm(arm), cell.margins.tableClearanceMm);
      return text;
    }
  }
  return {};
}

Eigen::Matrix3d nozzleFrame(const Eigen::Vector3d& axisIn) {
  const Eigen::Vector3d axis = axisIn.normalized();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX() - axis.x() * axis;
  if (u.norm() < 1e-6) u = Eigen::Vector3d::UnitY() - axis.y() * axis;
  u.normalize();
  Eigen::Matrix3d frame;
  frame.col(0) = u;
  frame.col(1) = axis.cross(u);
  frame.col(2) = axis;
  return frame;
}

namespace {

// platformPoseFor with the turn (nozzle frame times the rotation about the axis) computed once per step.
Eigen::Isometry3d poseWithTurn(const Cell& cell, const Eigen::Isometry3d& platformToFile, const Eigen::Matrix3d& turn,
                               const Eigen::Vector3d& fileMm) {
  Eigen::Isometry3d fileToBase = Eigen::Isometry3d::Identity();
  fileToBase.linear() = turn;
  fileToBase.translation() = cell.nozzleTipMm - turn * fileMm;
  return fileToBase * platformToFile;
}

// Below this much path between two poses the links' check stops splitting (docs/robot-cell.md, "Collisions").
constexpr double kFinestLinkSplitMm = 0.05;

std::string describeArmHit(const Cell& cell, const Joints& q, const ArmClearance& c, const Eigen::Vector3d& f) {
  const std::string link = armLinkSolids(cell.arm, q)[static_cast<std::size_t>(c.link)].name;
  const std::string at = " with the nozzle at the part's (" + fixed(f.x(), 2) + ", " + fixed(f.y(), 2) + ", " +
                         fixed(f.z(), 2) + ")";
  if (c.body == "the table")
    return "the arm's " + link + " would come within " + fixed(cell.margins.tableClearanceMm, 1) +
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

Eigen::Isometry3d platformPoseFor(const Cell& cell, const Eigen::Isometry3d& platformToFile, double rotationRad,
                                  const Eigen::Vector3d& fileMm) {
  const Eigen::Matrix3d turn = nozzleFrame(cell.nozzleAxis) * Eigen::AngleAxisd(rotationRad, Eigen::Vector3d::UnitZ());
  // Files' frame to base: the point `fileMm` onto the tip, +Z along the axis.
  Eigen::Isometry3d fileToBase = Eigen::Isometry3d::Identity();
  fileToBase.linear() = turn;
  fileToBase.translation() = cell.nozzleTipMm - turn * fileMm;
  return fileToBase * platformToFile;
}

double reachMarginMm(const ArmModel& arm, const Joints& q) {
  const double a2 = std::abs(arm.a[1]), a3 = std::abs(arm.a[2]);
  const double rho = std::sqrt(std::max(0.0, arm.a[1] * arm.a[1] + arm.a[2] * arm.a[2] +
                                                 2.0 * arm.a[1] * arm.a[2] * std::cos(q[2])));
  const double outer = a2 + a3 - rho;
  const double inner = rho - std::abs(a2 - a3);
  return std::min({outer, inner, singularityMargins(arm, q).shoulderMm});
}

StepOutput convertStep(const StepInput& input, const Cell& cell, const RobotProgramOptions& options,
                       const core::JobContext& context) {
  StepOutput out;
  RobotStepSummary& summary = out.summary;
  summary.step = input.step;
  summary.slicerSeconds = input.slicerSeconds;
  char programName[32];
  std::snprintf(programName, sizeof programName, "step-%02d.script", input.step);
  summary.program = programName;
  const std::string stepText = "step " + std::to_string(input.step);
  auto refuse = [&](int line, const std::string& why) {
    if (out.refusals.empty()) out.refusalLine = line;
    out.refusals.push_back(stepText + (line > 0 ? ", line " + std::to_string(line) : std::string()) + " (" +
                           input.gcodeFile + "): " + why);
  };

  auto side = scanGcodeSideInfo(input.gcode, input.gcodeFile);
  if (!side) {
    refuse(0, side.error().message);
    return out;
  }
  auto program = slicing::parseGcode(input.gcode, "A", input.gcodeFile);
  if (!program) {
    refuse(0, program.error().message);
    return out;
  }
  std::vector<const slicing::GcodeMove*> moves;
  for (const auto& m : program->moves) {
    if (m.commandsRotaryAxis) {
      refuse(m.line, "the program turns a platform axis; the cell has none: slice with the cell's profile "
                     "(resources/printers/ur5-cell-0.8.ini)");
      return out;
    }
    if (m.movesXy() || m.movesZ()) moves.push_back(&m);
  }
  if (moves.empty()) {
    refuse(0, "the program moves nowhere");
    return out;
  }
  auto fileOf = [&](const slicing::GcodeMove& m) -> Eigen::Vector3d { return m.to - input.printerOffsetMm; };
  const Eigen::Vector3d firstPoint = fileOf(*moves.front());
  const Eigen::Vector3d lastPoint = fileOf(*moves.back());
  const Eigen::Vector3d approach = firstPoint + Eigen::Vector3d(0, 0, kRetreatMm);
  const Eigen::Vector3d retreat = lastPoint + Eigen::Vector3d(0, 0, kRetreatMm);
  Eigen::AlignedBox3d bounds(approach);
  bounds.extend(retreat);
  for (const auto* m : moves) bounds.extend(fileOf(*m));

  const ArmModel& arm = cell.arm;
  const Eigen::Isometry3d platformToFlange = cell.flangeToPlatform.inverse();
  const CellMargins& margins = cell.margins;

  // The rotation about the nozzle axis and the branch: every corner of the step's bounds reachable on the
  // branch within the limits, the least margin (each over the cell's minimum) the largest.
  double bestScore = -std::numeric_limits<double>::infinity();
  int bestReached = -1;
  bool bestClear = false;
  double bestRotation = 0.0;
  int bestBranch = 0;
  const int rotations = std::max(1, static_cast<int>(std::lround(360.0 / options.rotationStepDegrees)));
  for (int r = 0; r < rotations; ++r) {
    const double rotation = r * options.rotationStepDegrees * kDeg;
    for (int branch = 0; branch < 8; ++branch) {
      int reached = 0;
      int clearCorners = 0;
      double score = std::numeric_limits<double>::infinity();
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d corner = bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
        const Eigen::Isometry3d flange = platformPoseFor(cell, input.platformToFile, rotation, corner) * platformToFlange;
        Joints q{};
        if (solveOnBranch(arm, flange, branch, cell.home, q) != Solve::Ok) continue;
        if (!armOnTable(cell, q).empty()) continue;  // a configuration with its elbow under the table
        ++reached;
        if (armClearance(cell, q).mm > 0.0) ++clearCorners;  // no link in the extruder's body or on the table
        const double reach = reachMarginMm(arm, q) / std::max(margins.minReachMm, 1.0);
        const double wrist = wristDegrees(q) / std::max(margins.minWristDegrees, 1.0);
        score = std::min({score, reach, wrist});
      }
      // Reaching every corner first, then the arm's links clear of the bodies at every corner, then the margin.
      const bool clear = reached == 8 && clearCorners == 8;
      if (reached == 8 ? (bestReached < 8 || (clear && !bestClear) || (clear == bestClear && score > bestScore))
                       : (bestReached < 8 && reached > bestReached)) {
        bestReached = reached;
        bestClear = clear;
        bestScore = reached == 8 ? score : bestScore;
        bestRotation = rotation;
        bestBranch = branch;
      }
    }
  }
  summary.rotationDegrees = bestRotation / kDeg;
  summary.branch = bestBranch;
  const Eigen::Matrix3d nozzleTurn =
      nozzleFrame(cell.nozzleAxis) * Eigen::AngleAxisd(bestRotation, Eigen::Vector3d::UnitZ());
  out.platformRotation = nozzleTurn * input.platformToFile.linear();

  // Collision candidates: per body, the points that could meet it for some nozzle point within the bounds.
  CollisionSet collisions;
  for (const auto& b : cell.boxes) {
    CollisionSet::Body body;
    body.name = b.name;
    body.baseToBox = b.pose.inverse();
    body.halfSizeMm = b.sizeMm / 2;
    collisions.bodies.push_back(body);
  }
  for (const auto& c : cell.cylinders) {
    CollisionSet::Body body;
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
  for (const auto& p : input.carried) {
    const Eigen::Vector3d s = input.platformToFile * p.platformMm;
    // world = tip + turn (s - f), f within bounds
    Eigen::AlignedBox3d swept;
    for (int c = 0; c < 8; ++c)
      swept.extend(cell.nozzleTipMm + nozzleTurn * (s - bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c))));
    for (std::size_t b = 0; b < bodyBounds.size(); ++b)
      if (swept.intersects(bodyBounds[b])) collisions.bodies[b].candidates.push_back({s, p.kind});
    if (swept.min().z() < cell.tableZMm + margins.tableClearanceMm) collisions.nearTable.push_back({s, p.kind});
  }
  // Sorted by height, so a sample tests only the candidates within the body's extent along the axis.
  for (auto& body : collisions.bodies)
    std::sort(body.candidates.begin(), body.candidates.end(),
              [](const CollisionSet::Candidate& a, const CollisionSet::Candidate& b) { return a.fileMm.z() < b.fileMm.z(); });
  auto inNozzleZone = [&](const Eigen::Vector3d& world) {
    const Eigen::Vector3d d = world - cell.nozzleTipMm;
    const double h = d.dot(cell.nozzleAxis);
    return h <= cell.nozzleZoneHeightMm && (d - h * cell.nozzleAxis).norm() <= cell.nozzleZoneRadiusMm;
  };
  auto where = [](const Eigen::Vector3d& w) {
    return "(at base x " + fixed(w.x(), 1) + " y " + fixed(w.y(), 1) + " z " + fixed(w.z(), 1) + " mm)";
  };
  // A collision at nozzle point f (files' frame), or an empty string.
  auto collisionAt = [&](const Eigen::Vector3d& f, const Eigen::Isometry3d& flange) -> std::string {
    for (const auto& body : collisions.bodies) {
      const auto first = std::lower_bound(
          body.candidates.begin(), body.candidates.end(), f.z() + body.axisMinMm,
          [](const CollisionSet::Candidate& c, double z) { return c.fileMm.z() < z; });
      for (auto it = first; it != body.candidates.end(); ++it) {
        const CollisionSet::Candidate& c = *it;
        const double height = c.fileMm.z() - f.z();
        if (height > body.axisMaxMm) break;
        if (c.kind == CarriedPoint::Kind::ThisStep && height > 1e-6) continue;  // not printed yet
        const Eigen::Vector3d world = cell.nozzleTipMm + nozzleTurn * (c.fileMm - f);
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
    for (const auto& c : collisions.nearTable) {
      if (c.kind == CarriedPoint::Kind::ThisStep && c.fileMm.z() > f.z() + 1e-6) continue;
      const Eigen::Vector3d world = cell.nozzleTipMm + nozzleTurn * (c.fileMm - f);
      if (world.z() < cell.tableZMm + margins.tableClearanceMm)
        return std::string(kindName(c.kind)) + " would come within " + fixed(margins.tableClearanceMm, 1) +
               " mm of the table " + where(world) + ", table at z " + fixed(cell.tableZMm, 1) +
               "; move the nozzle higher (nozzleTipMm) or the table lower";
    }
    (void)flange;  // the arm itself: armOnTable
    return {};
  };

  // The moves, checked.
  std::vector<Converted> converted;
  converted.reserve(moves.size() + 2);
  Joints joints{};
  const Eigen::Isometry3d approachTcp = platformPoseFor(cell, input.platformToFile, bestRotation, approach);
  switch (solveOnBranch(arm, approachTcp * platformToFlange, bestBranch, cell.home, joints)) {
    case Solve::Ok:
      break;
    default:
      refuse(moves.front()->line, "the step's first point, " + fixed(kRetreatMm, 0) +
                                      " mm off the nozzle, is out of the arm's reach with any rotation about the "
                                      "nozzle axis; move the nozzle (multidir cell reach) or scale the part down");
      return out;
  }
  const Joints approachJoints = joints;
  ArmClearance lastClearance = armClearance(cell, joints);
  {
    std::string hit = armOnTable(cell, joints);
    if (hit.empty() && lastClearance.mm <= 0.0) hit = describeArmHit(cell, joints, lastClearance, approach);
    if (!hit.empty()) {
      refuse(moves.front()->line, hit);
      return out;
    }
  }
  Eigen::Vector3d current = approach;
  std::size_t nextEvent = 0;
  std::size_t nextLayer = 0;
  int layer = 0;
  summary.reachMarginMm = std::numeric_limits<double>::infinity();
  summary.wristMarginDegrees = std::numeric_limits<double>::infinity();
  const double jointStepLimit = margins.maxJointStepDegrees * kDeg;
  double worstLoad = 0.0;
  int worstLoadJoint = 0;

  auto eventsUpTo = [&](int line, std::vector<std::string>& before) {
    while (nextLayer < side->layerChangeLines.size() && side->layerChangeLines[nextLayer] < line) {
      ++nextLayer;
      ++layer;
      before.push_back("textmsg(\"multidir step " + std::to_string(input.step) + " layer " + std::to_string(layer) + "\")");
    }
    while (nextEvent < side->events.size() && side->events[nextEvent].line <= line) {
      const GcodeEvent& e = side->events[nextEvent++];
      switch (e.kind) {
        case GcodeEvent::Kind::NozzleTemperature:
        case GcodeEvent::Kind::NozzleTemperatureWait: {
          const double fraction = std::clamp(e.value / kTemperatureFullScaleC, 0.0, 1.0);
          before.push_back("set_standard_analog_out(1, " + number(fraction, 4) + ")");
          if (e.kind == GcodeEvent::Kind::NozzleTemperatureWait && e.value > kHeatWaitBelowC) {
            before.push_back("while get_standard_analog_in(0) < " +
                             number((e.value - kHeatWaitBelowC) / kTemperatureFullScaleC, 4) + ":");
            before.push_back("  sync()");
            before.push_back("end");
          }
          break;
        }
        case GcodeEvent::Kind::FanOn:
          before.push_back("set_standard_digital_out(0, True)");
          break;
        case GcodeEvent::Kind::FanOff:
          before.push_back("set_standard_digital_out(0, False)");
          break;
      }
    }
  };

  for (std::size_t i = 0; i < moves.size(); ++i) {
    if ((i & 4095) == 0 && context.isCancelled()) {
      refuse(0, "cancelled");
      return out;
    }
    const slicing::GcodeMove& move = *moves[i];
    const Eigen::Vector3d target = fileOf(move);
    const double length = (target - current).norm();
    Converted c;
    c.line = move.line;
    c.fileMm = target;
    c.lengthMm = length;
    c.extrudes = move.extrudes();
    eventsUpTo(move.line, c.before);
    const std::size_t lineIndex = static_cast<std::size_t>(move.line);
    const double feed = lineIndex < side->feedMmPerMinByLine.size() ? side->feedMmPerMinByLine[lineIndex] : 0.0;
    double requested = cell.motion.travelSpeedMmPerS;
    if (c.extrudes) {
      if (!(feed > 0.0)) {
        refuse(move.line, "an extrusion with no feed rate (F) in effect");
        return out;
      }
      requested = feed / 60.0;
    }
    // Samples along the move: reach, branch, limits, jumps, margins, collisions, joint speeds.
    const int samples = std::max(1, static_cast<int>(std::ceil(length / options.sampleMm)));
    double load = 0.0;
    int loadJoint = 0;
    for (int s = 1; s <= samples; ++s) {
      const Eigen::Vector3d f = current + (target - current) * (static_cast<double>(s) / samples);
      const Eigen::Isometry3d tcp = poseWithTurn(cell, input.platformToFile, nozzleTurn, f);
      const Eigen::Isometry3d flange = tcp * platformToFlange;
      Joints q{};
      switch (solveOnBranch(arm, flange, bestBranch, joints, q)) {
        case Solve::Ok:
          break;
        case Solve::OutOfReach:
          refuse(move.line, "the platform pose for nozzle point (" + fixed(f.x(), 2) + ", " + fixed(f.y(), 2) + ", " +
                                fixed(f.z(), 2) + ") is out of the arm's reach; move the nozzle (multidir cell "
                                "reach) or scale the part down");
          return out;
        case Solve::OtherBranchOnly:
          refuse(move.line, "unreachable on the step's arm configuration (branch " + std::to_string(bestBranch) +
                                "): only another configuration reaches it, and changing it mid-step is a wrist or "
                                "elbow flip; move the nozzle or split the step");
          return out;
        case Solve::BeyondLimits:
          refuse(move.line, "the pose needs a joint beyond the cell's joint limits (jointLimitsDegrees)");
          return out;
      }
      int jumpJoint = 0;
      const double jump = maxJointGap(q, joints, &jumpJoint);
      if (jump > jointStepLimit) {
        refuse(move.line, "joint " + std::to_string(jumpJoint + 1) + " jumps " + fixed(jump / kDeg, 1) + " deg within " +
                              fixed(length / samples, 1) + " mm of path (over the cell's " +
                              fixed(margins.maxJointStepDegrees, 1) +
                              " deg, margins.maxJointStepDegrees): a wrist flip near a singularity");
        return out;
      }
      const double reach = reachMarginMm(arm, q);
      const double wrist = wristDegrees(q);
      summary.reachMarginMm = std::min(summary.reachMarginMm, reach);
      summary.wristMarginDegrees = std::min(summary.wristMarginDegrees, wrist);
      if (reach < margins.minReachMm) {
        refuse(move.line, "reach margin " + fixed(reach, 1) + " mm, under the cell's " + fixed(margins.minReachMm, 1) +
                              " mm (margins.minReachMm): the arm is near the edge of its workspace or the shoulder "
                              "singularity");
        return out;
      }
      if (wrist < margins.minWristDegrees) {
        refuse(move.line, "wrist 2 at " + fixed(wrist, 1) + " deg from the wrist singularity, under the cell's " +
                              fixed(margins.minWristDegrees, 1) + " deg (margins.minWristDegrees)");
        return out;
      }
      std::string hit = collisionAt(f, flange);
      if (hit.empty()) hit = armOnTable(cell, q);
      if (hit.empty()) {
        const ArmClearance clearance = armClearance(cell, q);
        const Eigen::Vector3d before = current + (target - current) * (static_cast<double>(s - 1) / samples);
        hit = armLinksBetween(cell, input.platformToFile, nozzleTurn, platformToFlange, bestBranch, before, joints,
                              lastClearance, f, q, clearance);
        lastClearance = clearance;
      }
      if (!hit.empty()) {
        refuse(move.line, hit);
        return out;
      }
      const double seconds = (length / samples) / requested;
      for (int j = 0; j < 6; ++j) {
        const double speed = std::abs(q[static_cast<std::size_t>(j)] - joints[static_cast<std::size_t>(j)]) / seconds;
        const double ratio = speed / arm.limits[static_cast<std::size_t>(j)].maxSpeedRadPerS;
        if (ratio > load) {
          load = ratio;
          loadJoint = j;
        }
      }
      joints = q;
      if (s == samples) c.tcp = tcp;
    }
    if (input.recordMotion) out.motion.push_back({move.line, target, c.tcp.translation(), joints, c.extrudes});
    if (load > worstLoad) {
      worstLoad = load;
      worstLoadJoint = loadJoint;
    }
    double speed = requested;
    if (c.extrudes) {
      const double filamentSpeed = move.filamentMm / length * requested;
      load = std::max(load, filamentSpeed / cell.maxFilamentMmPerS);
    }
    if (load > 1.0) {
      speed = requested / load;
      ++summary.slowdowns;
      summary.slowdownSeconds += trapezoidSeconds(length, speed, cell.motion.toolAccelMmPerS2) -
                                 trapezoidSeconds(length, requested, cell.motion.toolAccelMmPerS2);
    }
    // The written values, rounded as written, so the program's filament is what the controller will drive.
    speed = std::stod(number(speed / 1000.0, 6)) * 1000.0;
    c.speedMmPerS = speed;
    if (c.extrudes) c.filamentMm = move.filamentMm;
    summary.gcodeFilamentMm += c.extrudes ? move.filamentMm : 0.0;
    converted.push_back(std::move(c));
    current = target;
  }
  // After the last move: the platform backs off the nozzle, then home.
  Converted back;
  back.line = moves.back()->line;
  back.fileMm = retreat;
  back.lengthMm = (retreat - current).norm();
  back.speedMmPerS = cell.motion.travelSpeedMmPerS;
  eventsUpTo(std::numeric_limits<int>::max(), back.before);
  back.tcp = platformPoseFor(cell, input.platformToFile, bestRotation, retreat);
  Joints retreatJoints{};
  if (solveOnBranch(arm, back.tcp * platformToFlange, bestBranch, joints, retreatJoints) != Solve::Ok) {
    refuse(back.line, "the platform cannot back " + fixed(kRetreatMm, 0) + " mm off the nozzle after the step");
    return out;
  }
  const std::string retreatHit =
      armLinksBetween(cell, input.platformToFile, nozzleTurn, platformToFlange, bestBranch, current, joints,
                      lastClearance, retreat, retreatJoints, armClearance(cell, retreatJoints));
  if (!retreatHit.empty()) {
    refuse(back.line, retreatHit);
    return out;
  }
  converted.push_back(std::move(back));
  summary.slowestJoint = worstLoadJoint + 1;
  summary.slowestJointLoad = worstLoad;

  // The program.
  const CellMotion& motion = cell.motion;
  const double jointSpeed = motion.jointSpeedDegreesPerS * kDeg, jointAccel = motion.jointAccelDegreesPerS2 * kDeg;
  auto movej = [&](const Joints& from, const Joints& to) {
    summary.seconds += trapezoidSeconds(maxJointGap(from, to), jointSpeed, jointAccel);
    return "  movej(" + jointsText(to) + ", a=" + number(jointAccel, 4) + ", v=" + number(jointSpeed, 4) + ")\n";
  };
  std::string& script = out.script;
  char functionName[40];
  std::snprintf(functionName, sizeof functionName, "multidir_step_%02d", input.step);
  script += "def " + std::string(functionName) + "():\n";
  script += "  # MultiDir robot program: step " + std::to_string(input.step) + " of " + std::to_string(input.stepCount) +
            ", from " + input.gcodeFile + "; robot " + arm.name + ", rotation about the nozzle axis " +
            fixed(summary.rotationDegrees, 1) + " deg, arm configuration (branch) " + std::to_string(bestBranch) + "\n";
  script += "  # analog out 0: extruder filament speed / " + fixed(cell.maxFilamentMmPerS, 3) +
            " mm/s; analog out 1: nozzle set point / 300 C; digital out 0: part-cooling fan\n";
  script += "  set_tcp(" + poseText(cell.flangeToPlatform) + ")\n";
  script += "  set_standard_analog_out(0, 0.000000)\n";
  // The movel register (kMovelRegister): 0 in the joint moves, k just before movel k starts.
  const std::string movelRegister = "  write_output_integer_register(" + std::to_string(kMovelRegister) + ", ";
  script += movelRegister + "0)\n";
  script += movej(cell.home, cell.home);
  script += movej(cell.home, approachJoints);
  const double accel = motion.toolAccelMmPerS2;
  double written = 0.0;
  double blendIn = 0.0;  // the blend radius of the move before, into this one
  for (std::size_t i = 0; i < converted.size(); ++i) {
    const Converted& c = converted[i];
    for (const auto& line : c.before) script += "  " + line + "\n";
    double blend = 0.0;
    if (c.extrudes && i + 1 < converted.size() && converted[i + 1].extrudes)
      blend = std::min({motion.blendRadiusMm, 0.45 * c.lengthMm, 0.45 * converted[i + 1].lengthMm});
    // The extruder runs at one rate through a move, so the rate is the move's E over the time the move really
    // takes: a move that stops at both ends (no blend) speeds up and brakes on its trapezoid; only a blended one
    // keeps about its tool speed. (The rate at the tool speed over-extruded 1.2-2x on the kitten's short moves,
    // measured on the simulated controller.) Rounded as written, so the summary's filament is what it pushes.
    const double moveSeconds = blend > 0.0 || blendIn > 0.0 ? c.lengthMm / c.speedMmPerS
                                                            : trapezoidSeconds(c.lengthMm, c.speedMmPerS, accel);
    blendIn = blend;
    // The extruder's speed fraction while this move runs (0: travel).
    double analog0 = 0.0;
    if (c.extrudes && moveSeconds > 0.0)
      analog0 = std::stod(number(c.filamentMm / moveSeconds / cell.maxFilamentMmPerS, 6));
    if (analog0 != written) {
      script += "  set_standard_analog_out(0, " + number(analog0, 6) + ")\n";
      written = analog0;
    }
    script += movelRegister + std::to_string(summary.moves + 1) + ")\n";
    script += "  movel(" + poseText(c.tcp) + ", a=" + number(accel / 1000.0, 4) + ", v=" + number(c.speedMmPerS / 1000.0, 6) +
              ", r=" + number(blend / 1000.0, 6) + ")\n";
    ++summary.moves;
    summary.seconds += trapezoidSeconds(c.lengthMm, c.speedMmPerS, accel);
    summary.filamentMm += analog0 * cell.maxFilamentMmPerS * moveSeconds;
  }
  summary.gcodeMoves = static_cast<int>(moves.size());
  script += movelRegister + "0)\n";
  script += movej(retreatJoints, cell.home);
  script += "end\n";
  return out;
}

}  // namespace multidir::robot::detail
