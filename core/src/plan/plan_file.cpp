// savePlan and loadPlan: the plan folder (plan.json + region STLs). The JSON side is in plan_json.cpp.
#include "multidir/core/plan/plan_file.h"

#include <set>
#include <filesystem>
#include <new>
#include <optional>
#include <utility>

#include "detail/parallel.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "plan/json_field.h"
#include "plan/json_file.h"
#include "plan/output_folder.h"
#include "plan/plan_json.h"
#include "plan/stl_image.h"
#include "plan/supports_json.h"

namespace multidir::core {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPlanFileName = "plan.json";

// Binary STL repeats every corner as float: only identical corners are one vertex, and no face is dropped
// for being small, so the faces come back one for one, in order, and the origins in plan.json fit them.
LoadOptions regionLoadOptions() {
  LoadOptions options;
  options.weldToleranceMm = 0.0;
  options.degenerateAreaMm2 = 0.0;
  return options;
}

// Loading drops faces of zero area (regionLoadOptions): rounding to float can flatten a sliver.
bool everyFaceHasArea(const TriangleMesh& mesh) {
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (!(mesh.faceArea(f) > 0.0)) return false;
  return true;
}

Error invalid(const std::string& what) { return Error{ErrorCode::InvalidParameter, what, "plan"}; }

// Region i's mesh as its file will hold it: its STL image, checked to load back face for face.
Result<TriangleMesh> regionOnDisk(const Decomposition& plan, std::size_t i) {
  const TriangleMesh& mesh = plan.regions[i].mesh;
  const std::string region = "region " + std::to_string(i);
  if (mesh.empty()) return invalid(region + " has no faces");
  if (mesh.origins.size() != mesh.triangles.size())
    return invalid(region + " has " + std::to_string(mesh.triangles.size()) + " faces but " +
                   std::to_string(mesh.origins.size()) + " face origins");
  detail::StlImage image = detail::stlImage(mesh);
  const std::string name = detail::regionFileName(i);
  // When rounding to float merged no corners and left no face without area, the file loads back as the
  // same vertices and faces, so a closure check of the image is enough; otherwise it is loaded back through
  // every check of loadMesh.
  if (image.mergedCorners == 0 && image.droppedFaces == 0 && everyFaceHasArea(image.mesh) &&
      edgeCensus(image.mesh).closedOriented())
    return std::move(image.mesh);
  const Result<LoadedMesh> reloaded =
      checkAndRepair(RawSoup{image.mesh.vertices, image.mesh.triangles, 0}, regionLoadOptions(), name);
  if (!reloaded || reloaded->mesh.triangles.size() != image.mesh.triangles.size()) {
    // Say what really happened: the input was closed; rounding the cut to float broke it.
    std::string what = "writing region " + std::to_string(i) + " as binary STL (float) ";
    if (image.mergedCorners > 0)
      what += "would merge " + std::to_string(image.mergedCorners) +
              " of its corners that lie closer together than float precision can tell apart";
    else
      what += "would change its faces";
    what += ", and the region read back would not be the region cut (" +
            (reloaded ? std::to_string(image.mesh.triangles.size() - reloaded->mesh.triangles.size()) + " faces lost"
                      : reloaded.error().message) +
            "). This comes from a clipping plane passing within rounding distance of the model's vertices, not "
            "from the model: move that plane slightly (or use another --offset-step) and save again";
    return Error{ErrorCode::WriteFailed, what, name};
  }
  return std::move(image.mesh);
}

// The plan as the files will hold it: region meshes replaced by their STL images, made side by side (a
// million-face plan's images take a good part of its saving time). The first region that fails is named.
Result<Decomposition> planOnDisk(const Decomposition& plan) {
  if (plan.regions.empty()) return invalid("the decomposition has no regions: there is nothing to save");
  std::vector<std::optional<Result<TriangleMesh>>> images(plan.regions.size());
  detail::parallelFor(static_cast<int>(plan.regions.size()), detail::resolveThreadCount(0),
                      [&](int i) { images[static_cast<std::size_t>(i)] = regionOnDisk(plan, static_cast<std::size_t>(i)); });
  // Everything but the regions' meshes is copied: the images take their place (copying a million faces only
  // to drop them filled that much fresh memory). A field added to Region or Decomposition must be named here
  // (the compiler's missing-initializer warning says so).
  Decomposition onDisk{plan.clippingPlanes, {}, plan.jgBeforeMm2, plan.jgAfterMm2, plan.cancelled, plan.rotationAxis,
                       plan.statistics};
  onDisk.regions.reserve(plan.regions.size());
  for (std::size_t i = 0; i < plan.regions.size(); ++i) {
    if (!*images[i]) return images[i]->error();
    const Region& region = plan.regions[i];
    onDisk.regions.push_back(Region{std::move(**images[i]), region.basePlane, region.clippingIndex,
                                    region.printingDirection, region.angles, region.volumeMm3, region.riskyAreaMm2});
  }
  return onDisk;
}

// Writes each mesh to its path, side by side; the first failure in the given order is returned.
Status saveMeshes(const std::vector<std::pair<const TriangleMesh*, std::string>>& files) {
  std::vector<std::optional<Error>> failures(files.size());
  detail::parallelFor(static_cast<int>(files.size()), detail::resolveThreadCount(0), [&](int i) {
    const auto& [mesh, path] = files[static_cast<std::size_t>(i)];
    if (Status saved = saveMesh(*mesh, path); !saved) failures[static_cast<std::size_t>(i)] = saved.error();
  });
  for (const std::optional<Error>& failure : failures)
    if (failure) return *failure;
  return Done{};
}

// plan.json's text, read back through loadPlan's checks: what loadPlan would refuse is refused now, before
// any file is touched.
Result<std::string> checkedPlanText(const Decomposition& onDisk, const PlanMetadata& metadata,
                                    const std::vector<SupportSet>& supports) {
  std::string text = detail::planToJson(onDisk, metadata, supports).dump(2) + "\n";
  try {
    detail::planFromJson(nlohmann::json::parse(text), kPlanFileName);
  } catch (const detail::JsonFieldError& e) {
    return invalid("it would not load back: " + e.error().describe());
  }
  return text;
}

// A binary STL of n triangles has 84 + 50 n bytes; the supports' own mesh comes from plan.json, so the file
// is only checked to belong to it.
Status checkSupportFile(const fs::path& folder, const std::string& file, std::size_t triangles,
                        const std::string& jsonName, std::size_t region) {
  if (file.empty()) return Done{};
  const std::string field = "regions[" + std::to_string(region) + "].supports";
  std::error_code ec;
  const auto size = fs::file_size(folder / file, ec);
  if (ec)
    return Error{ErrorCode::FileNotFound, "the support file is missing (" + jsonName + " lists it as " + field + ".file)",
                 file};
  if (size != 84 + 50 * static_cast<std::uintmax_t>(triangles))
    return Error{ErrorCode::MalformedFile,
                 "is not a binary STL of " + std::to_string(triangles) + " triangles as " + jsonName + " says (" +
                     field + ".triangles): the file does not belong to this plan",
                 file};
  return Done{};
}

// Every region's claimed triangle count against its STL file's size, before anything is sized by the
// claim (the face origins of 8 regions claiming 50 million triangles each would take 3.2 GB): a binary STL
// holds 50 bytes per triangle and an ASCII one more, so a file of S bytes holds at most S / 50 triangles.
// Fields that are not what they should be are left to planFromJson, which names them.
Status checkClaimedTriangles(const nlohmann::json& document, const fs::path& folder, const std::string& jsonName) {
  if (!document.is_object() || !document.contains("regions") || !document["regions"].is_array()) return Done{};
  const nlohmann::json& regions = document["regions"];
  std::set<std::string> seen;  // a file named twice is planFromJson's to name
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const nlohmann::json& region = regions[i];
    if (!region.is_object() || !region.contains("file") || !region["file"].is_string() ||
        !region.contains("triangles") || !region["triangles"].is_number_unsigned())
      continue;
    const std::string file = region["file"].get<std::string>();
    if (file.empty() || file.find_first_of("/\\") != std::string::npos || file == "." || file == "..") continue;
    if (!seen.insert(file).second) continue;
    const auto claimed = region["triangles"].get<unsigned long long>();
    const std::string field = "regions[" + std::to_string(i) + "]";
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(folder / file, ec);
    if (ec)
      return Error{ErrorCode::FileNotFound,
                   "the region file is missing (" + jsonName + " lists it as " + field + ".file in " +
                       (folder.empty() ? std::string(".") : folder.string()) + ")",
                   file};
    if (claimed > size / 50)
      return Error{ErrorCode::MalformedFile,
                   jsonName + " says " + field + ".triangles is " + std::to_string(claimed) + ", but this file of " +
                       std::to_string(size) + " bytes holds at most " + std::to_string(size / 50) +
                       " triangles: the file does not belong to this plan, or plan.json was edited",
                   file};
  }
  return Done{};
}

Result<LoadedPlan> readPlan(const std::string& directoryOrPlanJson) {
  fs::path jsonPath(directoryOrPlanJson);
  std::error_code ec;
  if (fs::is_directory(jsonPath, ec)) jsonPath /= kPlanFileName;
  const fs::path folder = jsonPath.parent_path();
  const std::string jsonName = jsonPath.filename().empty() ? directoryOrPlanJson : jsonPath.filename().string();

  Result<nlohmann::json> document = detail::readJsonFile(jsonPath.string(), jsonName);
  if (!document) return document.error();
  if (Status claims = checkClaimedTriangles(*document, folder, jsonName); !claims) return claims.error();
  detail::PlanDocument doc = detail::planFromJson(*document, jsonName);

  LoadedPlan plan = std::move(doc.plan);
  plan.directory = folder.string();
  for (std::size_t i = 0; i < plan.decomposition.regions.size(); ++i) {
    const std::string& file = doc.regionFiles[i];
    const std::string field = "regions[" + std::to_string(i) + "]";
    const fs::path regionPath = folder / file;
    if (!fs::exists(regionPath, ec))
      return Error{ErrorCode::FileNotFound,
                   "the region file is missing (" + jsonName + " lists it as " + field + ".file in " +
                       (folder.empty() ? std::string(".") : folder.string()) + ")",
                   file};
    Result<LoadedMesh> loaded = loadMesh(regionPath.string(), regionLoadOptions());
    if (!loaded) return loaded.error();
    TriangleMesh& mesh = loaded->mesh;
    if (mesh.triangles.size() != doc.regionTriangles[i])
      return Error{ErrorCode::MalformedFile,
                   "has " + std::to_string(mesh.triangles.size()) + " triangles, but " + jsonName + " says " +
                       std::to_string(doc.regionTriangles[i]) + " (" + field +
                       ".triangles): the file does not belong to this plan",
                   file};
    mesh.origins = std::move(doc.regionOrigins[i]);
    plan.decomposition.regions[i].mesh = std::move(mesh);
    if (Status s = checkSupportFile(folder, doc.supportFiles[i], doc.supportTriangles[i], jsonName, i); !s)
      return s.error();
  }
  return plan;
}

}  // namespace

Status savePlan(const Decomposition& plan, const PlanMetadata& metadata, const std::string& directory) {
  return savePlan(plan, metadata, {}, directory);
}

Status savePlan(const Decomposition& plan, const PlanMetadata& metadata, const std::vector<SupportSet>& supports,
                const std::string& directory) {
  if (!supports.empty() && supports.size() != plan.regions.size())
    return invalid("there are " + std::to_string(supports.size()) + " support sets for " +
                   std::to_string(plan.regions.size()) + " regions: give one per region or none");
  for (std::size_t i = 0; i < supports.size(); ++i)
    if (supports[i].regionIndex != static_cast<int>(i))
      return invalid("support set " + std::to_string(i) + " says it belongs to region " +
                     std::to_string(supports[i].regionIndex));
  try {
    const Result<Decomposition> onDisk = planOnDisk(plan);
    if (!onDisk) return onDisk.error();
    const Result<std::string> text = checkedPlanText(*onDisk, metadata, supports);
    if (!text) return text.error();
    const fs::path folder(directory);
    if (Status made = detail::makeOutputFolder(folder, "plan folder"); !made) return made;
    std::vector<std::pair<const TriangleMesh*, std::string>> files;
    for (std::size_t i = 0; i < onDisk->regions.size(); ++i)
      files.emplace_back(&onDisk->regions[i].mesh, (folder / detail::regionFileName(i)).string());
    for (std::size_t i = 0; i < supports.size(); ++i)
      if (!supports[i].empty()) files.emplace_back(&supports[i].mesh, (folder / detail::supportFileName(i)).string());
    if (Status saved = saveMeshes(files); !saved) return saved;
    return detail::writeTextFile((folder / kPlanFileName).string(), *text, kPlanFileName);
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::WriteFailed, "there is not enough memory to write the plan", directory};
  } catch (const std::exception& e) {
    return Error{ErrorCode::WriteFailed, std::string("writing the plan failed: ") + e.what(), directory};
  }
}

Result<LoadedPlan> loadPlan(const std::string& directoryOrPlanJson) {
  try {
    return readPlan(directoryOrPlanJson);
  } catch (const detail::JsonFieldError& e) {
    return e.error();
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::TooLarge, "there is not enough memory to load this plan", directoryOrPlanJson};
  } catch (const std::exception& e) {
    return Error{
        ErrorCode::Internal,
        std::string("unexpected failure while loading the plan (") + e.what() + "); please report it with this plan",
        directoryOrPlanJson};
  }
}

}  // namespace multidir::core
