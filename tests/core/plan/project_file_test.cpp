#include "multidir/core/plan/project_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "multidir/core/plan/checksum.h"
#include "multidir/core/samples/samples.h"
#include "multidir/core/search/decompose.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::scratchDirectory;

namespace {

namespace fs = std::filesystem;

// A 4-DOF project whose every field differs from its default, so a round trip that drops one shows.
Project fullProject(const std::string& modelPath) {
  Project project;
  project.model.path = modelPath;
  project.model.checksum = checksumText(fnv1a64("model", 5));
  project.model.up = Vec3::UnitY();
  MachineSpec& machine = project.machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.platformRadiusMm = 42.5;
  machine.platformMarginMm = 3.25;
  machine.rotationAxis = Vec3::UnitZ();
  machine.minAngleDegrees = -45.0;
  machine.maxAngleDegrees = 30.0;
  machine.angleStepDegrees = 1.8;
  machine.maxTiltDegrees = 70.0;
  machine.forbiddenCones = {{Vec3::UnitX(), 12.5}};
  SearchOptions& options = project.options;
  options.scheme = SearchScheme::ConstrainedGreedy;
  options.beamWidth = 7;
  options.alphaMaxDegrees = 50.0;
  options.candidates.normalSamples = 123;
  options.candidates.offsetStepMm = 0.75;
  options.candidates.platformClearanceMm = 0.5;
  options.minVolumeDivisor = 12.0;
  options.volumeScales = 3;
  options.initialDeltaMm2 = 2.5;
  options.deltaGrowth = 3.0;
  options.diversityCosine = 0.9;
  options.diversityOffsetMm = 1.5;
  options.platformToleranceMm = 0.01;
  options.threads = 3;
  project.axisSearchCount = 12;
  ProjectPlan plan;
  plan.machine = machine;
  plan.machine.angleStepDegrees = 0.9;
  plan.options = options;
  plan.options.beamWidth = 4;
  plan.axisSearchCount = 6;
  plan.rotationAxis = Vec3(1, 0, 1).normalized();
  plan.clippingPlanes = {{Vec3(0, 1, 1).normalized(), 12.345678901234567}, {Vec3::UnitX(), -3.5}};
  plan.jgBeforeMm2 = 700.125;
  plan.jgAfterMm2 = 1.0 / 3.0;
  plan.cancelled = true;
  project.plan = plan;
  project.multidirVersion = "test";
  return project;
}

Project sampleProject() {
  Project project;
  project.model.sampleId = samples::catalogue().front().id;
  project.multidirVersion = "test";
  return project;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Saves the full project, edits its JSON by hand and loads it back: the error loadProject gives.
Error loadEdited(const std::string& testName, const std::function<void(nlohmann::json&)>& edit) {
  const std::string dir = scratchDirectory(testName);
  const std::string path = dir + "/edited.multidir";
  const Status saved = saveProject(fullProject(dir + "/model.stl"), path);
  if (!saved) return Error{ErrorCode::Internal, "saving failed: " + saved.error().describe(), ""};
  nlohmann::json doc = readJson(path);
  edit(doc);
  writeText(path, doc.dump(2));
  const Result<Project> loaded = loadProject(path);
  if (loaded) return Error{ErrorCode::Internal, "the edited project loaded", ""};
  return loaded.error();
}

void expectSameMachine(const MachineSpec& a, const MachineSpec& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.up, b.up);
  EXPECT_EQ(a.platformRadiusMm, b.platformRadiusMm);
  EXPECT_EQ(a.platformMarginMm, b.platformMarginMm);
  EXPECT_EQ(a.rotationAxis, b.rotationAxis);
  EXPECT_EQ(a.minAngleDegrees, b.minAngleDegrees);
  EXPECT_EQ(a.maxAngleDegrees, b.maxAngleDegrees);
  EXPECT_EQ(a.angleStepDegrees, b.angleStepDegrees);
  EXPECT_EQ(a.maxTiltDegrees, b.maxTiltDegrees);
  ASSERT_EQ(a.forbiddenCones.size(), b.forbiddenCones.size());
  for (std::size_t i = 0; i < a.forbiddenCones.size(); ++i) {
    EXPECT_EQ(a.forbiddenCones[i].axis, b.forbiddenCones[i].axis);
    EXPECT_EQ(a.forbiddenCones[i].halfAngleDegrees, b.forbiddenCones[i].halfAngleDegrees);
  }
}

void expectSameOptions(const SearchOptions& a, const SearchOptions& b) {
  EXPECT_EQ(a.scheme, b.scheme);
  EXPECT_EQ(a.beamWidth, b.beamWidth);
  EXPECT_EQ(a.alphaMaxDegrees, b.alphaMaxDegrees);
  EXPECT_EQ(a.candidates.normalSamples, b.candidates.normalSamples);
  EXPECT_EQ(a.candidates.offsetStepMm, b.candidates.offsetStepMm);
  EXPECT_EQ(a.candidates.platformClearanceMm, b.candidates.platformClearanceMm);
  EXPECT_EQ(a.minVolumeDivisor, b.minVolumeDivisor);
  EXPECT_EQ(a.volumeScales, b.volumeScales);
  EXPECT_EQ(a.initialDeltaMm2, b.initialDeltaMm2);
  EXPECT_EQ(a.deltaGrowth, b.deltaGrowth);
  EXPECT_EQ(a.diversityCosine, b.diversityCosine);
  EXPECT_EQ(a.diversityOffsetMm, b.diversityOffsetMm);
  EXPECT_EQ(a.platformToleranceMm, b.platformToleranceMm);
  EXPECT_EQ(a.threads, b.threads);
}

}  // namespace

TEST(ProjectFile, SaveWritesOneJsonFileWithSchemaAndVersion) {
  const std::string dir = scratchDirectory("ProjectSchema");
  ASSERT_TRUE(saveProject(fullProject(dir + "/model.stl"), dir + "/a.multidir").ok());
  const nlohmann::json doc = readJson(dir + "/a.multidir");
  EXPECT_EQ(doc["schema"], "multidir-project");
  EXPECT_EQ(doc["version"], kProjectFormatVersion);
  EXPECT_FALSE(fs::exists(dir + "/a.multidir.partial")) << "the atomic write leaves no partial file behind";
}

TEST(ProjectFile, RoundTripKeepsEveryField) {
  const std::string dir = scratchDirectory("ProjectRoundTrip");
  const Project project = fullProject(dir + "/model.stl");
  ASSERT_TRUE(saveProject(project, dir + "/a.multidir").ok());
  const Result<Project> loaded = loadProject(dir + "/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->model.path, fs::path(dir + "/model.stl").lexically_normal().string());
  EXPECT_EQ(loaded->model.checksum, project.model.checksum);
  EXPECT_TRUE(loaded->model.sampleId.empty());
  EXPECT_EQ(loaded->model.up, project.model.up);
  expectSameMachine(loaded->machine, project.machine);
  expectSameOptions(loaded->options, project.options);
  EXPECT_EQ(loaded->axisSearchCount, 12);
  EXPECT_EQ(loaded->multidirVersion, "test");
  ASSERT_TRUE(loaded->plan.has_value());
  const ProjectPlan& plan = *loaded->plan;
  expectSameMachine(plan.machine, project.plan->machine);
  expectSameOptions(plan.options, project.plan->options);
  EXPECT_EQ(plan.axisSearchCount, 6);
  EXPECT_EQ(plan.rotationAxis, project.plan->rotationAxis);
  ASSERT_EQ(plan.clippingPlanes.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(plan.clippingPlanes[k].normal, project.plan->clippingPlanes[k].normal) << "plane " << k;
    EXPECT_EQ(plan.clippingPlanes[k].offset, project.plan->clippingPlanes[k].offset) << "plane " << k;
  }
  EXPECT_EQ(plan.jgBeforeMm2, project.plan->jgBeforeMm2);
  EXPECT_EQ(plan.jgAfterMm2, project.plan->jgAfterMm2);
  EXPECT_TRUE(plan.cancelled);
}

TEST(ProjectFile, ProjectWithoutPlanHasNoneAfterLoading) {
  const std::string dir = scratchDirectory("ProjectNoPlan");
  Project project = fullProject(dir + "/model.stl");
  project.plan.reset();
  ASSERT_TRUE(saveProject(project, dir + "/a.multidir").ok());
  EXPECT_TRUE(readJson(dir + "/a.multidir")["plan"].is_null());
  const Result<Project> loaded = loadProject(dir + "/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_FALSE(loaded->plan.has_value());
}

TEST(ProjectFile, PoseChosenByAPoseSearchRoundTrips) {
  const std::string dir = scratchDirectory("ProjectPose");
  Project project = fullProject(dir + "/model.stl");
  project.model.up = Vec3(0.12, 0.98, -0.1).normalized();
  project.machine.up = project.model.up;
  project.machine.rotationAxis = project.model.up.unitOrthogonal();
  project.plan.reset();
  project.model.pose = ProjectPose{"resting", 812.5, Vec3::UnitZ()};
  ASSERT_TRUE(saveProject(project, dir + "/a.multidir").ok());
  EXPECT_EQ(readJson(dir + "/a.multidir")["model"]["pose"]["source"], "resting");
  const Result<Project> loaded = loadProject(dir + "/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->model.up, project.model.up) << "bit for bit";
  ASSERT_TRUE(loaded->model.pose.has_value());
  EXPECT_EQ(loaded->model.pose->source, "resting");
  EXPECT_EQ(loaded->model.pose->contactAreaMm2, 812.5);
  EXPECT_EQ(loaded->model.pose->platformUp, Vec3::UnitZ());
}

TEST(ProjectFile, ProjectWithoutAPoseWritesNoneAndReadsNone) {
  const std::string dir = scratchDirectory("ProjectNoPose");
  ASSERT_TRUE(saveProject(fullProject(dir + "/model.stl"), dir + "/a.multidir").ok());
  EXPECT_FALSE(readJson(dir + "/a.multidir")["model"].contains("pose")) << "older readers see the file they knew";
  const Result<Project> loaded = loadProject(dir + "/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_FALSE(loaded->model.pose.has_value());
}

TEST(ProjectFile, PoseWithAnUnknownSourceIsRefusedByName) {
  const Error error = loadEdited("ProjectPoseSource", [](nlohmann::json& d) {
    d["model"]["pose"] = {{"source", "guessed"}, {"contactAreaMm2", 0.0}, {"platformUp", {0, 0, 1}}};
  });
  EXPECT_EQ(error.code, ErrorCode::MalformedFile);
  EXPECT_NE(error.describe().find("model.pose.source must be"), std::string::npos) << error.describe();
}

TEST(ProjectFile, ModelBelowTheProjectFolderIsStoredRelativeAndFollowsAMove) {
  const std::string dir = scratchDirectory("ProjectRelative");
  fs::create_directories(dir + "/old/meshes");
  ASSERT_TRUE(saveProject(fullProject(dir + "/old/meshes/../meshes/model.stl"), dir + "/old/a.multidir").ok());
  EXPECT_EQ(readJson(dir + "/old/a.multidir")["model"]["path"], "meshes/model.stl");

  fs::rename(dir + "/old", dir + "/new");
  const Result<Project> loaded = loadProject(dir + "/new/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->model.path, fs::path(dir + "/new/meshes/model.stl").lexically_normal().string());
}

TEST(ProjectFile, ModelOutsideTheProjectFolderIsStoredAbsolute) {
  const std::string dir = scratchDirectory("ProjectAbsolute");
  fs::create_directories(dir + "/projects");
  const std::string model = fs::path(dir + "/model.stl").lexically_normal().string();
  ASSERT_TRUE(saveProject(fullProject(model), dir + "/projects/a.multidir").ok());
  EXPECT_EQ(readJson(dir + "/projects/a.multidir")["model"]["path"], model);
  const Result<Project> loaded = loadProject(dir + "/projects/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->model.path, model);
}

TEST(ProjectFile, HandWrittenRelativePathIsResolvedAgainstTheProjectFolder) {
  const std::string dir = scratchDirectory("ProjectHandRelative");
  fs::create_directories(dir + "/projects");
  ASSERT_TRUE(saveProject(fullProject(dir + "/model.stl"), dir + "/projects/a.multidir").ok());
  nlohmann::json doc = readJson(dir + "/projects/a.multidir");
  doc["model"]["path"] = "../model.stl";
  writeText(dir + "/projects/a.multidir", doc.dump());
  const Result<Project> loaded = loadProject(dir + "/projects/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->model.path, fs::path(dir + "/model.stl").lexically_normal().string());
}

TEST(ProjectFile, HandWrittenNormalWithSixDigitsIsRenormalised) {
  const std::string dir = scratchDirectory("ProjectHandNormal");
  ASSERT_TRUE(saveProject(fullProject(dir + "/model.stl"), dir + "/a.multidir").ok());
  nlohmann::json doc = readJson(dir + "/a.multidir");
  doc["plan"]["clippingPlanes"][0]["normal"] = {0, 0.6, 0.8000004};
  writeText(dir + "/a.multidir", doc.dump());
  const Result<Project> loaded = loadProject(dir + "/a.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_NEAR(loaded->plan->clippingPlanes[0].normal.norm(), 1.0, 1e-15);
}

TEST(ProjectFile, SampleProjectNamesTheSampleAndNoFile) {
  const std::string dir = scratchDirectory("ProjectSample");
  ASSERT_TRUE(saveProject(sampleProject(), dir + "/s.multidir").ok());
  const nlohmann::json doc = readJson(dir + "/s.multidir");
  EXPECT_TRUE(doc["model"]["path"].is_null());
  EXPECT_TRUE(doc["model"]["checksum"].is_null());
  const Result<Project> loaded = loadProject(dir + "/s.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->model.sampleId, samples::catalogue().front().id);
  EXPECT_TRUE(loaded->model.path.empty());
  EXPECT_TRUE(loaded->model.checksum.empty());
}

TEST(ProjectFile, EverySampleOfTheCatalogueRoundTrips) {
  const std::string dir = scratchDirectory("ProjectEverySample");
  for (const samples::SampleInfo& info : samples::catalogue()) {
    Project project = sampleProject();
    project.model.sampleId = info.id;
    const std::string path = dir + "/" + info.id + ".multidir";
    ASSERT_TRUE(saveProject(project, path).ok()) << info.id;
    const Result<Project> loaded = loadProject(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
    EXPECT_EQ(loaded->model.sampleId, info.id);
  }
}

TEST(ProjectFile, SaveRefusesAProjectWithoutAModelOrWithTwo) {
  const std::string dir = scratchDirectory("ProjectNoModel");
  Project none = sampleProject();
  none.model.sampleId.clear();
  const Status noModel = saveProject(none, dir + "/a.multidir");
  ASSERT_FALSE(noModel.ok());
  EXPECT_EQ(noModel.error().code, ErrorCode::InvalidParameter);
  EXPECT_NE(noModel.error().message.find("names no model"), std::string::npos) << noModel.error().describe();

  Project both = sampleProject();
  both.model.path = dir + "/model.stl";
  const Status twoModels = saveProject(both, dir + "/a.multidir");
  ASSERT_FALSE(twoModels.ok());
  EXPECT_NE(twoModels.error().message.find("both"), std::string::npos) << twoModels.error().describe();
  EXPECT_FALSE(fs::exists(dir + "/a.multidir"));
}

TEST(ProjectFile, SaveRefusesWhatLoadWouldRefuse) {
  const std::string dir = scratchDirectory("ProjectSaveChecks");
  Project unknown = sampleProject();
  unknown.model.sampleId = "teapot";
  const Status saved = saveProject(unknown, dir + "/a.multidir");
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(saved.error().where, "a.multidir");
  EXPECT_NE(saved.error().message.find("model.sample is not a sample MultiDir knows"), std::string::npos)
      << saved.error().describe();

  Project badPlane = fullProject(dir + "/model.stl");
  badPlane.plan->clippingPlanes[1].normal = Vec3(0, 0, 2);
  const Status planeSaved = saveProject(badPlane, dir + "/a.multidir");
  ASSERT_FALSE(planeSaved.ok());
  EXPECT_NE(planeSaved.error().message.find("plan.clippingPlanes[1].normal is not a unit vector"), std::string::npos)
      << planeSaved.error().describe();
  EXPECT_FALSE(fs::exists(dir + "/a.multidir")) << "nothing is written for a refused project";
}

TEST(ProjectFile, SaveIntoAMissingFolderIsWriteFailed) {
  const std::string dir = scratchDirectory("ProjectMissingFolder");
  const Status saved = saveProject(sampleProject(), dir + "/no/such/folder/a.multidir");
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::WriteFailed);
}

TEST(ProjectFile, MissingFileIsFileNotFound) {
  const Result<Project> loaded = loadProject(scratchDirectory("ProjectMissing") + "/none.multidir");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::FileNotFound);
}

TEST(ProjectFile, InvalidJsonIsMalformedWithTheByteOffset) {
  const std::string dir = scratchDirectory("ProjectInvalidJson");
  writeText(dir + "/a.multidir", "{\"schema\": \"multidir-project\", ");
  const Result<Project> loaded = loadProject(dir + "/a.multidir");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_EQ(loaded.error().where, "a.multidir");
  EXPECT_NE(loaded.error().message.find("near byte"), std::string::npos) << loaded.error().describe();
}

TEST(ProjectFile, VersionFromTheFutureIsRefused) {
  const Error error = loadEdited("ProjectFutureVersion", [](nlohmann::json& doc) { doc["version"] = 2; });
  EXPECT_EQ(error.code, ErrorCode::MalformedFile);
  EXPECT_EQ(error.where, "edited.multidir");
  EXPECT_NE(error.message.find("version is 2, newer than the version this MultiDir reads (1)"), std::string::npos)
      << error.describe();
}

TEST(ProjectFile, OtherSchemaIsNotAProject) {
  const Error error = loadEdited("ProjectSchemaWrong", [](nlohmann::json& doc) { doc["schema"] = "multidir-plan"; });
  EXPECT_NE(error.message.find("this is not a MultiDir project"), std::string::npos) << error.describe();
}

TEST(ProjectFile, UnknownFieldsAreIgnored) {
  const std::string dir = scratchDirectory("ProjectUnknownFields");
  ASSERT_TRUE(saveProject(sampleProject(), dir + "/a.multidir").ok());
  nlohmann::json doc = readJson(dir + "/a.multidir");
  doc["comment"] = "added by hand";
  doc["model"]["colour"] = "red";
  writeText(dir + "/a.multidir", doc.dump());
  EXPECT_TRUE(loadProject(dir + "/a.multidir").ok());
}

// Each malformed field is refused, and the message names it (file in `where`, the field's path in the text).
struct MalformedCase {
  const char* name;
  std::function<void(nlohmann::json&)> edit;
  ErrorCode code;
  const char* field;
};

TEST(ProjectFile, EachMalformedFieldIsRefusedByName) {
  const std::vector<MalformedCase> cases = {
      {"schemaMissing", [](nlohmann::json& d) { d.erase("schema"); }, ErrorCode::MalformedFile, "schema is missing"},
      {"versionText", [](nlohmann::json& d) { d["version"] = "1"; }, ErrorCode::MalformedFile,
       "version must be a whole number"},
      {"versionZero", [](nlohmann::json& d) { d["version"] = 0; }, ErrorCode::MalformedFile, "version must be between"},
      {"multidirVersion", [](nlohmann::json& d) { d["multidirVersion"] = 1; }, ErrorCode::MalformedFile,
       "multidirVersion must be a string"},
      {"units", [](nlohmann::json& d) { d["units"]["length"] = "inch"; }, ErrorCode::MalformedFile,
       "units.length must be \"mm\""},
      {"modelMissing", [](nlohmann::json& d) { d.erase("model"); }, ErrorCode::MalformedFile, "model is missing"},
      {"modelNone", [](nlohmann::json& d) { d["model"]["path"] = nullptr; }, ErrorCode::MalformedFile,
       "model names no model"},
      {"modelBoth", [](nlohmann::json& d) { d["model"]["sample"] = "snowman"; }, ErrorCode::MalformedFile,
       "model.sample must be null"},
      {"pathEmpty", [](nlohmann::json& d) { d["model"]["path"] = ""; }, ErrorCode::MalformedFile,
       "model.path is empty"},
      {"pathNumber", [](nlohmann::json& d) { d["model"]["path"] = 3; }, ErrorCode::MalformedFile,
       "model.path must be a string"},
      {"checksum", [](nlohmann::json& d) { d["model"]["checksum"] = "md5:1234"; }, ErrorCode::MalformedFile,
       "model.checksum must be"},
      {"sampleChecksum",
       [](nlohmann::json& d) {
         d["model"]["path"] = nullptr;
         d["model"]["sample"] = "snowman";
       },
       ErrorCode::MalformedFile, "model.checksum must be null for a sample"},
      {"sampleUnknown",
       [](nlohmann::json& d) {
         d["model"]["path"] = nullptr;
         d["model"]["checksum"] = nullptr;
         d["model"]["sample"] = "teapot";
       },
       ErrorCode::MalformedFile, "model.sample is not a sample MultiDir knows"},
      {"up",
       [](nlohmann::json& d) {
         d["model"]["up"] = {0, 0, 2};
       },
       ErrorCode::MalformedFile, "model.up is not a unit vector"},
      {"upMissing", [](nlohmann::json& d) { d["model"].erase("up"); }, ErrorCode::MalformedFile, "model.up is missing"},
      {"machineKind", [](nlohmann::json& d) { d["machine"]["kind"] = "6dof"; }, ErrorCode::MalformedFile,
       "machine.kind must be"},
      {"machineField", [](nlohmann::json& d) { d["machine"].erase("maxTiltDegrees"); }, ErrorCode::MalformedFile,
       "machine.maxTiltDegrees is missing"},
      {"machineRange", [](nlohmann::json& d) { d["machine"]["angleStepDegrees"] = 0; }, ErrorCode::InvalidParameter,
       "machine: "},
      {"machineCone", [](nlohmann::json& d) { d["machine"]["forbiddenCones"][0]["axis"] = "x"; },
       ErrorCode::MalformedFile, "machine.forbiddenCones[0].axis must be an array"},
      {"searchScheme", [](nlohmann::json& d) { d["search"]["scheme"] = "best"; }, ErrorCode::MalformedFile,
       "search.scheme must be"},
      {"searchBeam", [](nlohmann::json& d) { d["search"]["beamWidth"] = 2.5; }, ErrorCode::MalformedFile,
       "search.beamWidth must be a whole number"},
      {"searchRange", [](nlohmann::json& d) { d["search"]["beamWidth"] = 0; }, ErrorCode::InvalidParameter, "search: "},
      {"searchThreads", [](nlohmann::json& d) { d["search"].erase("threads"); }, ErrorCode::MalformedFile,
       "search.threads is missing"},
      {"axisCount", [](nlohmann::json& d) { d["search"]["axisSearchCount"] = -1; }, ErrorCode::MalformedFile,
       "search.axisSearchCount must be between"},
      {"planType", [](nlohmann::json& d) { d["plan"] = 5; }, ErrorCode::MalformedFile, "plan must be an object"},
      {"planMachine",
       [](nlohmann::json& d) {
         d["plan"]["machine"]["up"] = {1, 1, 0};
       },
       ErrorCode::MalformedFile, "plan.machine.up is not a unit vector"},
      {"planSearch", [](nlohmann::json& d) { d["plan"]["search"]["offsetStepMm"] = "fine"; }, ErrorCode::MalformedFile,
       "plan.search.offsetStepMm must be a number"},
      {"planAxisCount", [](nlohmann::json& d) { d["plan"]["search"]["axisSearchCount"] = 4000; },
       ErrorCode::MalformedFile, "plan.search.axisSearchCount must be at most 3600"},
      {"planAxis",
       [](nlohmann::json& d) {
         d["plan"]["rotationAxis"] = {0, 1, 0};
       },
       ErrorCode::MalformedFile, "plan.rotationAxis must lie in the platform plane"},
      {"planAxisMissing", [](nlohmann::json& d) { d["plan"].erase("rotationAxis"); }, ErrorCode::MalformedFile,
       "plan.rotationAxis is missing"},
      {"jgBefore", [](nlohmann::json& d) { d["plan"]["jgBeforeMm2"] = -1; }, ErrorCode::MalformedFile,
       "plan.jgBeforeMm2 must be at least 0"},
      {"jgAfter", [](nlohmann::json& d) { d["plan"]["jgAfterMm2"] = "small"; }, ErrorCode::MalformedFile,
       "plan.jgAfterMm2 must be a number"},
      {"cancelled", [](nlohmann::json& d) { d["plan"]["cancelled"] = 0; }, ErrorCode::MalformedFile,
       "plan.cancelled must be true or false"},
      {"planes", [](nlohmann::json& d) { d["plan"]["clippingPlanes"] = nlohmann::json::object(); },
       ErrorCode::MalformedFile, "plan.clippingPlanes must be an array"},
      {"planeNormal",
       [](nlohmann::json& d) {
         d["plan"]["clippingPlanes"][1]["normal"] = {0, 0, 0};
       },
       ErrorCode::MalformedFile, "plan.clippingPlanes[1].normal is not a unit vector"},
      {"planeOffset", [](nlohmann::json& d) { d["plan"]["clippingPlanes"][0].erase("offsetMm"); },
       ErrorCode::MalformedFile, "plan.clippingPlanes[0].offsetMm is missing"},
  };
  for (const MalformedCase& c : cases) {
    const Error error = loadEdited(std::string("ProjectMalformed-") + c.name, c.edit);
    EXPECT_EQ(error.code, c.code) << c.name << ": " << error.describe();
    EXPECT_EQ(error.where, "edited.multidir") << c.name;
    EXPECT_NE(error.message.find(c.field), std::string::npos) << c.name << ": " << error.describe();
  }
}

TEST(ProjectFile, TooManyPlanesAreRefused) {
  const Error error = loadEdited("ProjectTooManyPlanes", [](nlohmann::json& doc) {
    nlohmann::json& planes = doc["plan"]["clippingPlanes"];
    while (planes.size() <= kMaxProjectPlanes) planes.push_back(planes[0]);
  });
  EXPECT_EQ(error.code, ErrorCode::MalformedFile);
  EXPECT_NE(error.message.find("plan.clippingPlanes lists 10001 planes"), std::string::npos) << error.describe();
}

TEST(ProjectFile, RebuiltPlanHasTheSavedPlanesRegionsAndJg) {
  const TriangleMesh tbar = multidir::test::makeTBar(10, 30, 80, 10, 10);
  const MachineSpec machine;
  const SearchOptions options;
  JobContext job;
  const Result<Decomposition> searched = decompose(tbar, machine, options, job);
  ASSERT_TRUE(searched.ok()) << searched.error().describe();
  ASSERT_GE(searched->clippingPlanes.size(), 2u);

  const std::string dir = scratchDirectory("ProjectRebuild");
  Project project = sampleProject();
  project.plan = projectPlanOf(*searched, machine, options, 0);
  ASSERT_TRUE(saveProject(project, dir + "/t.multidir").ok());
  const Result<Project> loaded = loadProject(dir + "/t.multidir");
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();

  const Result<Decomposition> rebuilt = rebuildProjectPlan(tbar, *loaded->plan);
  ASSERT_TRUE(rebuilt.ok()) << rebuilt.error().describe();
  EXPECT_EQ(rebuilt->regions.size(), searched->regions.size());
  EXPECT_NEAR(rebuilt->jgAfterMm2, loaded->plan->jgAfterMm2, 1e-9 * std::max(1.0, loaded->plan->jgAfterMm2));
  EXPECT_NEAR(rebuilt->jgBeforeMm2, loaded->plan->jgBeforeMm2, 1e-9 * loaded->plan->jgBeforeMm2);
}

TEST(ProjectFile, RebuildPrintsA4DofPlanAboutItsSavedAxis) {
  ProjectPlan plan;
  plan.machine.kind = MachineKind::RotaryPlatform;
  plan.machine.rotationAxis = Vec3::UnitX();
  plan.rotationAxis = Vec3::UnitY();
  EXPECT_EQ(printingMachineOf(plan).rotationAxis, Vec3::UnitY());
  plan.machine.kind = MachineKind::TiltRotate;
  EXPECT_EQ(printingMachineOf(plan).rotationAxis, Vec3::UnitX()) << "other machines keep their own axis";
}
