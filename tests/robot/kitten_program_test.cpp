// The kitten's 5-DOF job (decomposed, sliced with the cell's profile) converted for the paper's cell and read
// back as the controller would: the scripts' movel targets, replayed through the cell, put the nozzle on the
// part where the G-code says; the extruder's commands push the G-code's filament; no joint passes its limits
// or its speed.
#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "job_inputs.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/job_motion.h"
#include "multidir/robot/robot_program.h"
#include "multidir/slicing/audit.h"
#include "multidir/slicing/gcode_program.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/slice_job.h"
#include "slicing/slicing_fixtures.h"
#include "support/joint_sweep_check.h"
#include "support/test_models.h"

namespace multidir::robot {
namespace {

const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

// The kitten at half size, 5-DOF (greedy), sliced coarse with the cell's profile into the test's own folder.
std::string slicedKitten(const std::string& testName) {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::TiltRotate;
  machine.up = core::Vec3::UnitY();
  const core::LoadedPlan plan = test::plannedInMemory(test::loadSharedModel("kitten.off"), machine, "kitten", 0.5);
  slicing::SliceJobOptions options;
  options.settings = test::coarseSettings(0.6);
  options.fixedDirection = false;
  const std::string dir = test::scratchDirectory(testName) + "/job";
  core::JobContext context;
  const auto profile = slicing::loadPrinterProfile("ur5-cell-0.8");
  if (!profile) throw std::runtime_error(profile.error().describe());
  const auto sliced = slicing::slicePlan(plan, *profile, options, dir, context);
  if (!sliced) throw std::runtime_error(sliced.error().describe());
  return dir;
}

// The paper's cell with its platform the plan's platform region (the plan's search kept the tilted steps clear
// of a platform that size; docs/robot-cell.md, "The platform").
std::string cellForJob(const std::string& jobDir, const std::string& testName) {
  std::ifstream jobIn(jobDir + "/print-job.json");
  const nlohmann::json job = nlohmann::json::parse(jobIn);
  std::ifstream cellIn(kShippedCell);
  nlohmann::json cell = nlohmann::json::parse(cellIn);
  cell["platformRadiusMm"] = job["pivot"]["platformRadiusMm"];
  const std::string path = test::scratchDirectory(testName + ".cell") + "/cell.json";
  std::ofstream(path) << cell.dump(2);
  return path;
}

struct ScriptMove {
  Eigen::Isometry3d tcp;  // mm
  double speedMmPerS = 0.0;
  double analog0 = 0.0;   // in effect while the move runs
  double accelMmPerS2 = 0.0;
  double blendMm = 0.0;
};

struct Script {
  Eigen::Isometry3d tcpOffset = Eigen::Isometry3d::Identity();
  std::vector<Joints> movej;
  std::vector<ScriptMove> movel;
};

Eigen::Isometry3d poseFrom(const double v[6]) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(v[0], v[1], v[2]) * 1000.0;
  const Eigen::Vector3d rv(v[3], v[4], v[5]);
  if (rv.norm() > 0) pose.linear() = Eigen::AngleAxisd(rv.norm(), rv.normalized()).toRotationMatrix();
  return pose;
}

// The contract's statements this test needs, read as the controller reads them.
Script readScript(const std::string& text) {
  Script script;
  std::istringstream lines(text);
  std::string line;
  double analog0 = 0.0;
  while (std::getline(lines, line)) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos) continue;
    const std::string s = line.substr(start);
    double v[6], a = 0, speed = 0, r = 0, value = 0;
    int port = 0;
    if (std::sscanf(s.c_str(), "set_tcp(p[%lf, %lf, %lf, %lf, %lf, %lf])", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) == 6) {
      script.tcpOffset = poseFrom(v);
    } else if (std::sscanf(s.c_str(), "set_standard_analog_out(%d, %lf)", &port, &value) == 2) {
      if (port == 0) analog0 = value;
    } else if (std::sscanf(s.c_str(), "movel(p[%lf, %lf, %lf, %lf, %lf, %lf], a=%lf, v=%lf, r=%lf)", &v[0], &v[1],
                           &v[2], &v[3], &v[4], &v[5], &a, &speed, &r) == 9) {
      script.movel.push_back({poseFrom(v), speed * 1000.0, analog0, a * 1000.0, r * 1000.0});
    } else if (std::sscanf(s.c_str(), "movej([%lf, %lf, %lf, %lf, %lf, %lf]", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) == 6) {
      script.movej.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
    }
  }
  return script;
}

// What the G-code says per step: its moves' targets in the platform frame (the part's), and its E.
struct GcodeStep {
  std::vector<Eigen::Vector3d> targets;  // moves with XY or Z motion, platform frame
  double extrudedMm = 0.0;
};

std::vector<GcodeStep> gcodeSteps(const std::string& jobDir) {
  const auto job = slicing::readAuditJob(jobDir);
  if (!job) throw std::runtime_error(job.error().describe());
  slicing::AuditMachine rest = job->machine;
  rest.kind = core::MachineKind::ThreeAxis;
  const Eigen::Isometry3d modelToPlatform = slicing::auditModelToFile(rest, {});
  std::vector<GcodeStep> steps;
  for (const auto& step : job->steps) {
    const Eigen::Isometry3d fileToPlatform = modelToPlatform * step.recordedModelToFile.inverse();
    const auto program = slicing::parseGcode(step.gcode, "A", step.gcodeFile);
    if (!program) throw std::runtime_error(program.error().describe());
    GcodeStep out;
    for (const auto& m : program->moves) {
      if (!m.movesXy() && !m.movesZ()) continue;
      out.targets.push_back(fileToPlatform * (m.to - job->printerOffset));
      if (m.extrudes()) out.extrudedMm += m.filamentMm;
    }
    steps.push_back(out);
  }
  return steps;
}

struct Converted {
  std::string jobDir;
  std::string cellPath;
  Cell cell;
  std::string outDir;
  std::vector<Script> scripts;
  nlohmann::json robotJob;
};

Converted convertedKitten(const std::string& testName) {
  Converted c;
  c.jobDir = slicedKitten(testName);
  c.cellPath = cellForJob(c.jobDir, testName);
  c.cell = loadCell(c.cellPath).value();
  const auto planned = planRobotJob(c.jobDir, c.cell, RobotProgramOptions{}, core::JobContext());
  if (!planned) throw std::runtime_error(planned.error().describe());
  c.outDir = test::scratchDirectory(testName + ".out") + "/robot";
  const auto written = writeRobotJob(planned.value(), c.cellPath, c.outDir);
  if (!written) throw std::runtime_error(written.error().describe());
  std::ifstream jobIn(c.outDir + "/robot-job.json");
  c.robotJob = nlohmann::json::parse(jobIn);
  // A step's programs (its parts, when above the cell's maxProgramBytes) read one after another, as they run.
  for (const auto& step : c.robotJob["steps"]) {
    std::string text;
    for (const auto& part : step["parts"]) text += test::readFile(c.outDir + "/" + part["program"].get<std::string>());
    c.scripts.push_back(readScript(text));
  }
  return c;
}

TEST(KittenRobotProgram, ReplayedNozzlePathInThePartFrameMatchesTheGcodeTo005Mm) {
  const Converted c = convertedKitten("KittenRobotProgram.NozzlePath");
  const std::vector<GcodeStep> gcode = gcodeSteps(c.jobDir);
  ASSERT_EQ(c.robotJob["format"], "multidir-robot-job");
  ASSERT_EQ(c.robotJob["robot"], "ur5");
  ASSERT_EQ(c.scripts.size(), gcode.size());
  ASSERT_GE(gcode.size(), 2u);
  for (std::size_t k = 0; k < gcode.size(); ++k) {
    const Script& script = c.scripts[k];
    // One movel per G-code move, then the retreat off the nozzle.
    ASSERT_EQ(script.movel.size(), gcode[k].targets.size() + 1) << "step " << k + 1;
    EXPECT_TRUE(script.tcpOffset.isApprox(c.cell.flangeToPlatform, 1e-9));
    double worst = 0.0;
    for (std::size_t i = 0; i < gcode[k].targets.size(); ++i) {
      const Eigen::Vector3d nozzleOnPart = script.movel[i].tcp.inverse() * c.cell.nozzleTipMm;
      worst = std::max(worst, (nozzleOnPart - gcode[k].targets[i]).norm());
    }
    EXPECT_LT(worst, 0.05) << "step " << k + 1;
    std::cout << "[ measured ] step " << k + 1 << ": nozzle on the part within " << worst << " mm of the G-code over "
              << gcode[k].targets.size() << " moves\n";
  }
}

TEST(KittenRobotProgram, ExtruderFilamentPerStepMatchesTheGcodesETo05Percent) {
  const Converted c = convertedKitten("KittenRobotProgram.Filament");
  const std::vector<GcodeStep> gcode = gcodeSteps(c.jobDir);
  ASSERT_EQ(c.scripts.size(), gcode.size());
  for (std::size_t k = 0; k < gcode.size(); ++k) {
    const Script& script = c.scripts[k];
    double pushed = 0.0;
    for (std::size_t i = 1; i < script.movel.size(); ++i) {
      const double length = (script.movel[i].tcp.translation() - script.movel[i - 1].tcp.translation()).norm();
      // The move's own duration as the controller runs it: a trapezoid when it stops at both ends, about
      // length / speed when blended into a neighbour.
      const ScriptMove& m = script.movel[i];
      const bool blended = m.blendMm > 0.0 || script.movel[i - 1].blendMm > 0.0;
      const double cruise = m.speedMmPerS * m.speedMmPerS / m.accelMmPerS2;
      const double seconds = blended           ? length / m.speedMmPerS
                             : length >= cruise ? length / m.speedMmPerS + m.speedMmPerS / m.accelMmPerS2
                                                : 2.0 * std::sqrt(length / m.accelMmPerS2);
      pushed += m.analog0 * c.cell.maxFilamentMmPerS * seconds;
    }
    // The first move (the descent from the approach) never extrudes.
    EXPECT_EQ(script.movel.front().analog0, 0.0);
    ASSERT_GT(gcode[k].extrudedMm, 0.0);
    EXPECT_NEAR(pushed / gcode[k].extrudedMm, 1.0, 0.005) << "step " << k + 1;
    EXPECT_NEAR(c.robotJob["steps"][k]["filamentMm"].get<double>(), pushed, 0.1 + 1e-3 * pushed);
  }
}

TEST(KittenRobotProgram, NoJointPassesItsLimitsOrItsSpeed) {
  const Converted c = convertedKitten("KittenRobotProgram.Joints");
  const ArmModel& arm = c.cell.arm;
  const Eigen::Isometry3d platformToFlange = c.cell.flangeToPlatform.inverse();
  for (std::size_t k = 0; k < c.scripts.size(); ++k) {
    const Script& script = c.scripts[k];
    // home, the via points from home, the step's first pose, the via points back home, home
    const std::size_t fromHome = c.robotJob["steps"][k]["viaPoints"]["fromHome"].get<std::size_t>();
    ASSERT_GE(script.movej.size(), 3u + fromHome);
    for (const Joints& target : script.movej)
      for (int j = 0; j < 6; ++j) {
        EXPECT_GE(target[j], arm.limits[j].minRad);
        EXPECT_LE(target[j], arm.limits[j].maxRad);
      }
    Joints joints = script.movej[1 + fromHome];
    double worstLoad = 0.0;
    Eigen::Vector3d previous = script.movel.front().tcp.translation();
    for (std::size_t i = 0; i < script.movel.size(); ++i) {
      const auto solutions = inverseKinematics(arm, script.movel[i].tcp * platformToFlange);
      const auto next = nearestWithinLimits(arm, solutions, joints);
      ASSERT_TRUE(next.has_value()) << "step " << k + 1 << ", movel " << i;
      const double length = (script.movel[i].tcp.translation() - previous).norm();
      const double seconds = length / script.movel[i].speedMmPerS;
      for (int j = 0; j < 6 && seconds > 0; ++j)
        worstLoad = std::max(worstLoad, std::abs((*next)[j] - joints[j]) / seconds / arm.limits[j].maxSpeedRadPerS);
      joints = *next;
      previous = script.movel[i].tcp.translation();
    }
    EXPECT_LE(worstLoad, 1.0 + 1e-6) << "step " << k + 1;
  }
}


// The kitten's steps each print on one rotation about the nozzle axis on the paper cell: no re-orientation, and
// each program moves in joint space only from home, to its approach (through its via points) and back home
// (through its via points).
TEST(KittenRobotProgram, EveryStepPrintsOnOneRotationWithNoReorientation) {
  const Converted c = convertedKitten("KittenRobotProgram.NoReorientation");
  ASSERT_EQ(c.robotJob["steps"].size(), c.scripts.size());
  for (std::size_t k = 0; k < c.scripts.size(); ++k) {
    const nlohmann::json& step = c.robotJob["steps"][k];
    EXPECT_TRUE(step["reorientations"].empty()) << "step " << k + 1;
    EXPECT_EQ(c.scripts[k].movej.size(),
              3u + step["viaPoints"]["fromHome"].get<std::size_t>() + step["viaPoints"]["toHome"].get<std::size_t>())
        << "step " << k + 1;
  }
}

// Every joint move of the kitten's programs on the paper cell (home to each step, through its via points, and
// back) replayed independently (support/joint_sweep_check.h: every 0.1 degree, point-to-solid distances of its
// own): the links, the platform and the part printed in earlier steps stay clear of the extruder's bodies and the
// table.
TEST(KittenRobotProgram, EveryJointMoveKeepsTheArmThePlatformAndTheEarlierPartClearOfTheCell) {
  const Converted c = convertedKitten("KittenRobotProgram.JointMoves");
  const auto inputs = detail::readJobInputs(c.jobDir, c.cell);
  ASSERT_TRUE(inputs.ok()) << inputs.error().describe();
  ASSERT_EQ(inputs->steps.size(), c.scripts.size());
  for (std::size_t k = 0; k < c.scripts.size(); ++k) {
    std::vector<Eigen::Vector3d> earlier;
    for (const detail::CarriedPoint& p : inputs->steps[k].carried)
      if (p.kind == detail::CarriedPoint::Kind::EarlierStep) earlier.push_back(p.platformMm);
    const std::string script =
        test::readFile(c.outDir + "/" + c.robotJob["steps"][k]["program"].get<std::string>());
    std::string what;
    EXPECT_GT(test::leastJointMoveClearance(c.cell, c.cell.home, script, earlier, what), 0.0)
        << "step " << k + 1 << ": " << what;
  }
}

// The studio's view of the job (robotJobMotion) is the programs' motion: each sample's platform pose is the
// pose the step's script commands for that G-code move, and it puts the fixed nozzle tip on the sample's point.
TEST(KittenRobotProgram, StudioMotionPosesAreTheScriptsMovelTargets) {
  const Converted c = convertedKitten("KittenRobotProgram.StudioMotion");
  const auto motion = robotJobMotion(c.jobDir, c.cell, RobotProgramOptions{}, core::JobContext());
  ASSERT_TRUE(motion.ok()) << motion.error().describe();
  ASSERT_EQ(motion->size(), c.scripts.size());
  for (std::size_t k = 0; k < motion->size(); ++k) {
    const StepMotion& step = (*motion)[k];
    const Script& script = c.scripts[k];
    EXPECT_FALSE(step.warning.has_value()) << "step " << k + 1;
    // One sample per G-code move; the script adds the retreat.
    ASSERT_EQ(step.samples.size() + 1, script.movel.size()) << "step " << k + 1;
    double worstPose = 0.0, worstTip = 0.0;
    for (std::size_t i = 0; i < step.samples.size(); ++i) {
      const Eigen::Isometry3d pose = platformPoseAt(step, step.samples[i]);
      worstPose = std::max(worstPose, (pose.translation() - script.movel[i].tcp.translation()).norm());
      worstPose = std::max(worstPose, 1000.0 * (pose.linear() - script.movel[i].tcp.linear()).norm());
      const Eigen::Vector3d tipOnPart = step.platformToFile * (pose.inverse() * c.cell.nozzleTipMm);
      worstTip = std::max(worstTip, (tipOnPart - step.samples[i].nozzleFileMm).norm());
      EXPECT_TRUE(platformPose(c.cell, step.samples[i].joints).isApprox(pose, 1e-6)) << "step " << k + 1 << " move " << i;
    }
    // The script writes metres with 7 decimals: 1e-4 mm.
    EXPECT_LT(worstPose, 1e-3) << "step " << k + 1;
    EXPECT_LT(worstTip, 1e-6) << "step " << k + 1;
    EXPECT_GT(step.region.faceCount(), 0u);
  }
}

// A cell whose nozzle the arm cannot bring the part to: the motion is not refused as a whole; the step says
// which line failed and why, as robot-program would refuse it.
TEST(KittenRobotProgram, StudioMotionOfAnUnreachableCellWarnsWithStepAndLine) {
  const std::string jobDir = slicedKitten("KittenRobotProgram.StudioWarning");
  Cell cell = loadCell(cellForJob(jobDir, "KittenRobotProgram.StudioWarning")).value();
  cell.nozzleTipMm = Eigen::Vector3d(0.0, -900.0, 400.0);  // beyond the UR5's 850 mm reach
  const auto motion = robotJobMotion(jobDir, cell, RobotProgramOptions{}, core::JobContext());
  ASSERT_TRUE(motion.ok()) << motion.error().describe();
  ASSERT_FALSE(motion->empty());
  const StepMotion& first = motion->front();
  ASSERT_TRUE(first.warning.has_value());
  EXPECT_EQ(first.warning->step, 1);
  EXPECT_GT(first.warning->line, 0);
  EXPECT_NE(first.warning->text.find("step 1, line " + std::to_string(first.warning->line)), std::string::npos)
      << first.warning->text;
  EXPECT_NE(first.warning->text.find("reach"), std::string::npos) << first.warning->text;
}

}  // namespace
}  // namespace multidir::robot
