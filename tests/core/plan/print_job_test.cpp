// Print jobs: machinePose turns each region's direction to up, exported regions stand on their base caps in
// the machine frame, model-frame files are the plan's meshes, support files follow the plan, print-job.json
// and the errors.
#include "multidir/core/plan/print_job.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/plan/checksum.h"
#include "multidir/core/search/decompose.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::scratchDirectory;

namespace {

namespace fs = std::filesystem;

// The T-bar stands on its stem; its bar's undersides overhang along +Z.
TriangleMesh tbar() { return multidir::test::makeTBar(10, 30, 80, 10, 10); }

// The same T-bar standing along +Y: a quarter turn about X takes +Z to +Y.
TriangleMesh tbarStandingAlongY() {
  TriangleMesh mesh = tbar();
  for (Vec3& v : mesh.vertices) v = Vec3(v.x(), v.z(), -v.y());
  return mesh;
}

// A rotary platform turning about Y, so it can tilt the bar's arms (which reach along X) upright.
MachineSpec rotaryMachine() {
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitZ();
  machine.rotationAxis = Vec3::UnitY();
  return machine;
}

// A robot arm whose up is +Y, so the machine frame must also turn up to +Z.
MachineSpec armMachineUpY() {
  MachineSpec machine;
  machine.kind = MachineKind::TiltRotate;
  machine.up = Vec3::UnitY();
  return machine;
}

PlanMetadata metadataFor(const MachineSpec& machine) {
  PlanMetadata meta;
  meta.modelPath = "tbar.stl";
  meta.modelChecksum = checksumText(fnv1a64("tbar", 4));
  meta.up = machine.up;
  meta.machine = machine;
  meta.multidirVersion = "test";
  return meta;
}

Decomposition decomposed(const TriangleMesh& model, const MachineSpec& machine) {
  JobContext job;
  auto result = decompose(model, machine, SearchOptions{}, job);
  if (!result.ok()) throw std::runtime_error(result.error().describe());
  if (result->regions.size() < 2) throw std::runtime_error("the T-bar plan was expected to have several regions");
  return std::move(result).value();
}

// Saved and loaded back, as `multidir export` gets it: float meshes from the STLs, origins restored. One
// folder per test: ctest runs tests in parallel processes, each saving its own copy.
LoadedPlan savedAndLoaded(const Decomposition& plan, const MachineSpec& machine,
                          const std::vector<SupportSet>& supports, const std::string& name) {
  const std::string dir = scratchDirectory(name + "." + testing::UnitTest::GetInstance()->current_test_info()->name());
  const Status saved = savePlan(plan, metadataFor(machine), supports, dir);
  if (!saved.ok()) throw std::runtime_error(saved.error().describe());
  auto loaded = loadPlan(dir);
  if (!loaded.ok()) throw std::runtime_error(loaded.error().describe());
  return std::move(loaded).value();
}

const LoadedPlan& rotaryPlan() {
  static const LoadedPlan plan =
      savedAndLoaded(decomposed(tbar(), rotaryMachine()), rotaryMachine(), {}, "PrintJob.RotaryPlan");
  return plan;
}

// A short strut under the second region's centre: supports on one region only.
SupportSet strutUnder(const TriangleMesh& region, int regionIndex, const Vec3& direction) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& v : region.vertices) centre += v;
  centre /= static_cast<double>(region.vertices.size());
  SupportSet set;
  set.regionIndex = regionIndex;
  set.nodes = {{centre, SupportNodeKind::Contact}, {centre - 4.0 * direction, SupportNodeKind::Merge}};
  set.struts = {{0, 1, 0.5, 0.5}};
  set.mesh = supportSolids(set.nodes, set.struts, set.strutSides);
  set.volumeMm3 = signedVolume(set.mesh);
  set.contacts = 1;
  return set;
}

const LoadedPlan& armPlan() {
  static const LoadedPlan plan = [] {
    const Decomposition decomposition = decomposed(tbarStandingAlongY(), armMachineUpY());
    std::vector<SupportSet> supports(decomposition.regions.size());
    for (std::size_t i = 0; i < supports.size(); ++i) supports[i].regionIndex = static_cast<int>(i);
    supports[1] = strutUnder(decomposition.regions[1].mesh, 1, decomposition.regions[1].printingDirection);
    return savedAndLoaded(decomposition, armMachineUpY(), supports, "PrintJob.ArmPlan");
  }();
  return plan;
}

PrintJob built(const LoadedPlan& plan, const PrintJobOptions& options = {}) {
  auto job = buildPrintJob(plan, options);
  if (!job.ok()) throw std::runtime_error(job.error().describe());
  return std::move(job).value();
}

std::string exported(const LoadedPlan& plan, const PrintJobOptions& options, const std::string& name) {
  const std::string dir = scratchDirectory(name) + "/job";
  const Status written = exportPrintJob(plan, options, dir);
  if (!written.ok()) throw std::runtime_error(written.error().describe());
  return dir;
}

// STL repeats every corner: read back with exact welding only and no face dropped, as loadPlan does.
TriangleMesh loadExact(const std::string& path) {
  LoadOptions options;
  options.weldToleranceMm = 0.0;
  options.degenerateAreaMm2 = 0.0;
  auto loaded = loadMesh(path, options);
  if (!loaded.ok()) throw std::runtime_error(loaded.error().describe());
  return loaded->mesh;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

Vec3 vec(const nlohmann::json& a) { return Vec3(a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()); }

double lowestZ(const TriangleMesh& mesh) {
  double low = std::numeric_limits<double>::infinity();
  for (const Vec3& v : mesh.vertices) low = std::min(low, v.z());
  return low;
}

bool exists(const std::string& path) { return fs::exists(path); }

// Every region of a machine-frame job stands on its base: the caps of the plane that cut it off face straight
// down (-Z) and lie at its lowest z, which print-job.json reports as its start height.
void expectRegionsStandOnTheirBaseCaps(const LoadedPlan& plan, const PrintJob& job) {
  ASSERT_EQ(job.steps.size(), plan.decomposition.regions.size());
  for (std::size_t i = 0; i < job.steps.size(); ++i) {
    const PrintJobStep& step = job.steps[i];
    const TriangleMesh& mesh = step.region;
    const double low = lowestZ(mesh);
    EXPECT_NEAR(step.lowestHeightMm, low, 1e-9) << "step " << step.index;
    // The first region's base is the platform plane, through the pivot (the origin); the others' are caps.
    const FaceOrigin base =
        i == 0 ? FaceOrigin::surface(-1) : FaceOrigin::cap(plan.decomposition.regions[i].clippingIndex);
    Vec3 areaNormal = Vec3::Zero();
    double area = 0.0;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
      const bool onBase = i == 0 ? std::abs(mesh.corner(f, 0).z()) < 1e-3 && std::abs(mesh.corner(f, 1).z()) < 1e-3 &&
                                       std::abs(mesh.corner(f, 2).z()) < 1e-3
                                 : mesh.origins[f] == base;
      if (!onBase) continue;
      areaNormal += mesh.areaNormal(f);
      area += mesh.faceArea(f);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(mesh.corner(f, k).z(), low, 1e-3) << "step " << step.index;
    }
    ASSERT_GT(area, 1.0) << "step " << step.index << " has no base";
    EXPECT_GT(-areaNormal.z() / (2.0 * area), 1.0 - 1e-6) << "step " << step.index << "'s base does not face down";
    if (i == 0) {
      EXPECT_NEAR(low, 0.0, 1e-4) << "the first region stands on the platform plane";
    }
  }
}

}  // namespace

TEST(MachinePose, RotaryPoseTurnsEveryRegionsDirectionToUp) {
  const LoadedPlan& plan = rotaryPlan();
  const MachineSpec machine = rotaryMachine();
  const Vec3 pivot(3, -2, 0);
  for (const Region& region : plan.decomposition.regions) {
    const Eigen::Isometry3d pose = machinePose(machine, region.printingDirection, pivot);
    EXPECT_LT((pose.linear() * region.printingDirection - machine.up).norm(), 1e-9)
        << region.printingDirection.transpose();
    EXPECT_LT((pose.linear() * machine.rotationAxis - machine.rotationAxis).norm(), 1e-12) << "turns about r";
    EXPECT_LT((pose * pivot - pivot).norm(), 1e-12) << "the pivot stays where it is";
  }
}

TEST(MachinePose, TiltPoseTurnsEveryRegionsDirectionToUp) {
  const LoadedPlan& plan = armPlan();
  const Vec3 pivot(1, 0, 4);
  for (const Region& region : plan.decomposition.regions) {
    const Eigen::Isometry3d pose = machinePose(armMachineUpY(), region.printingDirection, pivot);
    EXPECT_LT((pose.linear() * region.printingDirection - Vec3::UnitY()).norm(), 1e-9)
        << region.printingDirection.transpose();
    EXPECT_LT((pose * pivot - pivot).norm(), 1e-12);
  }
}

TEST(MachinePose, TiltIsTheSmallestRotationTakingTheDirectionToUp) {
  MachineSpec machine = armMachineUpY();
  machine.maxTiltDegrees = 180.0;
  const int count = 200;
  for (int i = 0; i < count; ++i) {
    // Fibonacci sphere, with both poles included.
    const double y = 1.0 - 2.0 * i / (count - 1);
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = i * kPi * (3.0 - std::sqrt(5.0));
    const Vec3 d(r * std::cos(phi), y, r * std::sin(phi));
    const Eigen::Matrix3d rotation = machinePose(machine, d, Vec3::Zero()).linear();
    EXPECT_LT((rotation * d - machine.up).norm(), 1e-9) << d.transpose();
    const Eigen::AngleAxisd turn(rotation);
    EXPECT_NEAR(turn.angle(), std::acos(std::clamp(d.dot(machine.up), -1.0, 1.0)), 1e-9) << d.transpose();
    if (turn.angle() > 1e-6) {
      EXPECT_NEAR(turn.axis().dot(machine.up), 0.0, 1e-9) << "the tilt axis is horizontal";
    }
  }
}

TEST(MachinePose, StraightDownTurnsHalfwayAboutTheTiltAxisOfAzimuthZero) {
  MachineSpec machine = armMachineUpY();
  machine.maxTiltDegrees = 180.0;
  const Eigen::Matrix3d rotation = machinePose(machine, -machine.up, Vec3::Zero()).linear();
  const Vec3 tiltAxis = machine.up.cross(platformFrameX(machine.up));
  EXPECT_LT((rotation * -machine.up - machine.up).norm(), 1e-12);
  EXPECT_LT((rotation * tiltAxis - tiltAxis).norm(), 1e-12);
}

TEST(MachinePose, ThreeAxisMachineLeavesThePartWhereItIs) {
  MachineSpec machine;
  machine.kind = MachineKind::ThreeAxis;
  const Eigen::Isometry3d pose = machinePose(machine, machine.up, Vec3(5, 6, 7));
  EXPECT_TRUE(pose.matrix().isApprox(Eigen::Matrix4d::Identity()));
}

TEST(PrintJob, RotaryRegionsStandOnTheirBaseCapsFacingDown) {
  expectRegionsStandOnTheirBaseCaps(rotaryPlan(), built(rotaryPlan()));
}

TEST(PrintJob, TiltedRegionsStandOnTheirBaseCapsFacingDownWithUpTurnedToZ) {
  expectRegionsStandOnTheirBaseCaps(armPlan(), built(armPlan()));
}

TEST(PrintJob, EveryRegionPrintedEarlierLiesBelowAStepsStartHeight) {
  // The machine moves the whole part: what was printed before stays below the nozzle's start, or it would
  // collide with it.
  for (const LoadedPlan* plan : {&rotaryPlan(), &armPlan()}) {
    const PrintJob job = built(*plan);
    for (std::size_t i = 1; i < job.steps.size(); ++i)
      for (std::size_t earlier = 0; earlier < i; ++earlier)
        for (const Vec3& v : plan->decomposition.regions[earlier].mesh.vertices)
          ASSERT_LE((job.steps[i].modelToFile * v).z(), job.steps[i].lowestHeightMm + 1e-3)
              << "region " << earlier + 1 << " reaches above the start of step " << i + 1;
  }
}

TEST(PrintJob, RotaryJobTurnsAboutThePlansAxisNotTheProfiles) {
  // An axis search may have turned the profile's axis: the plan's rotation axis is the one printed about.
  LoadedPlan plan = rotaryPlan();
  plan.metadata.machine.rotationAxis = Vec3::UnitX();
  const PrintJob job = built(plan);
  EXPECT_EQ(job.machine.rotationAxis, plan.decomposition.rotationAxis);
  expectRegionsStandOnTheirBaseCaps(plan, job);
}

TEST(PrintJob, ExportedMachineFrameRegionsKeepThePlansVolumes) {
  for (const LoadedPlan* plan : {&rotaryPlan(), &armPlan()}) {
    const std::string dir = exported(*plan, {}, "PrintJob.Volumes");
    for (std::size_t i = 0; i < plan->decomposition.regions.size(); ++i) {
      const Region& region = plan->decomposition.regions[i];
      const TriangleMesh file = loadExact(dir + "/step-0" + std::to_string(i + 1) + "-region.stl");
      EXPECT_NEAR(signedVolume(file), region.volumeMm3, 1e-4 * region.volumeMm3) << "step " << i + 1;
      EXPECT_NEAR(signedVolume(file), signedVolume(region.mesh), 1e-5 * region.volumeMm3) << "step " << i + 1;
    }
  }
}

TEST(PrintJob, ModelFrameFilesAreThePlansMeshes) {
  PrintJobOptions options;
  options.frame = PrintJobOptions::Frame::Model;
  const std::string dir = exported(armPlan(), options, "PrintJob.ModelFrame");
  for (std::size_t i = 0; i < armPlan().decomposition.regions.size(); ++i) {
    const TriangleMesh& planMesh = armPlan().decomposition.regions[i].mesh;
    const TriangleMesh file = loadExact(dir + "/step-0" + std::to_string(i + 1) + "-region.stl");
    EXPECT_EQ(file.vertices, planMesh.vertices) << "step " << i + 1;
    EXPECT_EQ(file.triangles, planMesh.triangles) << "step " << i + 1;
  }
  const PrintJob job = built(armPlan(), options);
  for (const PrintJobStep& step : job.steps) EXPECT_EQ(step.modelToFile.matrix(), Eigen::Matrix4d::Identity());
}

TEST(PrintJob, TextFormatsWriteEveryStepInThatFormat) {
  PrintJobOptions options;
  options.format = "off";
  const std::string dir = exported(rotaryPlan(), options, "PrintJob.Off");
  for (std::size_t i = 0; i < rotaryPlan().decomposition.regions.size(); ++i) {
    const std::string stem = dir + "/step-0" + std::to_string(i + 1) + "-region";
    EXPECT_FALSE(exists(stem + ".stl"));
    const TriangleMesh file = loadExact(stem + ".off");
    EXPECT_EQ(file.faceCount(), rotaryPlan().decomposition.regions[i].mesh.faceCount()) << "step " << i + 1;
  }
  EXPECT_EQ(readJson(dir + "/print-job.json")["steps"][0]["files"]["region"], "step-01-region.off");
}

TEST(PrintJob, SupportFilesExistExactlyForStepsWithSupports) {
  const LoadedPlan& plan = armPlan();
  const std::string dir = exported(plan, {}, "PrintJob.Supports");
  const nlohmann::json doc = readJson(dir + "/print-job.json");
  for (std::size_t i = 0; i < plan.decomposition.regions.size(); ++i) {
    const bool has = !plan.supports[i].empty();
    const std::string file = "step-0" + std::to_string(i + 1) + "-supports.stl";
    EXPECT_EQ(exists(dir + "/" + file), has) << file;
    EXPECT_EQ(doc["steps"][i]["files"]["supports"], has ? nlohmann::json(file) : nlohmann::json(nullptr)) << file;
    EXPECT_DOUBLE_EQ(doc["steps"][i]["supportVolumeMm3"].get<double>(), has ? plan.supports[i].volumeMm3 : 0.0);
  }
  EXPECT_TRUE(exists(dir + "/step-02-supports.stl")) << "the plan has supports on region 2";
}

TEST(PrintJob, NoSupportsOptionLeavesEverySupportOut) {
  PrintJobOptions options;
  options.supports = false;
  const std::string dir = exported(armPlan(), options, "PrintJob.NoSupports");
  const nlohmann::json doc = readJson(dir + "/print-job.json");
  for (std::size_t i = 0; i < armPlan().decomposition.regions.size(); ++i) {
    EXPECT_FALSE(exists(dir + "/step-0" + std::to_string(i + 1) + "-supports.stl"));
    EXPECT_TRUE(doc["steps"][i]["files"]["supports"].is_null());
  }
}

TEST(PrintJob, SupportsMoveWithTheirRegion) {
  const PrintJob job = built(armPlan());
  const PrintJobStep& step = job.steps[1];
  const TriangleMesh& planSupports = armPlan().supports[1].mesh;
  ASSERT_EQ(step.supports.vertexCount(), planSupports.vertexCount());
  for (std::size_t v = 0; v < planSupports.vertexCount(); ++v)
    EXPECT_LT((step.supports.vertices[v] - step.modelToFile * planSupports.vertices[v]).norm(), 1e-9);
  EXPECT_NEAR(signedVolume(step.supports), armPlan().supports[1].volumeMm3, 1e-9 * step.supportVolumeMm3);
}

TEST(PrintJob, JsonDescribesTheMachineAndEveryStep) {
  const LoadedPlan& plan = armPlan();
  const std::string dir = exported(plan, {}, "PrintJob.Json");
  const PrintJob job = built(plan);
  const nlohmann::json doc = readJson(dir + "/print-job.json");
  EXPECT_EQ(doc["schema"], "multidir-print-job");
  EXPECT_EQ(doc["version"], 1);
  EXPECT_EQ(doc["model"]["path"], "tbar.stl");
  EXPECT_EQ(doc["model"]["checksum"], plan.metadata.modelChecksum);
  EXPECT_EQ(doc["machine"]["kind"], "5dof");
  EXPECT_EQ(vec(doc["machine"]["up"]), Vec3::UnitY());
  EXPECT_EQ(doc["frame"], "machine");
  EXPECT_EQ(doc["format"], "stl");
  EXPECT_EQ(doc["pivot"]["name"], "platform centre");
  EXPECT_EQ(vec(doc["pivot"]["point"]), job.platform.center);
  EXPECT_EQ(vec(doc["pivot"]["point"]), platformRegionFor(plan.decomposition.regions[0].mesh, armMachineUpY()).center);
  ASSERT_EQ(doc["steps"].size(), plan.decomposition.regions.size());
  for (std::size_t i = 0; i < plan.decomposition.regions.size(); ++i) {
    const Region& region = plan.decomposition.regions[i];
    const nlohmann::json& step = doc["steps"][i];
    EXPECT_EQ(step["index"], i + 1);
    EXPECT_EQ(step["files"]["region"], "step-0" + std::to_string(i + 1) + "-region.stl");
    EXPECT_EQ(vec(step["printingDirection"]), region.printingDirection);
    const MachineAngles angles = machineAnglesFor(armMachineUpY(), region.printingDirection);
    EXPECT_EQ(step["angles"].size(), 2u) << "a 5-DOF step has a tilt and an azimuth";
    EXPECT_DOUBLE_EQ(step["angles"]["tiltDegrees"].get<double>(), angles.tiltDegrees);
    EXPECT_DOUBLE_EQ(step["angles"]["azimuthDegrees"].get<double>(), angles.azimuthDegrees);
    EXPECT_NEAR(step["angles"]["tiltDegrees"].get<double>(), region.angles.tiltDegrees, 1e-6);
    if (i == 0) {
      EXPECT_TRUE(step["basePlane"].is_null());
    } else {
      EXPECT_EQ(vec(step["basePlane"]["normal"]), region.basePlane->normal);
      EXPECT_EQ(step["basePlane"]["offsetMm"].get<double>(), region.basePlane->offset);
    }
    EXPECT_EQ(step["lowestHeightMm"].get<double>(), job.steps[i].lowestHeightMm);
    EXPECT_EQ(step["volumeMm3"].get<double>(), region.volumeMm3);
    EXPECT_EQ(step["riskyAreaMm2"].get<double>(), region.riskyAreaMm2);
    // modelToFile takes the plan's vertices to the file's.
    const nlohmann::json& m = step["modelToFile"];
    const Vec3& p = region.mesh.vertices[0];
    Vec3 mapped;
    for (int r = 0; r < 3; ++r)
      mapped[r] = m[r][0].get<double>() * p.x() + m[r][1].get<double>() * p.y() + m[r][2].get<double>() * p.z() +
                  m[r][3].get<double>();
    EXPECT_LT((mapped - job.steps[i].region.vertices[0]).norm(), 1e-9);
  }
}

TEST(PrintJob, RotaryJsonGivesTheRotaryAngleAndThePlansAxis) {
  const std::string dir = exported(rotaryPlan(), {}, "PrintJob.RotaryJson");
  const nlohmann::json doc = readJson(dir + "/print-job.json");
  EXPECT_EQ(doc["machine"]["kind"], "4dof");
  EXPECT_EQ(vec(doc["machine"]["rotationAxis"]), rotaryPlan().decomposition.rotationAxis);
  for (std::size_t i = 0; i < rotaryPlan().decomposition.regions.size(); ++i) {
    const nlohmann::json& angles = doc["steps"][i]["angles"];
    ASSERT_EQ(angles.size(), 1u);
    EXPECT_NEAR(angles["rotaryDegrees"].get<double>(), rotaryPlan().decomposition.regions[i].angles.rotaryDegrees,
                1e-6);
  }
}

TEST(PrintJob, FolderThatCannotBeCreatedIsWriteFailed) {
  const std::string dir = scratchDirectory("PrintJob.Unwritable");
  const std::string file = dir + "/not-a-folder";
  std::ofstream(file) << "x";
  for (const std::string& target : {file, file + "/job"}) {
    const Status written = exportPrintJob(rotaryPlan(), {}, target);
    ASSERT_FALSE(written.ok()) << target;
    EXPECT_EQ(written.error().code, ErrorCode::WriteFailed) << target;
    EXPECT_NE(written.error().describe().find("not-a-folder"), std::string::npos) << written.error().describe();
  }
}

TEST(PrintJob, UnknownFormatIsRefusedBeforeAnythingIsWritten) {
  PrintJobOptions options;
  options.format = "3mf";
  const std::string dir = scratchDirectory("PrintJob.Format") + "/job";
  const Status written = exportPrintJob(rotaryPlan(), options, dir);
  ASSERT_FALSE(written.ok());
  EXPECT_EQ(written.error().code, ErrorCode::UnsupportedFormat);
  EXPECT_NE(written.error().message.find("'3mf'"), std::string::npos) << written.error().message;
  EXPECT_NE(written.error().message.find("stl, obj, ply or off"), std::string::npos) << written.error().message;
  EXPECT_FALSE(exists(dir));
}

TEST(PrintJob, InconsistentPlanIsInvalidParameterNamingTheRegion) {
  LoadedPlan fewerSupports = armPlan();
  fewerSupports.supports.pop_back();
  const auto supports = buildPrintJob(fewerSupports, {});
  ASSERT_FALSE(supports.ok());
  EXPECT_EQ(supports.error().code, ErrorCode::InvalidParameter);
  EXPECT_NE(supports.error().message.find("support sets"), std::string::npos) << supports.error().message;

  // A direction off the rotary platform's plane of directions cannot be posed.
  LoadedPlan offAxis = rotaryPlan();
  Region& second = offAxis.decomposition.regions[1];
  second.printingDirection = (second.printingDirection + 0.2 * Vec3::UnitY()).normalized();
  second.basePlane->normal = second.printingDirection;
  const auto direction = buildPrintJob(offAxis, {});
  ASSERT_FALSE(direction.ok());
  EXPECT_EQ(direction.error().code, ErrorCode::InvalidParameter);
  EXPECT_NE(direction.error().message.find("region 2"), std::string::npos) << direction.error().message;

  LoadedPlan empty = rotaryPlan();
  empty.decomposition.regions.clear();
  const auto none = buildPrintJob(empty, {});
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error().code, ErrorCode::InvalidParameter);
}

TEST(PrintJob, ExportReplacesAnOlderJobsDescription) {
  const std::string dir = exported(armPlan(), {}, "PrintJob.Replace");
  PrintJobOptions options;
  options.format = "obj";
  ASSERT_TRUE(exportPrintJob(armPlan(), options, dir).ok());
  const nlohmann::json doc = readJson(dir + "/print-job.json");
  EXPECT_EQ(doc["format"], "obj");
  EXPECT_EQ(doc["steps"][0]["files"]["region"], "step-01-region.obj");
  EXPECT_FALSE(exists(dir + "/print-job.json.partial"));
}

TEST(PrintJobOptions, FramesAndFormatsAreCheckedByName) {
  EXPECT_EQ(parsePrintJobFrame("machine").value(), PrintJobOptions::Frame::Machine);
  EXPECT_EQ(parsePrintJobFrame("model").value(), PrintJobOptions::Frame::Model);
  EXPECT_FALSE(parsePrintJobFrame("printer").ok());
  EXPECT_STREQ(printJobFrameName(PrintJobOptions::Frame::Model), "model");
  for (const char* format : {"stl", "obj", "ply", "off"}) {
    PrintJobOptions options;
    options.format = format;
    EXPECT_TRUE(validate(options).ok()) << format;
  }
  PrintJobOptions upper;
  upper.format = "STL";
  EXPECT_EQ(validate(upper).error().code, ErrorCode::UnsupportedFormat);
}
