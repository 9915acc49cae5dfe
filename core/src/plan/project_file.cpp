// saveProject and loadProject: the .multidir project file (docs/plan-format.md, "Project files").
#include "multidir/core/plan/project_file.h"

#include <cmath>
#include <filesystem>
#include <new>

#include "multidir/core/plan/checksum.h"
#include "multidir/core/samples/samples.h"
#include "multidir/core/search/plan_from_planes.h"
#include "plan/json_field.h"
#include "plan/json_file.h"
#include "plan/settings_json.h"

namespace multidir::core {
namespace {

namespace fs = std::filesystem;
using detail::JsonField;
using nlohmann::ordered_json;

constexpr const char* kProjectSchema = "multidir-project";

bool isKnownSample(const std::string& id) {
  for (const samples::SampleInfo& info : samples::catalogue())
    if (info.id == id) return true;
  return false;
}

std::string knownSamples() {
  std::string list;
  for (const samples::SampleInfo& info : samples::catalogue()) list += (list.empty() ? "" : ", ") + info.id;
  return list;
}

// The project file's folder, absolute: model paths are stored relative to it.
fs::path projectFolder(const std::string& projectPath) {
  return fs::absolute(fs::path(projectPath)).lexically_normal().parent_path();
}

// Relative (with '/' separators) when the model lies in the project's folder or below it, else absolute.
std::string storedModelPath(const std::string& modelPath, const fs::path& folder) {
  const fs::path model = fs::absolute(fs::path(modelPath)).lexically_normal();
  const fs::path relative = model.lexically_relative(folder);
  if (!relative.empty() && *relative.begin() != ".." && relative.is_relative()) return relative.generic_string();
  return model.string();
}

std::string resolvedModelPath(const std::string& stored, const fs::path& folder) {
  const fs::path path(stored);
  if (path.is_absolute()) return path.lexically_normal().string();
  return (folder / path).lexically_normal().string();
}

ordered_json planeToJson(const Plane& plane) {
  return {{"normal", detail::toJson(plane.normal)}, {"offsetMm", plane.offset}};
}

ordered_json searchToJson(const SearchOptions& options, int axisSearchCount) {
  ordered_json search = detail::searchOptionsToJson(options);
  search["axisSearchCount"] = axisSearchCount;
  return search;
}

ordered_json planToJson(const ProjectPlan& plan) {
  ordered_json planes = ordered_json::array();
  for (const Plane& plane : plan.clippingPlanes) planes.push_back(planeToJson(plane));
  return {{"machine", detail::machineToJson(plan.machine)},
          {"search", searchToJson(plan.options, plan.axisSearchCount)},
          {"rotationAxis", detail::toJson(plan.rotationAxis)},
          {"jgBeforeMm2", plan.jgBeforeMm2},
          {"jgAfterMm2", plan.jgAfterMm2},
          {"cancelled", plan.cancelled},
          {"clippingPlanes", planes}};
}

ordered_json poseToJson(const ProjectPose& pose) {
  return {{"source", pose.source}, {"contactAreaMm2", pose.contactAreaMm2}, {"platformUp", detail::toJson(pose.platformUp)}};
}

ordered_json projectToJson(const Project& project, const fs::path& folder) {
  const ProjectModel& model = project.model;
  const auto textOrNull = [](const std::string& text) {
    return text.empty() ? ordered_json(nullptr) : ordered_json(text);
  };
  ordered_json modelJson = {
      {"path", model.path.empty() ? ordered_json(nullptr) : ordered_json(storedModelPath(model.path, folder))},
      {"checksum", textOrNull(model.checksum)},
      {"sample", textOrNull(model.sampleId)},
      {"up", detail::toJson(model.up)}};
  // Written only when set: a project without a pose is the same file older versions wrote.
  if (model.pose) modelJson["pose"] = poseToJson(*model.pose);
  return {{"schema", kProjectSchema},
          {"version", kProjectFormatVersion},
          {"multidirVersion", project.multidirVersion},
          {"units", {{"length", "mm"}, {"angle", "degrees"}}},
          {"model", modelJson},
          {"machine", detail::machineToJson(project.machine)},
          {"search", searchToJson(project.options, project.axisSearchCount)},
          {"plan", project.plan ? planToJson(*project.plan) : ordered_json(nullptr)}};
}

// A unit vector as written: plane normals and axes go back exactly as the plan had them (JSON keeps every bit of
// a double), so a rebuilt plan is the same plan. Only a vector that is off by more than rounding (edited by
// hand, within kUnitVectorTolerance) is renormalised.
Vec3 exactUnitVector(const JsonField& field) {
  constexpr double kRoundingSlack = 1e-12;
  const Vec3 v = field.vector();
  const Vec3 unit = field.unitVector();
  return std::abs(v.norm() - 1.0) <= kRoundingSlack ? v : unit;
}

int axisSearchCountFrom(const JsonField& search) {
  return static_cast<int>(search["axisSearchCount"].integer(0, 3600));
}

ProjectModel modelFromJson(const JsonField& field, const fs::path& folder) {
  ProjectModel model;
  const std::optional<JsonField> path = field.optional("path");
  const std::optional<JsonField> sample = field.optional("sample");
  const std::optional<JsonField> checksum = field.optional("checksum");
  if (path && sample) sample->fail("must be null when model.path names a file (a model is a file or a sample)");
  if (!path && !sample) field.fail("names no model: give model.path (a mesh file) or model.sample (a sample id)");
  if (path) {
    const std::string stored = path->string();
    if (stored.empty()) path->fail("is empty; give the model file's path");
    model.path = resolvedModelPath(stored, folder);
  }
  if (sample) {
    model.sampleId = sample->string();
    if (!isKnownSample(model.sampleId))
      sample->fail("is not a sample MultiDir knows (\"" + model.sampleId + "\"); known: " + knownSamples());
  }
  if (checksum) {
    if (sample) checksum->fail("must be null for a sample: a sample has no file");
    model.checksum = checksum->string();
    if (!isChecksumText(model.checksum)) checksum->fail("must be \"fnv1a64:\" followed by 16 hex digits, or null");
  }
  model.up = exactUnitVector(field["up"]);
  if (const std::optional<JsonField> pose = field.optional("pose")) {
    ProjectPose kept;
    const JsonField source = (*pose)["source"];
    kept.source = source.string();
    if (kept.source != "given" && kept.source != "resting" && kept.source != "sampled")
      source.fail("must be \"given\", \"resting\" or \"sampled\"");
    kept.contactAreaMm2 = (*pose)["contactAreaMm2"].numberAtLeast(0.0);
    kept.platformUp = exactUnitVector((*pose)["platformUp"]);
    model.pose = kept;
  }
  return model;
}

ProjectPlan planFromJson(const JsonField& field) {
  ProjectPlan plan;
  plan.machine = detail::machineFromJson(field["machine"], true);
  const JsonField search = field["search"];
  plan.options = detail::searchOptionsFromJson(search);
  plan.axisSearchCount = axisSearchCountFrom(search);
  const JsonField axis = field["rotationAxis"];
  plan.rotationAxis = exactUnitVector(axis);
  if (plan.machine.kind == MachineKind::RotaryPlatform &&
      std::abs(plan.rotationAxis.dot(plan.machine.up)) > detail::kUnitVectorTolerance)
    axis.fail("must lie in the platform plane (perpendicular to plan.machine.up)");
  plan.jgBeforeMm2 = field["jgBeforeMm2"].numberAtLeast(0.0);
  plan.jgAfterMm2 = field["jgAfterMm2"].numberAtLeast(0.0);
  plan.cancelled = field["cancelled"].boolean();
  const JsonField planes = field["clippingPlanes"];
  const std::size_t count = planes.arraySize();
  if (count > kMaxProjectPlanes)
    planes.fail("lists " + std::to_string(count) + " planes; at most " + std::to_string(kMaxProjectPlanes) +
                " are accepted");
  plan.clippingPlanes.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const JsonField plane = planes.element(k);
    plan.clippingPlanes.push_back(Plane{exactUnitVector(plane["normal"]), plane["offsetMm"].number()});
  }
  return plan;
}

Project projectFromJson(const nlohmann::json& document, const std::string& fileName, const fs::path& folder) {
  const JsonField root(document, "", fileName);
  const JsonField schema = root["schema"];
  if (schema.string() != kProjectSchema)
    schema.fail(std::string("must be \"") + kProjectSchema + "\": this is not a MultiDir project");
  const JsonField version = root["version"];
  const long long formatVersion = version.integer(1, 1'000'000);
  if (formatVersion > kProjectFormatVersion)
    version.fail("is " + std::to_string(formatVersion) + ", newer than the version this MultiDir reads (" +
                 std::to_string(kProjectFormatVersion) + "): update MultiDir to open this project");
  Project project;
  project.multidirVersion = root["multidirVersion"].string();
  if (const auto units = root.optional("units")) {
    if (const auto length = units->optional("length"); length && length->string() != "mm")
      length->fail("must be \"mm\"");
    if (const auto angle = units->optional("angle"); angle && angle->string() != "degrees")
      angle->fail("must be \"degrees\"");
  }
  project.model = modelFromJson(root["model"], folder);
  project.machine = detail::machineFromJson(root["machine"], true);
  const JsonField search = root["search"];
  project.options = detail::searchOptionsFromJson(search);
  project.axisSearchCount = axisSearchCountFrom(search);
  if (const auto plan = root.optional("plan")) project.plan = planFromJson(*plan);
  return project;
}

std::string fileNameOf(const std::string& path) {
  const std::string name = fs::path(path).filename().string();
  return name.empty() ? path : name;
}

}  // namespace

ProjectPlan projectPlanOf(const Decomposition& plan, const MachineSpec& machine, const SearchOptions& options,
                          int axisSearchCount) {
  ProjectPlan kept;
  kept.machine = machine;
  kept.options = options;
  kept.axisSearchCount = axisSearchCount;
  kept.rotationAxis = plan.rotationAxis;
  kept.clippingPlanes = plan.clippingPlanes;
  kept.jgBeforeMm2 = plan.jgBeforeMm2;
  kept.jgAfterMm2 = plan.jgAfterMm2;
  kept.cancelled = plan.cancelled;
  return kept;
}

MachineSpec printingMachineOf(const ProjectPlan& plan) {
  MachineSpec machine = plan.machine;
  if (machine.kind == MachineKind::RotaryPlatform) machine.rotationAxis = plan.rotationAxis;
  return machine;
}

Result<Decomposition> rebuildProjectPlan(const TriangleMesh& model, const ProjectPlan& plan) {
  Result<Decomposition> rebuilt =
      planFromClippingPlanes(model, printingMachineOf(plan), plan.options, plan.clippingPlanes);
  if (rebuilt) rebuilt->cancelled = plan.cancelled;
  return rebuilt;
}

Status saveProject(const Project& project, const std::string& path) {
  const std::string name = fileNameOf(path);
  try {
    if (project.model.path.empty() == project.model.sampleId.empty())
      return Error{ErrorCode::InvalidParameter,
                   project.model.path.empty() ? "the project names no model: set model.path or model.sampleId"
                                              : "the project names both a model file and a sample: keep one",
                   name};
    const fs::path folder = projectFolder(path);
    const std::string text = projectToJson(project, folder).dump(2) + "\n";
    try {
      projectFromJson(nlohmann::json::parse(text), name, folder);
    } catch (const detail::JsonFieldError& e) {
      return Error{ErrorCode::InvalidParameter, "the project would not load back: " + e.error().message, name};
    }
    return detail::writeTextFile(path, text, name);
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::WriteFailed, "there is not enough memory to write the project", name};
  } catch (const nlohmann::json::exception& e) {
    // dump() refuses strings that are not UTF-8, which a model path in another encoding can be.
    return Error{ErrorCode::InvalidParameter,
                 std::string("the project cannot be written as JSON (is the model path valid UTF-8?): ") + e.what(),
                 name};
  } catch (const std::exception& e) {
    return Error{ErrorCode::WriteFailed, std::string("writing the project failed: ") + e.what(), name};
  }
}

Result<Project> loadProject(const std::string& path) {
  const std::string name = fileNameOf(path);
  try {
    Result<nlohmann::json> document = detail::readJsonFile(path, name);
    if (!document) return document.error();
    return projectFromJson(*document, name, projectFolder(path));
  } catch (const detail::JsonFieldError& e) {
    return e.error();
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::TooLarge, "there is not enough memory to load this project", name};
  } catch (const std::exception& e) {
    return Error{
        ErrorCode::Internal,
        std::string("unexpected failure while loading the project (") + e.what() + "); please report it with this file",
        name};
  }
}

}  // namespace multidir::core
