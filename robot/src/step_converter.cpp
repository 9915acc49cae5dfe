// One step to one URScript program. The step's orientation (the rotation about the nozzle axis and the arm
// configuration) is chosen once and kept while the step prints (step_run.h); only a step that no single
// orientation can print is split into runs re-oriented at travel moves (step_reorientation.h).
#include "step_converter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "gcode_events.h"
#include "joint_path_planner.h"
#include "multidir/robot/arm_links.h"
#include "multidir/slicing/gcode_program.h"
#include "step_reorientation.h"
#include "step_run.h"

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

std::string number(double v, int decimals) { return fixedText(v, decimals); }
std::string fixed(double v, int decimals) { return fixedText(v, decimals); }

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

double maxJointGap(const Joints& a, const Joints& b) {
  double worst = 0.0;
  for (std::size_t j = 0; j < 6; ++j) worst = std::max(worst, std::abs(a[j] - b[j]));
  return worst;
}

// The whole step on one orientation: its approach, every move, its retreat.
std::optional<RunFailure> runWhole(StepRun& run, std::size_t moves, const core::JobContext& context) {
  if (auto failed = run.startAtApproach()) return failed;
  for (std::size_t i = 0; i < moves; ++i)
    if (auto failed = run.advance(i, context)) return failed;
  return run.retreat();
}

// The planned runs carried out, keeping what they convert: each run's moves, its lift (all but the last) or the
// retreat (the last). Replays the plan's own checks, so it cannot fail where the plan did not.
std::optional<RunFailure> runPlanned(const StepPath& path, const RunPlan& plan, const core::JobContext& context,
                                     std::vector<std::unique_ptr<StepRun>>& runs) {
  for (std::size_t k = 0; k < plan.runs.size(); ++k) {
    const PlannedRun& planned = plan.runs[k];
    runs.push_back(std::make_unique<StepRun>(path, planned.orientation, true));
    StepRun& run = *runs.back();
    if (auto failed = k == 0 ? run.startAtApproach() : run.startAfterTurn(planned.first, runs[k - 1]->joints()))
      return failed;
    for (std::size_t i = k == 0 ? planned.first : planned.first + 1; i < planned.end; ++i)
      if (auto failed = run.advance(i, context)) return failed;
    if (auto failed = planned.end == path.moves.size() ? run.retreat() : run.liftOff(planned.end - 1)) return failed;
  }
  return std::nullopt;
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
  StepPath path;
  path.input = &input;
  path.cell = &cell;
  path.options = &options;
  path.side = &*side;
  for (const auto& m : program->moves) {
    if (m.commandsRotaryAxis) {
      refuse(m.line, "the program turns a platform axis; the cell has none: slice with the cell's profile "
                     "(resources/printers/ur5-cell-0.8.ini)");
      return out;
    }
    if (m.movesXy() || m.movesZ()) path.moves.push_back(&m);
  }
  if (path.moves.empty()) {
    refuse(0, "the program moves nowhere");
    return out;
  }
  for (const auto* m : path.moves) path.points.push_back(m->to - input.printerOffsetMm);
  path.approach = path.points.front() + Eigen::Vector3d(0, 0, kRetreatMm);
  path.retreat = path.points.back() + Eigen::Vector3d(0, 0, kRetreatMm);
  path.bounds = Eigen::AlignedBox3d(path.approach);
  path.bounds.extend(path.retreat);
  for (const auto& p : path.points) path.bounds.extend(p);
  path.sweptBounds = path.bounds;
  path.sweptBounds.max().z() += kRetreatMm;  // a re-orientation lifts the part off the nozzle
  path.platformToFlange = cell.flangeToPlatform.inverse();
  const ArmModel& arm = cell.arm;

  // The step's orientation, and the whole step on it; only when that fails, the runs re-oriented at travel moves.
  const Orientation best = bestOrientation(scoreOrientations(path, path.bounds)).orientation;
  std::vector<std::unique_ptr<StepRun>> runs;
  runs.push_back(std::make_unique<StepRun>(path, best, true));
  std::optional<RunFailure> failed = runWhole(*runs.front(), path.moves.size(), context);
  if (failed && !failed->fatal) {
    const RunPlan plan = planRuns(path, *failed, context);
    if (plan.failure) {
      failed = plan.failure;
      if (plan.failure->fatal) {
        refuse(context.isCancelled() ? 0 : failed->line, failed->reason);
        return out;
      }
    } else {
      runs.clear();
      failed = runPlanned(path, plan, context, runs);
      if (failed) failed->reason = "re-orientation: " + failed->reason;
    }
  }
  // Every run's moves, in order; the summary over all of them.
  std::vector<Converted> converted;
  summary.reachMarginMm = std::numeric_limits<double>::infinity();
  summary.wristMarginDegrees = std::numeric_limits<double>::infinity();
  double worstLoad = 0.0;
  int worstLoadJoint = 0;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    StepRun& run = *runs[k];
    const RunStats& stats = run.stats();
    summary.reachMarginMm = std::min(summary.reachMarginMm, stats.reachMarginMm);
    summary.wristMarginDegrees = std::min(summary.wristMarginDegrees, stats.wristMarginDegrees);
    if (stats.worstLoad > worstLoad) {
      worstLoad = stats.worstLoad;
      worstLoadJoint = stats.worstLoadJoint;
    }
    summary.slowdowns += stats.slowdowns;
    summary.slowdownSeconds += stats.slowdownSeconds;
    summary.gcodeFilamentMm += stats.gcodeFilamentMm;
    out.platformRotations.push_back(run.nozzleTurn() * input.platformToFile.linear());
    for (MotionSample& m : run.motion()) {
      m.run = static_cast<int>(k);
      out.motion.push_back(m);
    }
    if (k > 0 && !run.converted().empty() && run.converted().front().turn) {
      const Converted& turn = run.converted().front();
      summary.reorientations.push_back({turn.line, run.orientation().rotationRad / kDeg, run.orientation().branch});
    }
    converted.insert(converted.end(), std::make_move_iterator(run.converted().begin()),
                     std::make_move_iterator(run.converted().end()));
  }
  summary.rotationDegrees = runs.front()->orientation().rotationRad / kDeg;
  summary.branch = runs.front()->orientation().branch;
  if (failed) {
    refuse(failed->line, failed->reason);
    return out;
  }
  summary.slowestJoint = worstLoadJoint + 1;
  summary.slowestJointLoad = worstLoad;
  const Joints approachJoints = runs.front()->startJoints();
  const Joints retreatJoints = runs.back()->joints();

  // The joint moves between home and the step: straight when clear, else via points; refused when neither.
  const JointMoveScene before{&cell, &input.carried, input.platformToFile, -std::numeric_limits<double>::infinity()};
  const JointMoveScene after{&cell, &input.carried, input.platformToFile, std::numeric_limits<double>::infinity()};
  const JointPathPlan fromHome = planJointPath(before, cell.home, approachJoints, options.viaPoints);
  const JointPathPlan toHome = planJointPath(after, retreatJoints, cell.home, options.viaPoints);
  auto refuseMove = [&](const std::string& move, const JointPathPlan& plan) {
    std::string why = "the move " + move + " (a joint move) is not clear: " + plan.straightHit;
    if (options.viaPoints)
      why += "; no via points found either (" + std::to_string(plan.candidatesTried) +
             " natural candidates, then a search of " + std::to_string(plan.searchSamples) +
             " joint sets within the joint limits)";
    else
      why += "; via points are off (--no-via-points)";
    refuse(0, why + ": move the cell's home (homeDegrees) or the extruder's bodies");
  };
  if (!fromHome.found) refuseMove("from home to " + stepText + "'s first point, " + fixed(kRetreatMm, 0) + " mm off the nozzle", fromHome);
  if (!toHome.found) refuseMove("from " + stepText + "'s last point, " + fixed(kRetreatMm, 0) + " mm off the nozzle, back home", toHome);
  if (!fromHome.found || !toHome.found) return out;
  summary.viaPointsFromHome = static_cast<int>(fromHome.vias.size());
  summary.viaPointsToHome = static_cast<int>(toHome.vias.size());

  // The G-code's temperatures, fan and layer changes before the moves they precede.
  std::size_t nextEvent = 0;
  std::size_t nextLayer = 0;
  int layer = 0;
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
  for (std::size_t i = 0; i < converted.size(); ++i)
    eventsUpTo(i + 1 == converted.size() ? std::numeric_limits<int>::max() : converted[i].line, converted[i].before);

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
            fixed(summary.rotationDegrees, 1) + " deg, arm configuration (branch) " + std::to_string(summary.branch) +
            (summary.reorientations.empty()
                 ? std::string()
                 : "; re-oriented " + std::to_string(summary.reorientations.size()) + " time(s) at travel moves") +
            "\n";
  script += "  # analog out 0: extruder filament speed / " + fixed(cell.maxFilamentMmPerS, 3) +
            " mm/s; analog out 1: nozzle set point / 300 C; digital out 0: part-cooling fan\n";
  script += "  set_tcp(" + poseText(cell.flangeToPlatform) + ")\n";
  script += "  set_standard_analog_out(0, 0.000000)\n";
  // The movel register (kMovelRegister): 0 in the joint moves, k just before movel k starts.
  const std::string movelRegister = "  write_output_integer_register(" + std::to_string(kMovelRegister) + ", ";
  script += movelRegister + "0)\n";
  script += movej(cell.home, cell.home);
  auto jointPath = [&](const Joints& from, const JointPathPlan& plan, const Joints& to, const std::string& what) {
    if (!plan.vias.empty())
      script += "  # " + what + ": " + std::to_string(plan.vias.size()) + " via point(s) (" + plan.method +
                "): the straight joint move is not clear\n";
    Joints at = from;
    for (const Joints& via : plan.vias) {
      script += movej(at, via);
      at = via;
    }
    script += movej(at, to);
  };
  jointPath(cell.home, fromHome, approachJoints, "from home to the step's first point");
  const double accel = motion.toolAccelMmPerS2;
  double written = 0.0;
  double blendIn = 0.0;  // the blend radius of the move before, into this one
  int turns = 0;
  for (std::size_t i = 0; i < converted.size(); ++i) {
    const Converted& c = converted[i];
    for (const auto& line : c.before) script += "  " + line + "\n";
    if (c.turn) {
      // A re-orientation: the part is off the nozzle (the lift before), the extruder stopped (a travel).
      const std::size_t k = static_cast<std::size_t>(++turns);
      const RobotReorientation& r = summary.reorientations[k - 1];
      script += "  # re-orientation " + std::to_string(k) + " before G-code line " + std::to_string(r.line) +
                ": rotation about the nozzle axis " + fixed(r.rotationDegrees, 1) + " deg, arm configuration (branch) " +
                std::to_string(r.branch) + "\n";
      script += movej(c.turnFrom, c.turnTo);
      blendIn = 0.0;
      continue;
    }
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
  summary.gcodeMoves = static_cast<int>(path.moves.size());
  script += movelRegister + "0)\n";
  jointPath(retreatJoints, toHome, cell.home, "from the step's last point back home");
  script += "end\n";
  return out;
}

}  // namespace multidir::robot::detail
