#include "multidir/core/plan/plan_file.h"

#include <gtest/gtest.h>

#include <iterator>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

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

PlanMetadata tbarMetadata() {
  PlanMetadata meta;
  meta.modelPath = "tbar.stl";
  meta.modelChecksum = checksumText(fnv1a64("tbar", 4));
  meta.up = Vec3::UnitZ();
  meta.machine.up = Vec3::UnitZ();
  meta.multidirVersion = "test";
  return meta;
}

// The T-bar's plan under the default 5-DOF machine, computed once for the whole file.
const Decomposition& tbarPlan() {
  static const Decomposition plan = [] {
    JobContext job;
    const PlanMetadata meta = tbarMetadata();
    auto result = decompose(multidir::test::makeTBar(10, 30, 80, 10, 10), meta.machine, meta.options, job);
    if (!result.ok()) throw std::runtime_error(result.error().describe());
    return std::move(result).value();
  }();
  return plan;
}

std::string savedTbar(const std::string& testName) {
  const std::string dir = scratchDirectory(testName);
  const Status saved = savePlan(tbarPlan(), tbarMetadata(), dir);
  if (!saved.ok()) throw std::runtime_error(saved.error().describe());
  return dir;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// Saves the T-bar plan, edits plan.json by hand and loads it back: the error loadPlan gives.
Error loadEdited(const std::string& testName, const std::function<void(nlohmann::json&)>& edit) {
  const std::string dir = savedTbar(testName);
  nlohmann::json doc = readJson(dir + "/plan.json");
  edit(doc);
  writeText(dir + "/plan.json", doc.dump(2));
  const Result<LoadedPlan> loaded = loadPlan(dir);
  if (loaded.ok()) return Error{ErrorCode::Internal, "the edited plan loaded", ""};
  return loaded.error();
}

using FloatCorners = std::array<float, 9>;

FloatCorners cornersOf(const TriangleMesh& mesh, std::size_t face) {
  FloatCorners c{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) c[static_cast<std::size_t>(3 * k + i)] = static_cast<float>(mesh.corner(face, k)[i]);
  return c;
}

// Each face's origin keyed by its corners at float precision; with `only`, just the faces `only` has.
std::map<FloatCorners, FaceOrigin> originsByCorners(const TriangleMesh& mesh, const TriangleMesh* only = nullptr) {
  std::set<FloatCorners> wanted;
  if (only)
    for (std::size_t f = 0; f < only->faceCount(); ++f) wanted.insert(cornersOf(*only, f));
  std::map<FloatCorners, FaceOrigin> origins;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    if (!only || wanted.count(cornersOf(mesh, f))) origins.emplace(cornersOf(mesh, f), mesh.origins[f]);
  return origins;
}

MachineSpec everyFieldSet() {
  MachineSpec m;
  m.kind = MachineKind::RotaryPlatform;
  m.up = Vec3(0, 1, 0);
  m.platformRadiusMm = 80.5;
  m.platformMarginMm = 2.25;
  m.rotationAxis = Vec3(0, 0, -1);
  m.minAngleDegrees = -75.0;
  m.maxAngleDegrees = 35.5;
  m.angleStepDegrees = 0.9;
  m.maxTiltDegrees = 70.0;
  m.forbiddenCones = {{Vec3(1, 0, 0), 12.5}, {Vec3(0.6, 0.8, 0), 30.0}};
  return m;
}

}  // namespace

TEST(Checksum, Fnv1a64MatchesThePublishedTestVectors) {
  EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a64("foobar", 6), 0x85944171f73967e8ull);
}

TEST(Checksum, DataGivenInPiecesHashesAsAWhole) {
  EXPECT_EQ(fnv1a64("bar", 3, fnv1a64("foo", 3)), fnv1a64("foobar", 6));
}

TEST(Checksum, FileChecksumIsTheTextOfItsBytesHash) {
  const std::string dir = scratchDirectory("Checksum.File");
  writeText(dir + "/foobar.txt", "foobar");
  const Result<std::string> sum = fileChecksum(dir + "/foobar.txt");
  ASSERT_TRUE(sum.ok()) << sum.error().describe();
  EXPECT_EQ(*sum, "fnv1a64:85944171f73967e8");
  EXPECT_TRUE(isChecksumText(*sum));
  EXPECT_FALSE(isChecksumText("fnv1a64:85944171F73967E8"));
  EXPECT_FALSE(isChecksumText("sha256:85944171f73967e8"));
}

TEST(Checksum, MissingFileIsFileNotFound) {
  const Result<std::string> sum = fileChecksum("/nonexistent/model.stl");
  ASSERT_FALSE(sum.ok());
  EXPECT_EQ(sum.error().code, ErrorCode::FileNotFound);
}

TEST(PlanFile, SaveWritesPlanJsonAndOneStlPerRegion) {
  const std::string dir = savedTbar("PlanFile.Files");
  ASSERT_GE(tbarPlan().regions.size(), 3u);
  EXPECT_TRUE(fs::exists(dir + "/plan.json"));
  for (std::size_t i = 1; i <= tbarPlan().regions.size(); ++i) {
    const std::string name = dir + "/region-0" + std::to_string(i) + ".stl";
    EXPECT_TRUE(fs::exists(name)) << name;
  }
  const nlohmann::json doc = readJson(dir + "/plan.json");
  EXPECT_EQ(doc["schema"], "multidir-plan");
  EXPECT_EQ(doc["version"], 1);
  EXPECT_EQ(doc["regions"][0]["file"], "region-01.stl");
}

TEST(PlanFile, RoundTripKeepsPlanesRegionsOriginsAndVolumes) {
  const Decomposition& plan = tbarPlan();
  const Result<LoadedPlan> loaded = loadPlan(savedTbar("PlanFile.RoundTrip"));
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const Decomposition& back = loaded->decomposition;

  ASSERT_EQ(back.clippingPlanes.size(), plan.clippingPlanes.size());
  for (std::size_t k = 0; k < plan.clippingPlanes.size(); ++k) {
    EXPECT_EQ(back.clippingPlanes[k].normal, plan.clippingPlanes[k].normal);
    EXPECT_EQ(back.clippingPlanes[k].offset, plan.clippingPlanes[k].offset);
  }
  ASSERT_EQ(back.regions.size(), plan.regions.size());
  for (std::size_t i = 0; i < plan.regions.size(); ++i) {
    const Region& a = plan.regions[i];
    const Region& b = back.regions[i];
    SCOPED_TRACE("region " + std::to_string(i));
    // Slivers thinner than float precision are left out of the STL, nothing else.
    EXPECT_LE(b.mesh.triangles.size(), a.mesh.triangles.size());
    EXPECT_GE(b.mesh.triangles.size() + 4, a.mesh.triangles.size());
    EXPECT_EQ(originsByCorners(b.mesh), originsByCorners(a.mesh, &b.mesh));
    EXPECT_EQ(b.clippingIndex, a.clippingIndex);
    EXPECT_EQ(b.basePlane.has_value(), a.basePlane.has_value());
    EXPECT_EQ(b.printingDirection, a.printingDirection);
    EXPECT_EQ(b.volumeMm3, a.volumeMm3);
    EXPECT_EQ(b.riskyAreaMm2, a.riskyAreaMm2);
    EXPECT_EQ(b.angles.tiltDegrees, a.angles.tiltDegrees);
    EXPECT_EQ(b.angles.azimuthDegrees, a.angles.azimuthDegrees);
    // The mesh itself went through float (binary STL): the same solid within float rounding.
    EXPECT_NEAR(signedVolume(b.mesh), a.volumeMm3, 1e-4 * a.volumeMm3);
  }
  EXPECT_EQ(back.jgBeforeMm2, plan.jgBeforeMm2);
  EXPECT_EQ(back.jgAfterMm2, plan.jgAfterMm2);
  EXPECT_EQ(back.cancelled, plan.cancelled);
  EXPECT_EQ(back.statistics.candidatesScored, plan.statistics.candidatesScored);
  EXPECT_EQ(back.statistics.levels, plan.statistics.levels);
}

TEST(PlanFile, RoundTripKeepsTheMetadata) {
  const std::string dir = savedTbar("PlanFile.Metadata");
  const Result<LoadedPlan> loaded = loadPlan(dir + "/plan.json");  // the file works as well as its folder
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const PlanMetadata expected = tbarMetadata();
  const PlanMetadata& meta = loaded->metadata;
  EXPECT_EQ(meta.modelPath, expected.modelPath);
  EXPECT_EQ(meta.modelChecksum, expected.modelChecksum);
  EXPECT_EQ(meta.up, expected.up);
  EXPECT_EQ(meta.machine.kind, expected.machine.kind);
  EXPECT_EQ(meta.options.beamWidth, expected.options.beamWidth);
  EXPECT_EQ(meta.options.candidates.normalSamples, expected.options.candidates.normalSamples);
  EXPECT_EQ(meta.multidirVersion, "test");
  EXPECT_EQ(loaded->formatVersion, kPlanFormatVersion);
}

TEST(PlanFile, SaveCreatesMissingFolders) {
  const std::string dir = scratchDirectory("PlanFile.Folders") + "/a/b/plan";
  ASSERT_TRUE(savePlan(tbarPlan(), tbarMetadata(), dir).ok());
  EXPECT_TRUE(loadPlan(dir).ok());
}

TEST(PlanFile, SaveWhereAFileStandsIsWriteFailed) {
  const std::string dir = scratchDirectory("PlanFile.FileInTheWay");
  writeText(dir + "/taken", "x");
  const Status saved = savePlan(tbarPlan(), tbarMetadata(), dir + "/taken");
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::WriteFailed);
  EXPECT_NE(saved.error().message.find("a file of this name exists"), std::string::npos) << saved.error().describe();
}

TEST(PlanFile, SaveRefusesRegionsWhoseOriginsDoNotMatchTheirFaces) {
  Decomposition plan = tbarPlan();
  plan.regions[1].mesh.origins.pop_back();
  const std::string dir = scratchDirectory("PlanFile.BadOrigins") + "/plan";
  const Status saved = savePlan(plan, tbarMetadata(), dir);
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::InvalidParameter);
  EXPECT_NE(saved.error().message.find("region 1 has"), std::string::npos) << saved.error().describe();
  EXPECT_FALSE(fs::exists(dir)) << "nothing is written for a refused plan";
}

TEST(PlanFile, SaveRefusesWhatLoadWouldRefuse) {
  PlanMetadata meta = tbarMetadata();
  meta.modelChecksum = "md5:1234";
  const Status saved = savePlan(tbarPlan(), meta, scratchDirectory("PlanFile.BadChecksum") + "/plan");
  ASSERT_FALSE(saved.ok());
  EXPECT_NE(saved.error().message.find("model.checksum must be"), std::string::npos) << saved.error().describe();
}

TEST(PlanFile, MissingFolderOrPlanJsonIsFileNotFound) {
  const Result<LoadedPlan> loaded = loadPlan(scratchDirectory("PlanFile.Empty"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::FileNotFound);
  EXPECT_EQ(loaded.error().where, "plan.json");
}

TEST(PlanFile, MissingRegionFileIsFileNotFoundNamingIt) {
  const std::string dir = savedTbar("PlanFile.MissingRegion");
  fs::remove(dir + "/region-02.stl");
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::FileNotFound);
  EXPECT_EQ(loaded.error().where, "region-02.stl");
  EXPECT_NE(loaded.error().message.find("regions[1].file"), std::string::npos) << loaded.error().describe();
}

TEST(PlanFile, RegionFileOfAnotherSolidIsRefusedByItsTriangleCount) {
  const std::string dir = savedTbar("PlanFile.ForeignRegion");
  ASSERT_TRUE(saveMesh(multidir::test::makeBox(Vec3(0, 0, 0), Vec3(1, 1, 1)), dir + "/region-02.stl").ok());
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  // The 684-byte box cannot hold the region's triangles: refused by size before anything is read.
  EXPECT_EQ(loaded.error().where, "region-02.stl");
  EXPECT_NE(loaded.error().message.find("regions[1].triangles"), std::string::npos) << loaded.error().describe();
}

TEST(PlanFile, TriangleClaimsBeyondWhatTheRegionFileHoldsAreRefusedBeforeAllocating) {
  // 50 million triangles per region would cost 400 MB of face origins each before the file was looked at.
  const Error error = loadEdited("PlanFile.HugeClaim", [](nlohmann::json& d) {
    d["regions"][0]["triangles"] = 50'000'000;
    d["regions"][0]["faceOrigins"] = "s0+50000000";
  });
  EXPECT_EQ(error.code, ErrorCode::MalformedFile) << error.describe();
  EXPECT_NE(error.message.find("regions[0].triangles is 50000000"), std::string::npos) << error.describe();
  EXPECT_NE(error.message.find("holds at most"), std::string::npos) << error.describe();
}

TEST(PlanFile, NonFiniteNumberNamesTheField) {
  const std::string dir = savedTbar("PlanFile.NonFinite");
  std::ifstream in(dir + "/plan.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = "\"volumeMm3\": ";
  const std::size_t at = text.find(key, text.find("\"regions\""));
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = text.find_first_of(",\n}", at + key.size());
  text.replace(at + key.size(), end - at - key.size(), "1e999");
  writeText(dir + "/plan.json", text);
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile) << loaded.error().describe();
  EXPECT_NE(loaded.error().describe().find("plan.json: regions[0].volumeMm3 is '1e999'"), std::string::npos)
      << loaded.error().describe();
}

TEST(PlanFile, UnreadableRegionFileGivesItsLoadError) {
  const std::string dir = savedTbar("PlanFile.GarbageRegion");
  writeText(dir + "/region-01.stl", "solid nothing\nfacet normal oops\n");
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().where, "region-01.stl");
}

TEST(PlanFile, InvalidJsonIsMalformedWithTheByteOffset) {
  const std::string dir = savedTbar("PlanFile.InvalidJson");
  writeText(dir + "/plan.json", "{\"schema\": \"multidir-plan\",, }");
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(loaded.error().describe().find("plan.json: not valid JSON (syntax error near byte"), std::string::npos)
      << loaded.error().describe();
}

// Each hand edit of plan.json and the message that names what is wrong.
struct EditCase {
  const char* name;
  std::function<void(nlohmann::json&)> edit;
  const char* message;
};

class PlanFileEdits : public testing::TestWithParam<EditCase> {};

TEST_P(PlanFileEdits, AreRefusedNamingTheField) {
  const EditCase& c = GetParam();
  const Error error = loadEdited(std::string("PlanFile.Edit.") + c.name, c.edit);
  EXPECT_NE(error.code, ErrorCode::Internal) << error.message;
  EXPECT_NE(error.describe().find(c.message), std::string::npos) << error.describe();
}

INSTANTIATE_TEST_SUITE_P(
    PlanFile, PlanFileEdits,
    testing::Values(
        EditCase{"WrongSchema", [](nlohmann::json& d) { d["schema"] = "something-else"; },
                 "plan.json: schema must be \"multidir-plan\""},
        EditCase{"NewerVersion", [](nlohmann::json& d) { d["version"] = 2; },
                 "plan.json: version is 2, newer than the version this MultiDir reads (1)"},
        EditCase{"VersionAsText", [](nlohmann::json& d) { d["version"] = "1"; },
                 "plan.json: version must be a whole number, not a string"},
        EditCase{"DirectionNotUnit",
                 [](nlohmann::json& d) {
                   d["regions"][2]["printingDirection"] = {0.0, 0.0, 2.0};
                 },
                 "plan.json: regions[2].printingDirection is not a unit vector"},
        EditCase{"DirectionNotAVector",
                 [](nlohmann::json& d) {
                   d["regions"][1]["printingDirection"] = {1.0, 0.0};
                 },
                 "plan.json: regions[1].printingDirection must be an array of three numbers"},
        EditCase{"DirectionOffItsBase",
                 [](nlohmann::json& d) {
                   d["regions"][1]["printingDirection"] = {0.0, 0.0, 1.0};
                 },
                 "plan.json: regions[1].printingDirection differs from its base plane's normal"},
        EditCase{"FirstDirectionNotUp",
                 [](nlohmann::json& d) {
                   d["regions"][0]["printingDirection"] = {1.0, 0.0, 0.0};
                 },
                 "plan.json: regions[0].printingDirection must be machine.up"},
        EditCase{"DirectionBeyondTheMachine", [](nlohmann::json& d) { d["machine"]["maxTiltDegrees"] = 5.0; },
                 "plan.json: regions[1].printingDirection cannot be printed by the 5dof machine"},
        EditCase{"MissingVolume", [](nlohmann::json& d) { d["regions"][0].erase("volumeMm3"); },
                 "plan.json: regions[0].volumeMm3 is missing"},
        EditCase{"NegativeVolume", [](nlohmann::json& d) { d["regions"][0]["volumeMm3"] = -5.0; },
                 "plan.json: regions[0].volumeMm3 must be a positive volume"},
        EditCase{"NegativeRiskyArea", [](nlohmann::json& d) { d["regions"][1]["riskyAreaMm2"] = -1.0; },
                 "plan.json: regions[1].riskyAreaMm2 must be at least 0"},
        EditCase{"TiltOutOfRange", [](nlohmann::json& d) { d["regions"][1]["angles"]["tiltDegrees"] = 200.0; },
                 "plan.json: regions[1].angles.tiltDegrees must be between 0 and 180 degrees"},
        EditCase{"PlaneRemoved", [](nlohmann::json& d) { d["clippingPlanes"].erase(0); }, "clipping planes make"},
        EditCase{"PlaneNormalNotUnit",
                 [](nlohmann::json& d) {
                   d["clippingPlanes"][0]["normal"] = {1.0, 1.0, 0.0};
                 },
                 "plan.json: clippingPlanes[0].normal is not a unit vector"},
        EditCase{"BasePlaneMoved",
                 [](nlohmann::json& d) {
                   d["regions"][1]["basePlane"]["offsetMm"] =
                       d["regions"][1]["basePlane"]["offsetMm"].get<double>() + 1;
                 },
                 "plan.json: regions[1].basePlane differs from clippingPlanes["},
        EditCase{"FirstRegionOnAPlane",
                 [](nlohmann::json& d) { d["regions"][0]["basePlane"] = d["regions"][1]["basePlane"]; },
                 "plan.json: regions[0].basePlane must be null"},
        EditCase{"ClippingIndexWrong", [](nlohmann::json& d) { d["regions"][1]["clippingIndex"] = -1; },
                 "plan.json: regions[1].clippingIndex must be"},
        EditCase{
            "TrianglesDisagreeWithOrigins",
            [](nlohmann::json& d) { d["regions"][0]["triangles"] = d["regions"][0]["triangles"].get<long long>() + 1; },
            "plan.json: regions[0].faceOrigins describes"},
        EditCase{"OriginsGarbage", [](nlohmann::json& d) { d["regions"][0]["faceOrigins"] = "x1 s2"; },
                 "plan.json: regions[0].faceOrigins: run 1 ('x1') must start with s (surface face) or c"},
        EditCase{"OriginsCapOfAMissingPlane",
                 [](nlohmann::json& d) {
                   const long long n = d["regions"][0]["triangles"].get<long long>();
                   d["regions"][0]["faceOrigins"] = "c9*" + std::to_string(n);
                 },
                 "plan.json: regions[0].faceOrigins names the cap of clipping plane 9"},
        EditCase{"RegionFileOutsideTheFolder", [](nlohmann::json& d) { d["regions"][0]["file"] = "../evil.stl"; },
                 "plan.json: regions[0].file must be the name of an .stl file in the plan's folder"},
        EditCase{"RegionFileTwice", [](nlohmann::json& d) { d["regions"][1]["file"] = "region-01.stl"; },
                 "plan.json: regions[1].file names 'region-01.stl', which an earlier region already uses"},
        EditCase{"UnknownMachine", [](nlohmann::json& d) { d["machine"]["kind"] = "7dof"; },
                 "plan.json: machine.kind must be \"3dof\", \"4dof\", \"5dof\" or \"apart\""},
        EditCase{"MachineFieldMissing", [](nlohmann::json& d) { d["machine"].erase("platformMarginMm"); },
                 "plan.json: machine.platformMarginMm is missing"},
        EditCase{"BeamWidthZero", [](nlohmann::json& d) { d["search"]["beamWidth"] = 0; },
                 "plan.json: search: beam width must be between 1 and 1000"},
        EditCase{"VolumeScalesFive", [](nlohmann::json& d) { d["search"]["volumeScales"] = 5; },
                 "plan.json: search: volume scales must be between 1 and 4"},
        EditCase{"VolumeScalesZero", [](nlohmann::json& d) { d["search"]["volumeScales"] = 0; },
                 "plan.json: search: volume scales must be between 1 and 4"},
        EditCase{"UnknownScheme", [](nlohmann::json& d) { d["search"]["scheme"] = "random"; },
                 "plan.json: search.scheme must be \"beam\", \"greedy\" or \"cgreedy\""},
        EditCase{"BadChecksum", [](nlohmann::json& d) { d["model"]["checksum"] = "abc"; },
                 "plan.json: model.checksum must be \"fnv1a64:\" followed by 16 hex digits"},
        EditCase{"JgAsText", [](nlohmann::json& d) { d["result"]["jgAfterMm2"] = "small"; },
                 "plan.json: result.jgAfterMm2 must be a number, not a string"},
        EditCase{"CancelledAsNumber", [](nlohmann::json& d) { d["result"]["cancelled"] = 0; },
                 "plan.json: result.cancelled must be true or false"},
        EditCase{"RegionsNotAnArray", [](nlohmann::json& d) { d["regions"] = nlohmann::json::object(); },
                 "plan.json: regions must be an array, not an object"},
        EditCase{"LengthInInches", [](nlohmann::json& d) { d["units"]["length"] = "inch"; },
                 "plan.json: units.length must be \"mm\""}),
    [](const testing::TestParamInfo<EditCase>& info) { return std::string(info.param.name); });

TEST(PlanFile, SearchSettingsKeepTheirVolumeScales) {
  PlanMetadata meta = tbarMetadata();
  meta.options.volumeScales = 3;
  const std::string dir = scratchDirectory("PlanFile.VolumeScales");
  ASSERT_TRUE(savePlan(tbarPlan(), meta, dir).ok());
  EXPECT_EQ(readJson(dir + "/plan.json")["search"]["volumeScales"], 3);
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->metadata.options.volumeScales, 3);
}

TEST(PlanFile, PlanWrittenBeforeVolumeScalesReadsAsSearchedAtOneScale) {
  // Plans saved before the beam ran at several scales have no search.volumeScales: they ran at w alone.
  const std::string dir = savedTbar("PlanFile.NoVolumeScales");
  nlohmann::json doc = readJson(dir + "/plan.json");
  ASSERT_EQ(doc["search"]["volumeScales"], SearchOptions{}.volumeScales);
  ASSERT_NE(SearchOptions{}.volumeScales, 1) << "the default would hide a reader that ignores the field";
  doc["search"].erase("volumeScales");
  writeText(dir + "/plan.json", doc.dump(2));
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->metadata.options.volumeScales, 1);
}

TEST(PlanFile, SearchSettingsKeepTheApartPartsPrices) {
  PlanMetadata meta = tbarMetadata();
  meta.options.partCostMm2 = 75.0;
  meta.options.cutFaceCost = 0.5;
  const std::string dir = scratchDirectory("PlanFile.PartPrices");
  ASSERT_TRUE(savePlan(tbarPlan(), meta, dir).ok());
  EXPECT_EQ(readJson(dir + "/plan.json")["search"]["cutFaceCost"], 0.5);
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->metadata.options.partCostMm2, 75.0);
  EXPECT_EQ(loaded->metadata.options.cutFaceCost, 0.5);
}

TEST(PlanFile, PlanWrittenBeforeTheCutFaceWasPricedReadsWithoutACutFacePrice) {
  // Plans saved before the cut face was priced have no search.cutFaceCost: a part had its fixed price only.
  const std::string dir = savedTbar("PlanFile.NoCutFaceCost");
  nlohmann::json doc = readJson(dir + "/plan.json");
  ASSERT_NE(SearchOptions{}.cutFaceCost, 0.0) << "the default would hide a reader that ignores the field";
  doc["search"].erase("cutFaceCost");
  writeText(dir + "/plan.json", doc.dump(2));
  const Result<LoadedPlan> loaded = loadPlan(dir);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->metadata.options.cutFaceCost, 0.0);
}

TEST(PlanFile, SaveWhereARegionFileIsAFolderFailsNamingThatFile) {
  // Region files are written side by side; the one that cannot be written is the one named.
  const std::string dir = scratchDirectory("PlanFile.RegionFileIsAFolder");
  ASSERT_GE(tbarPlan().regions.size(), 3u);
  fs::create_directories(dir + "/region-02.stl");
  const Status saved = savePlan(tbarPlan(), tbarMetadata(), dir);
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::WriteFailed) << saved.error().describe();
  EXPECT_NE(saved.error().describe().find("region-02.stl"), std::string::npos) << saved.error().describe();
  EXPECT_EQ(saved.error().describe().find("region-01.stl"), std::string::npos) << saved.error().describe();
  EXPECT_EQ(saved.error().describe().find("region-03.stl"), std::string::npos) << saved.error().describe();
  EXPECT_FALSE(fs::exists(dir + "/plan.json")) << "plan.json is written only after every region file";
}

TEST(PlanFile, UnknownFieldsAreIgnored) {
  const std::string dir = savedTbar("PlanFile.UnknownFields");
  nlohmann::json doc = readJson(dir + "/plan.json");
  doc["comment"] = "printed on the lab's printer";
  doc["regions"][0]["colour"] = "red";
  writeText(dir + "/plan.json", doc.dump(2));
  const Result<LoadedPlan> loaded = loadPlan(dir);
  EXPECT_TRUE(loaded.ok()) << loaded.error().describe();
}

TEST(MachineProfile, RoundTripKeepsEveryField) {
  const std::string path = scratchDirectory("MachineProfile.RoundTrip") + "/rotary.json";
  const MachineSpec m = everyFieldSet();
  ASSERT_TRUE(saveMachineProfile(m, path).ok());
  const Result<MachineSpec> back = loadMachineProfile(path);
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_EQ(back->kind, m.kind);
  EXPECT_EQ(back->up, m.up);
  EXPECT_EQ(back->platformRadiusMm, m.platformRadiusMm);
  EXPECT_EQ(back->platformMarginMm, m.platformMarginMm);
  EXPECT_EQ(back->rotationAxis, m.rotationAxis);
  EXPECT_EQ(back->minAngleDegrees, m.minAngleDegrees);
  EXPECT_EQ(back->maxAngleDegrees, m.maxAngleDegrees);
  EXPECT_EQ(back->angleStepDegrees, m.angleStepDegrees);
  EXPECT_EQ(back->maxTiltDegrees, m.maxTiltDegrees);
  ASSERT_EQ(back->forbiddenCones.size(), 2u);
  EXPECT_EQ(back->forbiddenCones[1].axis, m.forbiddenCones[1].axis);
  EXPECT_EQ(back->forbiddenCones[1].halfAngleDegrees, 30.0);
}

TEST(MachineProfile, SavingAnInvalidMachineIsRefused) {
  MachineSpec m = everyFieldSet();
  m.angleStepDegrees = 0.0;
  const std::string path = scratchDirectory("MachineProfile.SaveInvalid") + "/bad.json";
  const Status saved = saveMachineProfile(m, path);
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::InvalidParameter);
  EXPECT_FALSE(fs::exists(path));
}

TEST(MachineProfile, LoadingAValueOutOfRangeIsRefusedNamingIt) {
  const std::string path = scratchDirectory("MachineProfile.LoadInvalid") + "/bad.json";
  writeText(path, R"({"schema": "multidir-machine", "version": 1, "kind": "4dof", "up": [0, 0, 1],
                      "rotationAxis": [1, 0, 0], "angleStepDegrees": 0})");
  const Result<MachineSpec> loaded = loadMachineProfile(path);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(loaded.error().describe(), "bad.json: angle step must be above 0 and at most 90 degrees");
}

TEST(MachineProfile, LoadingARotationAxisThatIsNotUnitNamesTheField) {
  const std::string path = scratchDirectory("MachineProfile.NotUnit") + "/bad.json";
  writeText(path, R"({"schema": "multidir-machine", "version": 1, "kind": "4dof", "rotationAxis": [2, 0, 0]})");
  const Result<MachineSpec> loaded = loadMachineProfile(path);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(loaded.error().describe().find("bad.json: rotationAxis is not a unit vector"), std::string::npos)
      << loaded.error().describe();
}

TEST(MachineProfile, FieldsLeftOutTakeTheirDefaults) {
  const std::string path = scratchDirectory("MachineProfile.Defaults") + "/printer.json";
  writeText(path, R"({"schema": "multidir-machine", "version": 1, "kind": "3dof", "up": [0, 1, 0]})");
  const Result<MachineSpec> loaded = loadMachineProfile(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->kind, MachineKind::ThreeAxis);
  EXPECT_EQ(loaded->up, Vec3(0, 1, 0));
  EXPECT_EQ(loaded->platformMarginMm, MachineSpec{}.platformMarginMm);
}

TEST(MachineProfile, APlanFileIsNotAProfile) {
  const std::string dir = savedTbar("MachineProfile.NotAProfile");
  const Result<MachineSpec> loaded = loadMachineProfile(dir + "/plan.json");
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().describe().find("plan.json: schema must be \"multidir-machine\""), std::string::npos)
      << loaded.error().describe();
}
