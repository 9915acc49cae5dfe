// Slicing print jobs end to end with PrusaSlicer: the snowman, kitten and bunny plans, a plan with supports,
// the stitched program, and the errors for a missing slicer and a bed too small.
#include "multidir/slicing/slice_job.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "multidir/core/samples/samples.h"
#include "multidir/slicing/gcode_program.h"
#include "slicing_fixtures.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;
using core::Vec3;

namespace {

namespace fs = std::filesystem;

PrinterProfile profileNamed(const std::string& name) {
  core::Result<PrinterProfile> p = loadPrinterProfile(name);
  if (!p) throw std::runtime_error(p.error().describe());
  return *p;
}

std::string scratch(const std::string& name) {
  return test::scratchDirectory("slice_job." + name + "." +
                                testing::UnitTest::GetInstance()->current_test_info()->name());
}

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Independent of the checks inside sliceJob: every extrusion of every step file lies on or above its base
// plane and on the bed.
void expectStepsOnTheirBasePlanes(const SlicedJob& sliced, const std::string& dir) {
  for (const SlicedStep& step : sliced.steps) {
    const std::vector<GcodeMove> moves = test::extrusionsOf(dir + "/" + step.gcodeFile);
    int stepMoves = 0;
    for (const GcodeMove& m : moves) {
      EXPECT_GE(m.to.x(), sliced.profile.bedMin().x() - 1e-3);
      EXPECT_LE(m.to.x(), sliced.profile.bedMax().x() + 1e-3);
      EXPECT_GE(m.to.y(), sliced.profile.bedMin().y() - 1e-3);
      EXPECT_LE(m.to.y(), sliced.profile.bedMax().y() + 1e-3);
      if (m.step != step.index) continue;
      ++stepMoves;
      ASSERT_GE(std::min(m.from.z(), m.to.z()), step.baseZMm - 1e-3) << step.gcodeFile << " line " << m.line;
    }
    EXPECT_GT(stepMoves, 0) << step.gcodeFile;
    EXPECT_GT(step.estimate.printSeconds, 0.0);
    EXPECT_GT(step.estimate.filamentMm, 0.0);
  }
}

// Generalised winding number: about 1 inside a closed, outward-oriented mesh, about 0 outside.
double windingNumber(const core::TriangleMesh& mesh, const Vec3& p) {
  double total = 0.0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const Vec3 a = mesh.corner(f, 0) - p, b = mesh.corner(f, 1) - p, c = mesh.corner(f, 2) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(num, den);
  }
  return total / (4.0 * M_PI);
}

// A plain printer's job of one step: the box from `lo` to `hi`.
core::PrintJob oneBoxJob(const Vec3& lo, const Vec3& hi) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::ThreeAxis;
  core::PrintJobStep step;
  step.region = test::makeBox(lo, hi);
  step.regionFile = "step-01-region.stl";
  job.steps = {step};
  return job;
}

// A stand-in slicer: a shell script with `body`, executable; its path.
std::string fakeSlicer(const std::string& path, const std::string& body) {
  std::ofstream(path) << "#!/bin/sh\n" << body;
  fs::permissions(path, fs::perms::owner_all);
  return path;
}

// The coarse settings at `layerHeightMm`, without the fixed-direction comparison (one slicing per step).
SliceJobOptions coarseOptions(double layerHeightMm) {
  SliceJobOptions options;
  options.settings = test::coarseSettings(layerHeightMm);
  options.fixedDirection = false;
  return options;
}

core::MachineSpec rotary(const Vec3& up) {
  core::MachineSpec m;
  m.kind = core::MachineKind::RotaryPlatform;
  m.up = up;
  m.rotationAxis = Vec3::UnitX();  // perpendicular to both ups used here
  return m;
}

}  // namespace

TEST(SliceJob, SnowmanOnAKlipperRotaryAxisGivesCheckedStepsAndOneStitchedProgram) {
  const core::Result<core::TriangleMesh> snowman = core::samples::makeSample("snowman");
  ASSERT_TRUE(snowman.ok());
  const core::LoadedPlan plan = test::plannedInMemory(*snowman, rotary(Vec3::UnitZ()), "snowman", 0.5);
  const core::PrintJob job = test::machineJob(plan);
  SliceJobOptions options = coarseOptions(0.3);
  const std::string dir = scratch("snowman");
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, profileNamed("klipper-rotary"), options, dir, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  ASSERT_EQ(sliced->steps.size(), job.steps.size());
  expectStepsOnTheirBasePlanes(*sliced, dir);

  ASSERT_EQ(sliced->stitchedFile, "job.gcode");
  const std::string stitched = test::readFile(dir + "/job.gcode");
  EXPECT_EQ(countOf(stitched, "; MULTIDIR START SEQUENCE"), 1);
  EXPECT_EQ(countOf(stitched, "\nG28"), 1);  // homing only once
  EXPECT_EQ(countOf(stitched, "; MULTIDIR END SEQUENCE"), 1);
  EXPECT_EQ(countOf(stitched, "purge line"), 1);
  const core::Result<GcodeProgram> program = parseGcode(stitched);
  ASSERT_TRUE(program.ok());
  int turns = 0;
  for (const GcodeMove& m : program->moves)
    if (m.rotates()) {
      ASSERT_TRUE(m.inTransition);
      const TurnPlan& turn = sliced->turns[static_cast<std::size_t>(turns)];
      EXPECT_GE(m.from.z(), turn.clearanceZMm - 1e-3);
      EXPECT_NEAR(m.rotaryToDegrees, turn.toDegrees, 1e-3);
      ++turns;
    }
  const int expectedTurns = [&] {
    int n = 0;
    for (const TurnPlan& t : sliced->turns) n += std::abs(t.toDegrees - t.fromDegrees) > 1e-9 ? 1 : 0;
    return n;
  }();
  EXPECT_EQ(turns, expectedTurns);
  // Steps after the first print on plastic: no skirt.
  for (std::size_t i = 1; i < sliced->steps.size(); ++i)
    EXPECT_EQ(countOf(test::readFile(dir + "/" + sliced->steps[i].gcodeFile), ";TYPE:Skirt"), 0);

  const std::string jobJson = test::readFile(dir + "/print-job.json");
  EXPECT_NE(jobJson.find("\"slicing\""), std::string::npos);
  EXPECT_NE(jobJson.find("\"printSeconds\""), std::string::npos);
}

TEST(SliceJob, EachStepsPoseTakesItsToolpathsBackOntoItsRegionInTheModel) {
  // The inverse of modelToPrinter lays a step's extrusions over its region and supports where the plan has
  // them (model coordinates): what the studio's G-code preview draws.
  const core::Result<core::TriangleMesh> snowman = core::samples::makeSample("snowman");
  ASSERT_TRUE(snowman.ok());
  const core::LoadedPlan plan = test::plannedInMemory(*snowman, rotary(Vec3::UnitZ()), "snowman", 0.5);
  SliceJobOptions options = coarseOptions(0.3);
  options.settings.push_back({"skirts", "0"});  // step 1's skirt lies around the part, not over it
  const std::string dir = scratch("snowman-pose");
  core::JobContext context;
  const core::Result<SlicedJob> sliced = slicePlan(plan, profileNamed("klipper-rotary"), options, dir, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  ASSERT_EQ(sliced->steps.size(), plan.decomposition.regions.size());
  const double slack = 0.6;  // half an extrusion width plus the slicer's rounding
  for (std::size_t k = 0; k < sliced->steps.size(); ++k) {
    const SlicedStep& step = sliced->steps[k];
    Eigen::AlignedBox3d box;
    for (const Vec3& v : plan.decomposition.regions[k].mesh.vertices) box.extend(v);
    if (k < plan.supports.size())
      for (const Vec3& v : plan.supports[k].mesh.vertices) box.extend(v);
    box.min() -= Vec3::Constant(slack);
    box.max() += Vec3::Constant(slack);
    const Eigen::Isometry3d printerToModel = step.modelToPrinter.inverse();
    int checked = 0;
    for (const GcodeMove& m : test::extrusionsOf(dir + "/" + step.gcodeFile)) {
      if (m.step != step.index) continue;
      ++checked;
      const Vec3 p = printerToModel * m.to;
      ASSERT_TRUE(box.contains(p)) << step.gcodeFile << " line " << m.line << ": (" << p.transpose()
                                   << ") outside region " << k + 1 << "'s box";
    }
    EXPECT_GT(checked, 0) << step.gcodeFile;
  }
}

TEST(SliceJob, CancellingWhileTheSlicerRunsStopsItAndKeepsNoGcode) {
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("cancel");
  // A slicer that never ends on its own: it writes its process id, then waits (exec: the pid is the child's).
  const std::string pidFile = dir + "/slicer.pid";
  const std::string fake = fakeSlicer(dir + "/slow-slicer.sh", "echo $$ > '" + pidFile + "'\nexec sleep 60\n");
  SliceJobOptions options;
  options.slicerExecutable = fake;
  options.fixedDirection = false;
  core::JobContext context;
  std::thread canceller([context, pidFile]() mutable {
    for (int i = 0; i < 400 && !fs::exists(pidFile); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    context.cancel();
  });
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, dir + "/out", context);
  canceller.join();
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::Cancelled) << sliced.error().describe();
  EXPECT_FALSE(fs::exists(dir + "/out/step-01.gcode"));
  ASSERT_TRUE(fs::exists(pidFile)) << "the slicer never started";
  const pid_t pid = static_cast<pid_t>(std::stol(test::readFile(pidFile)));
  EXPECT_NE(::kill(pid, 0), 0) << "the slicer (pid " << pid << ") still runs";
  // The work folder of the run is gone too.
  for (const auto& entry : fs::directory_iterator(dir + "/out"))
    EXPECT_EQ(entry.path().filename().string().rfind(".slicing-", 0), std::string::npos) << entry.path();
}

TEST(SliceJob, CancellingStopsEverySlicerRunningSideBySide) {
  // Two steps, sliced side by side: one cancel stops both slicers at once.
  core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  core::PrintJobStep second = job.steps.front();
  second.index = 2;
  second.regionFile = "step-02-region.stl";
  for (Vec3& v : second.region.vertices) v.z() += 10.0;
  second.lowestHeightMm = 10.0;
  job.steps.push_back(second);
  const std::string dir = scratch("cancel-side-by-side");
  const std::string pidFile = dir + "/slicer.pids";
  const std::string fake = fakeSlicer(dir + "/slow-slicer.sh", "echo $$ >> '" + pidFile + "'\nexec sleep 60\n");
  SliceJobOptions options;
  options.slicerExecutable = fake;
  options.fixedDirection = false;
  const auto runningSlicers = [&pidFile] {
    std::ifstream in(pidFile);
    int n = 0;
    for (long pid = 0; in >> pid;) ++n;
    return n;
  };
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const int expected = static_cast<int>(std::min<std::size_t>(2, cores));
  core::JobContext context;
  std::chrono::steady_clock::time_point cancelledAt;
  std::thread canceller([&, context]() mutable {
    for (int i = 0; i < 400 && runningSlicers() < expected; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    cancelledAt = std::chrono::steady_clock::now();
    context.cancel();
  });
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, dir + "/out", context);
  const auto returnedAt = std::chrono::steady_clock::now();
  canceller.join();
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::Cancelled) << sliced.error().describe();
  EXPECT_EQ(runningSlicers(), expected) << "the slicers did not start side by side";
  EXPECT_LT(std::chrono::duration<double>(returnedAt - cancelledAt).count(), 0.5);
  std::ifstream pids(pidFile);
  for (long pid = 0; pids >> pid;) EXPECT_NE(::kill(static_cast<pid_t>(pid), 0), 0) << "slicer " << pid << " still runs";
  for (const auto& entry : fs::directory_iterator(dir + "/out"))
    EXPECT_NE(entry.path().filename().string().rfind(".slicing-", 0), 0u) << entry.path();
}

TEST(SliceJob, ProgressNamesTheStepBeingSliced) {
  // Three steps, the comparison and stitching: five shares, as sliceJob reports them.
  EXPECT_EQ(sliceStageAt(0.0, 3, true).kind, SliceStage::Kind::Step);
  EXPECT_EQ(sliceStageAt(0.0, 3, true).step, 1);
  EXPECT_EQ(sliceStageAt(1.0 / 5.0, 3, true).step, 2);
  EXPECT_EQ(sliceStageAt(2.0 / 5.0, 3, true).step, 3);
  EXPECT_EQ(sliceStageAt(3.0 / 5.0, 3, true).kind, SliceStage::Kind::FixedDirection);
  EXPECT_EQ(sliceStageAt(4.0 / 5.0, 3, true).kind, SliceStage::Kind::Stitching);
  EXPECT_EQ(sliceStageAt(3.0 / 4.0, 3, false).kind, SliceStage::Kind::Stitching);
  EXPECT_EQ(sliceStageAt(1.0, 3, false).kind, SliceStage::Kind::Done);
}

TEST(SliceJob, BunnyPlanSlicesForTheRobotWithEstimatesAndTheFixedDirectionComparison) {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::TiltRotate;
  machine.up = Vec3::UnitY();
  const core::LoadedPlan plan = test::plannedInMemory(test::loadSharedModel("bunny.off"), machine, "bunny", 0.3);
  const core::PrintJob job = test::machineJob(plan);
  SliceJobOptions options;
  options.settings = test::coarseSettings(0.6);
  const std::string dir = scratch("bunny");
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, profileNamed("robot-0.8"), options, dir, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  expectStepsOnTheirBasePlanes(*sliced, dir);
  EXPECT_TRUE(sliced->stitchedFile.empty());  // the robot turns over Modbus: one program per step
  EXPECT_FALSE(fs::exists(dir + "/job.gcode"));
  ASSERT_TRUE(sliced->fixedDirection.has_value());
  EXPECT_GT(sliced->fixedDirection->filamentMm, 0.0);
  double sum = 0.0;
  for (const SlicedStep& s : sliced->steps) sum += s.estimate.printSeconds;
  EXPECT_DOUBLE_EQ(sliced->total.printSeconds, sum);
  // A Modbus platform turns after each step but the last: those programs end above the clearance.
  for (std::size_t i = 0; i + 1 < sliced->steps.size(); ++i) {
    const core::Result<GcodeProgram> p = parseGcode(test::readFile(dir + "/" + sliced->steps[i].gcodeFile));
    ASSERT_TRUE(p.ok());
    EXPECT_GE(p->moves.back().to.z(), sliced->turns[i].clearanceZMm - 1e-3);
  }
}

TEST(SliceJob, KittenPlanSlicesOnARotaryPlatformIntoOneStitchedProgram) {
  const core::LoadedPlan plan =
      test::plannedInMemory(test::loadSharedModel("kitten.off"), rotary(Vec3::UnitY()), "kitten", 0.4);
  const core::PrintJob job = test::machineJob(plan);
  SliceJobOptions options = coarseOptions(0.3);
  const std::string dir = scratch("kitten");
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, profileNamed("klipper-rotary"), options, dir, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  expectStepsOnTheirBasePlanes(*sliced, dir);
  EXPECT_EQ(sliced->stitchedFile, "job.gcode");
  const std::string stitched = test::readFile(dir + "/job.gcode");
  EXPECT_EQ(countOf(stitched, "; MULTIDIR START SEQUENCE"), 1);
  EXPECT_EQ(countOf(stitched, "; MULTIDIR TRANSITION"), static_cast<int>(sliced->steps.size()) - 1);
}

TEST(SliceJob, PlanWithSupportsExtrudesInsideTheSupportMeshes) {
  // The T-bar printed along up on a plain printer: its bar's undersides stand on supports.
  core::MachineSpec machine;
  machine.kind = core::MachineKind::ThreeAxis;
  const core::LoadedPlan plan = test::plannedInMemory(test::makeTBar(10, 30, 60, 10, 20), machine, "tbar");
  const core::PrintJob job = test::machineJob(plan);
  std::size_t withSupports = 0;
  while (withSupports < job.steps.size() && job.steps[withSupports].supports.empty()) ++withSupports;
  ASSERT_LT(withSupports, job.steps.size()) << "the T-bar's plan was expected to keep supports";
  SliceJobOptions options = coarseOptions(0.3);
  const std::string dir = scratch("tbar");
  core::JobContext context;
  const PrinterProfile profile = profileNamed("marlin-220");
  const core::Result<SlicedJob> sliced = sliceJob(job, profile, options, dir, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();

  const core::PrintJobStep& step = job.steps[withSupports];
  core::TriangleMesh supports = step.supports;
  core::TriangleMesh region = step.region;
  // Where the step printed them: its pose in the printer (the part placed on the bed) after undoing the job's.
  const Eigen::Isometry3d toPrinter = sliced->steps[withSupports].modelToPrinter * step.modelToFile.inverse();
  for (Vec3& v : supports.vertices) v = toPrinter * v;
  for (Vec3& v : region.vertices) v = toPrinter * v;
  const std::vector<GcodeMove> moves = test::extrusionsOf(dir + "/" + sliced->steps[withSupports].gcodeFile);
  int inSupports = 0;
  int sampled = 0;
  for (std::size_t i = 0; i < moves.size() && sampled < 400; i += std::max<std::size_t>(1, moves.size() / 400)) {
    if (moves[i].step != step.index) continue;
    ++sampled;
    const Vec3 mid = 0.5 * (moves[i].from + moves[i].to) - Vec3(0, 0, 0.15);  // the middle of the layer
    if (windingNumber(supports, mid) > 0.5 && windingNumber(region, mid) < 0.5) ++inSupports;
  }
  EXPECT_GT(inSupports, 0) << "of " << sampled << " sampled extrusions";
}

TEST(SliceJob, MissingSlicerNamesTheCommand) {
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  SliceJobOptions options;
  options.slicerExecutable = "no-such-prusa-slicer";
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, scratch("missing"), context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::FileNotFound);
  EXPECT_NE(sliced.error().message.find("no-such-prusa-slicer --loglevel 1 --export-gcode"), std::string::npos)
      << sliced.error().message;
}

TEST(SliceJob, FailingSlicerGivesItsExitCodeAndLastOutput) {
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("failing");
  const std::string fake =
      fakeSlicer(dir + "/fake-slicer.sh", "echo 'Error: the slicer could not do it' >&2\nexit 4\n");
  SliceJobOptions options;
  options.slicerExecutable = fake;
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, dir + "/out", context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::ExternalToolFailed);
  EXPECT_NE(sliced.error().message.find("exit code 4"), std::string::npos) << sliced.error().message;
  EXPECT_NE(sliced.error().message.find("the slicer could not do it"), std::string::npos);
}

TEST(SliceJob, APartTooBigForTheBedIsRefusedBeforeSlicing) {
  // 40 mm on a 30 mm bed: refused before the slicer runs (it would leave a mark), saying by how much.
  const core::PrintJob job = oneBoxJob(Vec3(-20, -20, 0), Vec3(20, 20, 3));
  const std::string dir = scratch("smallbed");
  const std::string ini = dir + "/small.ini";
  std::ofstream(ini) << "bed_shape = 0x0,30x0,30x30,0x30\nmax_print_height = 100\nskirts = 0\n";
  const std::string mark = dir + "/the-slicer-ran";
  SliceJobOptions options = coarseOptions(0.3);
  options.slicerExecutable = fakeSlicer(dir + "/marking-slicer.sh", "touch '" + mark + "'\nexit 1\n");
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed(ini), options, dir + "/out", context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::TooLarge);
  const std::string& m = sliced.error().message;
  EXPECT_NE(m.find("step 1 reaches 5.0 mm past the bed's -X side"), std::string::npos) << m;
  EXPECT_NE(m.find("5.0 mm past the bed's +Y side"), std::string::npos) << m;
  EXPECT_NE(m.find("scale the model by 0.75 or less"), std::string::npos) << m;
  EXPECT_NE(m.find("at least 40 x 40 mm"), std::string::npos) << m;
  EXPECT_FALSE(fs::exists(mark)) << "the slicer ran for a part that cannot fit";
  EXPECT_FALSE(fs::exists(dir + "/out/step-01.gcode"));
}

namespace {

// A plan sliced once per test process, read by several tests: the job, what was sliced, its folder, the
// progress it reported.
struct SlicedPlan {
  core::PrintJob job;
  core::Result<SlicedJob> sliced = core::Error{core::ErrorCode::Internal, "not sliced", "test"};
  std::string dir;
  std::vector<std::pair<double, std::string>> progress;
  double layerHeightMm = 0.0;
};

SlicedPlan slicedPlan(const core::LoadedPlan& plan, const std::string& profile, double layerHeightMm,
                      const std::string& name) {
  SlicedPlan out;
  out.job = test::machineJob(plan);
  out.layerHeightMm = layerHeightMm;
  // ctest runs each test in its own process, side by side: each slices into its own folder.
  out.dir = test::scratchDirectory("slice_job.shared." + name + "." +
                                  testing::UnitTest::GetInstance()->current_test_info()->name());
  SliceJobOptions options = coarseOptions(layerHeightMm);
  std::mutex mutex;
  core::JobContext context([&](double fraction, const std::string& phase) {
    std::lock_guard<std::mutex> lock(mutex);
    out.progress.emplace_back(fraction, phase);
  });
  out.sliced = sliceJob(out.job, profileNamed(profile), options, out.dir, context);
  return out;
}

// The bunny on the paper's robot arm (5-DOF), at its 0.4 mm layers.
const SlicedPlan& bunnyOnTheRobot() {
  static const SlicedPlan plan = [] {
    core::MachineSpec machine;
    machine.kind = core::MachineKind::TiltRotate;
    machine.up = Vec3::UnitY();
    return slicedPlan(test::plannedInMemory(test::loadSharedModel("bunny.off"), machine, "bunny", 0.5), "robot-0.8",
                      0.4, "bunny-robot");
  }();
  return plan;
}

// The kitten on the Klipper printer's rotary axis (4-DOF, one stitched program), at 0.2 mm layers.
const SlicedPlan& kittenOnTheRotaryAxis() {
  static const SlicedPlan plan = [] {
    return slicedPlan(test::plannedInMemory(test::loadSharedModel("kitten.off"), rotary(Vec3::UnitY()), "kitten", 0.4),
                      "klipper-rotary", 0.2, "kitten-klipper");
  }();
  return plan;
}

// The z of each step's first extrusion after its marker, read from a program.
std::map<int, double> firstLayerZ(const std::string& path) {
  std::map<int, double> first;
  for (const GcodeMove& m : test::extrusionsOf(path))
    if (m.step > 0 && !first.count(m.step)) first[m.step] = std::min(m.from.z(), m.to.z());
  return first;
}

// How far the filament is drawn back at each step's first extrusion after its marker, the programs played one
// after another on one printer from a primed start.
std::map<int, double> drawnBackAtFirstExtrusion(const std::vector<std::string>& paths) {
  std::map<int, double> at;
  FilamentState filament;
  for (const std::string& path : paths) {
    const core::Result<GcodeProgram> program = parseGcode(test::readFile(path));
    if (!program) throw std::runtime_error(program.error().describe());
    for (const GcodeMove& m : program->moves) {
      if (m.step > 0 && m.extrudes() && !at.count(m.step))
        at[m.step] = filament.firmwareRetracted ? 1e9 : filament.retractedMm;
      advance(filament, m);
    }
  }
  return at;
}

bool supportsReachBelowTheirBasePlane(const core::PrintJob& job) {
  for (std::size_t k = 1; k < job.steps.size(); ++k)
    for (const Vec3& v : job.steps[k].supports.vertices)
      if (v.z() < job.steps[k].lowestHeightMm - 0.05) return true;
  return false;
}

}  // namespace

TEST(SliceJob, LaterStepsStartOneLayerAboveTheirBasePlane) {
  // Their supports may reach below the base plane (they continue in the step below): clipped there, they no
  // longer pull the first layer down to a sliver over the plastic already printed.
  for (const SlicedPlan* plan : {&bunnyOnTheRobot(), &kittenOnTheRotaryAxis()}) {
    ASSERT_TRUE(plan->sliced.ok()) << plan->sliced.error().describe();
    ASSERT_GT(plan->sliced->steps.size(), 1u);
    for (const SlicedStep& step : plan->sliced->steps) {
      const std::map<int, double> first = firstLayerZ(plan->dir + "/" + step.gcodeFile);
      ASSERT_TRUE(first.count(step.index)) << step.gcodeFile;
      EXPECT_NEAR(first.at(step.index) - step.baseZMm, plan->layerHeightMm, 0.005) << plan->dir << " " << step.gcodeFile;
    }
  }
  EXPECT_TRUE(supportsReachBelowTheirBasePlane(bunnyOnTheRobot().job) ||
              supportsReachBelowTheirBasePlane(kittenOnTheRotaryAxis().job))
      << "neither plan has supports below a base plane: the test no longer covers the clip";
}

TEST(SliceJob, EveryStepIsPrimedBeforeItsFirstExtrusion) {
  // Each step's program starts where the previous one left the filament (drawn back for the turn).
  for (const SlicedPlan* plan : {&bunnyOnTheRobot(), &kittenOnTheRotaryAxis()}) {
    ASSERT_TRUE(plan->sliced.ok()) << plan->sliced.error().describe();
    std::vector<std::string> files;
    for (const SlicedStep& step : plan->sliced->steps) files.push_back(plan->dir + "/" + step.gcodeFile);
    for (const auto& [step, drawnBack] : drawnBackAtFirstExtrusion(files))
      EXPECT_LE(drawnBack, 0.01) << plan->dir << ": step " << step << "'s program";
    if (plan->sliced->stitchedFile.empty()) continue;
    for (const auto& [step, drawnBack] : drawnBackAtFirstExtrusion({plan->dir + "/" + plan->sliced->stitchedFile}))
      EXPECT_LE(drawnBack, 0.01) << plan->dir << ": step " << step << " in " << plan->sliced->stitchedFile;
  }
}

TEST(SliceJob, ProgressMovesWhileTheSlicersRun) {
  // Not one report per step: the slicers' own stages move the progress inside a step's share.
  const SlicedPlan& plan = bunnyOnTheRobot();
  ASSERT_TRUE(plan.sliced.ok()) << plan.sliced.error().describe();
  const double n = static_cast<double>(plan.sliced->steps.size());
  const double firstStepDone = 1.0 / (n + 1.0);  // no comparison: one share per step and one for the rest
  int insideTheFirstShare = 0;
  bool namesAPercent = false;
  for (const auto& [fraction, phase] : plan.progress) {
    if (fraction > 0.0 && fraction < firstStepDone) ++insideTheFirstShare;
    namesAPercent = namesAPercent || phase.find(" %)") != std::string::npos;
  }
  EXPECT_GE(insideTheFirstShare, 2);
  EXPECT_TRUE(namesAPercent);
}

TEST(SliceJob, ThePlacedPartIsWhatThePrintJobFileDescribes) {
  // One placement for every step: print-job.json's poses and step meshes are those the G-code was sliced from.
  const SlicedPlan& plan = kittenOnTheRotaryAxis();
  ASSERT_TRUE(plan.sliced.ok()) << plan.sliced.error().describe();
  const nlohmann::json written = nlohmann::json::parse(test::readFile(plan.dir + "/print-job.json"));
  const PrinterProfile& profile = plan.sliced->profile;
  for (std::size_t k = 0; k < plan.sliced->steps.size(); ++k) {
    const SlicedStep& step = plan.sliced->steps[k];
    const nlohmann::json& m = written["steps"][k]["modelToFile"];
    Eigen::Matrix4d fromFile = Eigen::Matrix4d::Identity();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) fromFile(r, c) = m[r][c].get<double>();
    Eigen::Isometry3d toPrinter = Eigen::Isometry3d::Identity();
    toPrinter.translation() = Vec3(profile.platformCenter.x(), profile.platformCenter.y(), profile.platformZMm);
    EXPECT_LT(((toPrinter.matrix() * fromFile) - step.modelToPrinter.matrix()).cwiseAbs().maxCoeff(), 1e-6)
        << "step " << step.index;
    EXPECT_NEAR(written["steps"][k]["lowestHeightMm"].get<double>() + profile.platformZMm, step.baseZMm, 1e-6);
  }
}

// The output folder: a new job replaces an earlier one only once it is complete, a folder holding other files
// is refused unless allowed, and nothing is ever written through a link planted in it.
namespace {

// An earlier job as `multidir slice` leaves it: print-job.json of ours and the step files it names.
void writeEarlierJob(const std::string& folder, int steps) {
  fs::create_directories(folder);
  std::ofstream(folder + "/print-job.json") << R"({"schema": "multidir-print-job", "version": 1, "earlier": true})";
  for (int k = 1; k <= steps; ++k) {
    const std::string stem = folder + "/step-0" + std::to_string(k);
    std::ofstream(stem + ".gcode") << "; the earlier job's step " << k << "\n";
    std::ofstream(stem + "-region.stl") << "solid earlier\nendsolid earlier\n";
  }
}

// Every entry of a folder with its content (a folder's as "<folder>"), to compare before and after.
std::map<std::string, std::string> contentOf(const std::string& folder) {
  std::map<std::string, std::string> entries;
  for (const auto& entry : fs::directory_iterator(folder))
    entries[entry.path().filename().string()] =
        entry.is_directory() ? std::string("<folder>") : test::readFile(entry.path().string());
  return entries;
}

}  // namespace

TEST(SliceJobFolder, AFailedSliceLeavesTheEarlierJobInTheFolderAsItWas) {
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("failed-reslice");
  writeEarlierJob(dir + "/out", 2);
  const std::map<std::string, std::string> before = contentOf(dir + "/out");
  SliceJobOptions options = coarseOptions(0.3);
  options.slicerExecutable = fakeSlicer(dir + "/failing-slicer.sh", "exit 3\n");
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, dir + "/out", context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::ExternalToolFailed) << sliced.error().describe();
  EXPECT_EQ(contentOf(dir + "/out"), before);
  // Nothing is left beside it either: the fresh folder the job was written into is gone.
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().rfind(".out.", 0), 0u) << entry.path();
}

TEST(SliceJobFolder, AFolderHoldingOtherFilesIsRefusedBeforeAnythingIsSlicedOrWritten) {
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("other-files");
  fs::create_directories(dir + "/out");
  std::ofstream(dir + "/out/notes.txt") << "the user's own notes\n";
  const std::string mark = dir + "/the-slicer-ran";
  SliceJobOptions options = coarseOptions(0.3);
  options.slicerExecutable = fakeSlicer(dir + "/marking-slicer.sh", "touch '" + mark + "'\nexit 1\n");
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, dir + "/out", context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::InvalidParameter) << sliced.error().describe();
  EXPECT_EQ(sliced.error().where, dir + "/out");
  EXPECT_NE(sliced.error().message.find("'notes.txt'"), std::string::npos) << sliced.error().message;
  EXPECT_NE(sliced.error().message.find("--force"), std::string::npos) << sliced.error().message;
  EXPECT_NE(sliced.error().message.find("empty folder"), std::string::npos) << sliced.error().message;
  EXPECT_FALSE(fs::exists(mark)) << "the slicer ran for a folder that was refused";
  EXPECT_EQ(contentOf(dir + "/out"), (std::map<std::string, std::string>{{"notes.txt", "the user's own notes\n"}}));
}

TEST(SliceJobFolder, ANewJobReplacesAnEarlierLongerJobAsAWhole) {
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("replace-earlier");
  writeEarlierJob(dir + "/out", 3);
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), coarseOptions(0.3), dir + "/out", context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  // The one-step job and nothing of the earlier three-step one.
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir + "/out")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"print-job.json", "step-01-region.stl", "step-01.gcode"}));
  EXPECT_NE(test::readFile(dir + "/out/print-job.json").find("\"slicing\""), std::string::npos);
  EXPECT_EQ(test::readFile(dir + "/out/step-01.gcode").find("the earlier job"), std::string::npos);
}

TEST(SliceJobFolder, WritingIntoAFolderHoldingOtherFilesWhenAllowedKeepsThem) {
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("allowed-other-files");
  fs::create_directories(dir + "/out");
  std::ofstream(dir + "/out/notes.txt") << "the user's own notes\n";
  SliceJobOptions options = coarseOptions(0.3);
  options.writeIntoOtherFolder = true;
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, dir + "/out", context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  EXPECT_EQ(test::readFile(dir + "/out/notes.txt"), "the user's own notes\n");
  EXPECT_TRUE(fs::exists(dir + "/out/step-01.gcode"));
  EXPECT_NE(test::readFile(dir + "/out/print-job.json").find("\"slicing\""), std::string::npos);
}

TEST(SliceJobFolder, LinksPlantedAtTheJobsFileNamesAreNeverWrittenThrough) {
  // Links where the job's files, their temporaries and the work folder go, in a folder holding an earlier
  // job: whatever they point to stays as it was.
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("planted-links");
  const std::string out = dir + "/out";
  writeEarlierJob(out, 1);
  std::ofstream(dir + "/victim.txt") << "not MultiDir's\n";
  fs::create_directories(dir + "/victim-folder");
  for (const char* name : {"step-01.gcode.part", "print-job.json.part", "step-02.gcode"})
    fs::create_symlink(dir + "/victim.txt", out + "/" + name);
  fs::create_directory_symlink(dir + "/victim-folder", out + "/.slicing-" + std::to_string(::getpid()));
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), coarseOptions(0.3), out, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  EXPECT_EQ(test::readFile(dir + "/victim.txt"), "not MultiDir's\n");
  EXPECT_TRUE(fs::is_empty(dir + "/victim-folder"));
  EXPECT_FALSE(fs::is_symlink(out + "/step-01.gcode"));
  EXPECT_NE(test::readFile(out + "/step-01.gcode").find("; MULTIDIR STEP 1"), std::string::npos);
}

TEST(SliceJob, AnOutOfRangeSlicerSettingIsRefusedNamingTheKeyAndTheRange) {
  // Over the profile (--set): the slicer would have printed `M104 S1` for this temperature.
  const core::PrintJob job = oneBoxJob(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  const std::string dir = scratch("setting-range");
  const std::string mark = dir + "/the-slicer-ran";
  SliceJobOptions options = coarseOptions(0.3);
  options.settings.push_back({"temperature", "1e308"});
  options.slicerExecutable = fakeSlicer(dir + "/marking-slicer.sh", "touch '" + mark + "'\nexit 1\n");
  core::JobContext context;
  const auto sliced = sliceJob(job, profileNamed("marlin-220"), options, dir + "/out", context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::InvalidParameter) << sliced.error().describe();
  EXPECT_NE(sliced.error().where.find("temperature"), std::string::npos) << sliced.error().describe();
  EXPECT_NE(sliced.error().message.find("[0, 500]"), std::string::npos) << sliced.error().message;
  EXPECT_FALSE(fs::exists(mark));
}
