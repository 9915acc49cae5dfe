#include "plan/plan_json.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "multidir/core/plan/checksum.h"
#include "plan/face_origin_runs.h"
#include "plan/json_field.h"
#include "plan/settings_json.h"
#include "plan/supports_json.h"

namespace multidir::core::detail {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr const char* kPlanSchema = "multidir-plan";
// Two copies of one plane (a region's base plane and the clipping plane it names) must agree this well.
constexpr double kSamePlaneTolerance = 1e-6;
// Printing directions are checked against the machine with this slack (radians), well above the search's
// rounding and well below a stepper step.
constexpr double kRealizableToleranceRadians = 1e-4;
// Matches LoadOptions::maxTriangles: a region cannot hold more than a loadable model.
constexpr long long kMaxTriangles = 50'000'000;
constexpr long long kMaxCount = std::numeric_limits<int>::max();

ordered_json planeToJson(const Plane& plane) { return {{"normal", toJson(plane.normal)}, {"offsetMm", plane.offset}}; }

Plane planeFromJson(const JsonField& field) { return Plane{field["normal"].unitVector(), field["offsetMm"].number()}; }

bool samePlane(const Plane& a, const Plane& b) {
  return (a.normal - b.normal).norm() <= kSamePlaneTolerance &&
         std::abs(a.offset - b.offset) <= kSamePlaneTolerance * std::max(1.0, std::abs(a.offset));
}

ordered_json statisticsToJson(const SearchStatistics& s) {
  return {{"candidatesScored", s.candidatesScored},
          {"candidatesPerLevel", s.candidatesPerLevel},
          {"normals", s.normals},
          {"levels", s.levels},
          {"clipsPerformed", s.clipsPerformed},
          {"seconds", s.seconds},
          {"threads", s.threads},
          {"proxyFaces", s.proxyFaces},
          {"jgBeforePolishMm2", s.jgBeforePolishMm2},
          {"polishEvaluations", s.polishEvaluations},
          {"polishSeconds", s.polishSeconds},
          {"notes", s.notes}};
}

SearchStatistics statisticsFromJson(const JsonField& field) {
  SearchStatistics s;
  s.candidatesScored = field["candidatesScored"].integer(0, std::numeric_limits<long long>::max());
  s.candidatesPerLevel = static_cast<int>(field["candidatesPerLevel"].integer(0, kMaxCount));
  s.normals = static_cast<int>(field["normals"].integer(0, kMaxCount));
  s.levels = static_cast<int>(field["levels"].integer(0, kMaxCount));
  s.clipsPerformed = static_cast<int>(field["clipsPerformed"].integer(0, kMaxCount));
  s.seconds = field["seconds"].numberAtLeast(0.0);
  s.threads = static_cast<int>(field["threads"].integer(1, kMaxCount));
  // Written since the proxy search; older plans have neither.
  if (const auto proxy = field.optional("proxyFaces")) s.proxyFaces = static_cast<int>(proxy->integer(0, kMaxCount));
  // Written since polishing; older plans (and plans not polished, -1) have it unpolished.
  if (const auto before = field.optional("jgBeforePolishMm2")) s.jgBeforePolishMm2 = before->numberAtLeast(-1.0);
  if (const auto evaluations = field.optional("polishEvaluations"))
    s.polishEvaluations = static_cast<int>(evaluations->integer(0, kMaxCount));
  if (const auto seconds = field.optional("polishSeconds")) s.polishSeconds = seconds->numberAtLeast(0.0);
  if (const auto notes = field.optional("notes"))
    for (std::size_t i = 0; i < notes->arraySize(); ++i) s.notes.push_back(notes->element(i).string());
  return s;
}

ordered_json regionToJson(const Region& region, std::size_t index) {
  ordered_json angles = {{"rotaryDegrees", region.angles.rotaryDegrees},
                         {"tiltDegrees", region.angles.tiltDegrees},
                         {"azimuthDegrees", region.angles.azimuthDegrees}};
  return {{"file", regionFileName(index)},
          {"triangles", region.mesh.triangles.size()},
          {"clippingIndex", region.clippingIndex},
          {"basePlane", region.basePlane ? planeToJson(*region.basePlane) : ordered_json(nullptr)},
          {"printingDirection", toJson(region.printingDirection)},
          {"angles", angles},
          {"volumeMm3", region.volumeMm3},
          {"riskyAreaMm2", region.riskyAreaMm2},
          {"faceOrigins", encodeFaceOrigins(region.mesh.origins)}};
}

ordered_json regionToJsonWithSupports(const Region& region, std::size_t index, const SupportSet* supports) {
  ordered_json out = regionToJson(region, index);
  if (supports && !supports->empty()) out["supports"] = supportsToJson(*supports, index);
  return out;
}

// A file name inside the plan's folder: no folders, no "..", no hidden files, ends in .stl.
bool isPlainStlName(const std::string& name) {
  if (name.size() < 5 || name.size() > 255 || name[0] == '.') return false;
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
          c == '.'))
      return false;
  const std::string ext = name.substr(name.size() - 4);
  return ext == ".stl" || ext == ".STL";
}

void readRegion(const JsonField& field, std::size_t index, std::size_t planeCount, const std::vector<Plane>& planes,
                const MachineSpec& printingMachine, PlanDocument& doc) {
  Region region;
  const JsonField file = field["file"];
  const std::string name = file.string();
  if (!isPlainStlName(name))
    file.fail("must be the name of an .stl file in the plan's folder (letters, digits, '-', '_', '.'; no folders)");
  for (const std::string& other : doc.regionFiles)
    if (other == name) file.fail("names '" + name + "', which an earlier region already uses");
  const auto triangles = static_cast<std::size_t>(field["triangles"].integer(4, kMaxTriangles));

  const JsonField clipping = field["clippingIndex"];
  region.clippingIndex = static_cast<std::int32_t>(clipping.integer(-1, kMaxCount));
  const std::optional<JsonField> base = field.optional("basePlane");
  // Printing order is the inverse of clipping order: region i (i >= 1) was cut off by plane N - i.
  const long long expectedClipping =
      index == 0 ? -1 : static_cast<long long>(planeCount) - static_cast<long long>(index);
  if (region.clippingIndex != expectedClipping)
    clipping.fail("must be " + std::to_string(expectedClipping) + " (region " + std::to_string(index) + " of " +
                  std::to_string(planeCount + 1) + " in printing order was cut off by clipping plane N - " +
                  std::to_string(index) + "; -1 for the first region)");
  if (index == 0 && base) base->fail("must be null: the first region stands on the platform");
  if (index > 0) {
    if (!base) field["basePlane"].fail("is missing: every region after the first stands on a clipping plane");
    region.basePlane = planeFromJson(*base);
    if (!samePlane(*region.basePlane, planes[static_cast<std::size_t>(region.clippingIndex)]))
      base->fail("differs from clippingPlanes[" + std::to_string(region.clippingIndex) + "]");
  }

  const JsonField direction = field["printingDirection"];
  region.printingDirection = direction.unitVector();
  if (index == 0 && (region.printingDirection - printingMachine.up).norm() > kSamePlaneTolerance)
    direction.fail("must be machine.up: the first region is printed on the platform at rest");
  if (region.basePlane && (region.printingDirection - region.basePlane->normal).norm() > kSamePlaneTolerance)
    direction.fail("differs from its base plane's normal (a region is printed along the normal of its base)");
  if (index > 0 && !isRealizable(printingMachine, region.printingDirection, kRealizableToleranceRadians))
    direction.fail(std::string("cannot be printed by the ") + machineKindName(printingMachine.kind) + " machine");

  const JsonField angles = field["angles"];
  const JsonField rotary = angles["rotaryDegrees"], tilt = angles["tiltDegrees"], azimuth = angles["azimuthDegrees"];
  region.angles.rotaryDegrees = rotary.number();
  region.angles.tiltDegrees = tilt.number();
  region.angles.azimuthDegrees = azimuth.number();
  if (std::abs(region.angles.rotaryDegrees) > 180) rotary.fail("must be between -180 and 180 degrees");
  if (region.angles.tiltDegrees < 0 || region.angles.tiltDegrees > 180) tilt.fail("must be between 0 and 180 degrees");
  if (std::abs(region.angles.azimuthDegrees) > 180) azimuth.fail("must be between -180 and 180 degrees");

  const JsonField volume = field["volumeMm3"];
  region.volumeMm3 = volume.number();
  if (!(region.volumeMm3 > 0)) volume.fail("must be a positive volume in mm^3");
  region.riskyAreaMm2 = field["riskyAreaMm2"].numberAtLeast(0.0);

  SupportSet supports;
  supports.regionIndex = static_cast<int>(index);
  std::string supportFile;
  std::size_t supportTriangles = 0;
  if (const auto supportsField = field.optional("supports")) {
    SupportsDocument read = supportsFromJson(*supportsField, index);
    supports = std::move(read.supports);
    supportFile = std::move(read.file);
    supportTriangles = read.triangles;
  }

  const JsonField originsField = field["faceOrigins"];
  Result<std::vector<FaceOrigin>> origins = decodeFaceOrigins(originsField.string(), triangles);
  if (!origins) originsField.failInside(origins.error().message);
  if (origins->size() != triangles)
    originsField.fail("describes " + std::to_string(origins->size()) + " faces but the region has " +
                      std::to_string(triangles) + " triangles");
  for (const FaceOrigin& origin : *origins)
    if (origin.isCap() && static_cast<std::size_t>(origin.index) >= planeCount)
      originsField.fail("names the cap of clipping plane " + std::to_string(origin.index) + ", but the plan has " +
                        std::to_string(planeCount) + " planes");

  doc.regionFiles.push_back(name);
  doc.regionTriangles.push_back(triangles);
  doc.regionOrigins.push_back(std::move(origins).value());
  doc.supportFiles.push_back(std::move(supportFile));
  doc.supportTriangles.push_back(supportTriangles);
  doc.plan.supports.push_back(std::move(supports));
  doc.plan.decomposition.regions.push_back(std::move(region));
}

ordered_json poseToJson(const PlanPose& pose) {
  ordered_json rotation = ordered_json::array();
  for (int r = 0; r < 3; ++r) rotation.push_back({pose.rotation(r, 0), pose.rotation(r, 1), pose.rotation(r, 2)});
  ordered_json runnersUp = ordered_json::array();
  for (const PlanPoseTrial& t : pose.runnersUp)
    runnersUp.push_back({{"up", toJson(t.up)}, {"source", t.source}, {"jgAfterMm2", t.jgAfterMm2},
                         {"regions", t.regions}, {"searched", t.searched}, {"contactAreaMm2", t.contactAreaMm2},
                         {"stabilityMarginMm", t.stabilityMarginMm}});
  return {{"up", toJson(pose.up)}, {"rotation", rotation}, {"source", pose.source},
          {"contactAreaMm2", pose.contactAreaMm2}, {"stabilityMarginMm", pose.stabilityMarginMm},
          {"runnersUp", runnersUp}};
}

PlanPose poseFromJson(const JsonField& field) {
  PlanPose pose;
  pose.up = field["up"].unitVector();
  const JsonField rotation = field["rotation"];
  if (rotation.arraySize() != 3) rotation.fail("must hold three rows");
  for (std::size_t r = 0; r < 3; ++r) pose.rotation.row(static_cast<int>(r)) = rotation.element(r).vector().transpose();
  if (!(pose.rotation * pose.rotation.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-6) ||
      pose.rotation.determinant() < 0)
    rotation.fail("must be a rotation (orthonormal rows, determinant 1)");
  pose.source = field["source"].string();
  pose.contactAreaMm2 = field["contactAreaMm2"].numberAtLeast(0.0);
  // Plans written before the margin was recorded have none.
  if (const auto margin = field.optional("stabilityMarginMm")) pose.stabilityMarginMm = margin->number();
  const JsonField runnersUp = field["runnersUp"];
  for (std::size_t i = 0; i < runnersUp.arraySize(); ++i) {
    const JsonField t = runnersUp.element(i);
    PlanPoseTrial trial;
    trial.up = t["up"].unitVector();
    trial.source = t["source"].string();
    trial.jgAfterMm2 = t["jgAfterMm2"].numberAtLeast(0.0);
    trial.regions = static_cast<int>(t["regions"].integer(0, kMaxCount));
    trial.searched = t["searched"].boolean();
    if (const auto contact = t.optional("contactAreaMm2")) trial.contactAreaMm2 = contact->numberAtLeast(0.0);
    if (const auto margin = t.optional("stabilityMarginMm")) trial.stabilityMarginMm = margin->number();
    pose.runnersUp.push_back(trial);
  }
  return pose;
}

}  // namespace

std::string regionFileName(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "region-%02zu.stl", index + 1);
  return name;
}

ordered_json planToJson(const Decomposition& plan, const PlanMetadata& metadata,
                        const std::vector<SupportSet>& supports) {
  ordered_json planes = ordered_json::array();
  for (const Plane& plane : plan.clippingPlanes) planes.push_back(planeToJson(plane));
  ordered_json regions = ordered_json::array();
  for (std::size_t i = 0; i < plan.regions.size(); ++i)
    regions.push_back(regionToJsonWithSupports(plan.regions[i], i, i < supports.size() ? &supports[i] : nullptr));
  ordered_json search = searchOptionsToJson(metadata.options);
  search["axisSearchCount"] = metadata.axisSearchCount;
  ordered_json document = {{"schema", kPlanSchema},
          {"version", kPlanFormatVersion},
          {"multidirVersion", metadata.multidirVersion},
          {"units", {{"length", "mm"}, {"angle", "degrees"}}},
          {"model",
           {{"path", metadata.modelPath},
            {"checksum", metadata.modelChecksum.empty() ? ordered_json(nullptr) : ordered_json(metadata.modelChecksum)},
            {"up", toJson(metadata.up)}}},
          {"machine", machineToJson(metadata.machine)},
          {"search", search},
          {"result",
           {{"jgBeforeMm2", plan.jgBeforeMm2},
            {"jgAfterMm2", plan.jgAfterMm2},
            {"cancelled", plan.cancelled},
            {"rotationAxis", toJson(plan.rotationAxis)},
            {"statistics", statisticsToJson(plan.statistics)}}},
          {"clippingPlanes", planes},
          {"regions", regions}};
  if (metadata.pose) document["pose"] = poseToJson(*metadata.pose);
  return document;
}

PlanDocument planFromJson(const json& document, const std::string& fileName) {
  const JsonField root(document, "", fileName);
  PlanDocument doc;
  const JsonField schema = root["schema"];
  if (schema.string() != kPlanSchema)
    schema.fail(std::string("must be \"") + kPlanSchema + "\": this is not a MultiDir plan");
  const JsonField version = root["version"];
  const long long formatVersion = version.integer(1, kMaxCount);
  if (formatVersion > kPlanFormatVersion)
    version.fail("is " + std::to_string(formatVersion) + ", newer than the version this MultiDir reads (" +
                 std::to_string(kPlanFormatVersion) + "): update MultiDir to open this plan");
  doc.plan.formatVersion = static_cast<int>(formatVersion);
  PlanMetadata& meta = doc.plan.metadata;
  meta.multidirVersion = root["multidirVersion"].string();
  if (const auto units = root.optional("units")) {
    if (const auto length = units->optional("length"); length && length->string() != "mm")
      length->fail("must be \"mm\"");
    if (const auto angle = units->optional("angle"); angle && angle->string() != "degrees")
      angle->fail("must be \"degrees\"");
  }

  const JsonField model = root["model"];
  meta.modelPath = model["path"].string();
  if (const auto checksum = model.optional("checksum")) {
    meta.modelChecksum = checksum->string();
    if (!isChecksumText(meta.modelChecksum)) checksum->fail("must be \"fnv1a64:\" followed by 16 hex digits, or null");
  }
  meta.up = model["up"].unitVector();
  meta.machine = machineFromJson(root["machine"], true);
  const JsonField search = root["search"];
  meta.options = searchOptionsFromJson(search);
  meta.axisSearchCount = static_cast<int>(search["axisSearchCount"].integer(0, 3600));
  if (const auto pose = root.optional("pose")) meta.pose = poseFromJson(*pose);  // older plans have none

  Decomposition& plan = doc.plan.decomposition;
  const JsonField result = root["result"];
  plan.jgBeforeMm2 = result["jgBeforeMm2"].numberAtLeast(0.0);
  plan.jgAfterMm2 = result["jgAfterMm2"].numberAtLeast(0.0);
  plan.cancelled = result["cancelled"].boolean();
  const JsonField axis = result["rotationAxis"];
  plan.rotationAxis = axis.unitVector();
  plan.statistics = statisticsFromJson(result["statistics"]);
  // 4-DOF plans are printed about the axis the search chose, which an axis search may have turned.
  MachineSpec printingMachine = meta.machine;
  if (printingMachine.kind == MachineKind::RotaryPlatform) {
    printingMachine.rotationAxis = plan.rotationAxis;
    if (std::abs(plan.rotationAxis.dot(printingMachine.up)) > kUnitVectorTolerance)
      axis.fail("must lie in the platform plane (perpendicular to machine.up)");
  }

  const JsonField planes = root["clippingPlanes"];
  const std::size_t planeCount = planes.arraySize();
  for (std::size_t k = 0; k < planeCount; ++k) plan.clippingPlanes.push_back(planeFromJson(planes.element(k)));

  const JsonField regions = root["regions"];
  const std::size_t regionCount = regions.arraySize();
  if (regionCount != planeCount + 1)
    regions.fail("lists " + std::to_string(regionCount) + " regions, but " + std::to_string(planeCount) +
                 " clipping planes make " + std::to_string(planeCount + 1));
  for (std::size_t i = 0; i < regionCount; ++i)
    readRegion(regions.element(i), i, planeCount, plan.clippingPlanes, printingMachine, doc);
  return doc;
}

}  // namespace multidir::core::detail
