#include "apart_files.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "multidir/assembly/assembly_sheet.h"
#include "multidir/core/common/atomic_file.h"

namespace multidir::apart {

namespace fs = std::filesystem;

namespace {

nlohmann::ordered_json summaryJson(const ApartResult& result) {
  int unnumbered = 0;
  nlohmann::ordered_json labelRecords = nlohmann::ordered_json::array();
  for (const assembly::PartLabel& label : result.labels) {
    if (!label.placed) ++unnumbered;
    nlohmann::ordered_json record = {{"part", label.part + 1}, {"number", label.text}, {"placed", label.placed}};
    if (label.placed) {
      record["joint"] = label.joint + 1;
      record["heightMm"] = label.heightMm;
    } else {
      record["note"] = label.note;
    }
    labelRecords.push_back(record);
  }
  nlohmann::ordered_json summary = {{"parts", result.plan.parts.size()},
                                    {"cutsToFit", result.plan.cutsToFit},
                                    {"joints", result.plan.joints.size()},
                                    {"dowels", result.layout.dowels.size()},
                                    {"plates", result.plates.plates},
                                    {"jgApartMm2", result.plan.jgMm2},
                                    {"jgPlanMm2", result.jgPlanMm2},
                                    {"jgBeforeMm2", result.jgBeforeMm2},
                                    {"partsNumbered", static_cast<int>(result.labels.size()) - unnumbered},
                                    {"labels", labelRecords}};
  if (result.sliced) {
    nlohmann::ordered_json perPlate = nlohmann::ordered_json::array();
    for (const PlateEstimate& p : result.plateEstimates)
      perPlate.push_back({{"plate", p.plate + 1},
                          {"seconds", p.estimate.printSeconds},
                          {"filamentCm3", p.estimate.filamentCm3},
                          {"supportCm3", p.estimate.supportCm3}});
    summary["platesSliced"] = perPlate;
    summary["apartSeconds"] = result.total.printSeconds;
    summary["apartFilamentCm3"] = result.total.filamentCm3;
    summary["apartSupportCm3"] = result.total.supportCm3;
    summary["wholeSupportCm3"] = result.whole.supportCm3;
    summary["wholeSeconds"] = result.whole.printSeconds;
    summary["wholeFilamentCm3"] = result.whole.filamentCm3;
  }
  return summary;
}

core::Status writeFile(ApartResult& result, const std::string& folder, const std::string& name, const std::string& text) {
  if (core::Status s = core::writeTextFileAtomically((fs::path(folder) / name).string(), text); !s) return s.error();
  result.files.push_back(name);
  return core::Done{};
}

bool isEmptyOrEarlierOutput(const std::string& target) {
  std::error_code ec;
  if (!fs::exists(target, ec)) return true;
  return fs::is_empty(target, ec) || fs::exists(fs::path(target) / "apart.json", ec);
}

}  // namespace

core::Status writeSheetAndSummary(ApartResult& result, const PrintApartOptions& options, const std::string& folder) {
  std::vector<assembly::SheetEstimate> estimates;
  if (result.sliced) {
    for (const PlateEstimate& p : result.plateEstimates)
      estimates.push_back({"Plate " + std::to_string(p.plate + 1), p.estimate.printSeconds, p.estimate.filamentCm3,
                           p.estimate.supportCm3});
    estimates.push_back({"All plates", result.total.printSeconds, result.total.filamentCm3, result.total.supportCm3});
    estimates.push_back({"One piece with supports", result.whole.printSeconds, result.whole.filamentCm3,
                         result.whole.supportCm3});
  }
  assembly::SheetInput input;
  input.title = options.title;
  input.plan = &result.plan;
  input.layout = &result.layout;
  input.dowelOptions = options.dowels;
  input.labels = &result.labels;
  input.parts = &result.parts;
  input.dowels = &result.dowels;
  input.plates = &result.plates;
  input.estimates = estimates;
  const core::Result<assembly::Sheet> sheet = assembly::assemblySheet(input);
  if (!sheet) return sheet.error();
  std::error_code ec;
  fs::create_directories(fs::path(folder) / "sheet", ec);
  for (const assembly::SheetPicture& picture : sheet->pictures)
    if (core::Status s = writeFile(result, folder, picture.name, std::string(picture.png.begin(), picture.png.end())); !s)
      return s;
  if (core::Status s = writeFile(result, folder, "assembly.html", sheet->html); !s) return s;
  return writeFile(result, folder, "apart.json", summaryJson(result).dump(2) + "\n");
}

core::Status commitFolder(core::StagedFolder& staged) {
  if (isEmptyOrEarlierOutput(staged.target())) return staged.replaceTarget();
  return staged.moveEntriesInto("apart.json");
}

core::Status copyApartFiles(const ApartResult& result, const std::string& folder) {
  if (result.folder.empty() || result.files.empty())
    return core::Error{core::ErrorCode::InvalidParameter, "nothing to export: print the plan apart first", folder};
  const fs::path target = fs::absolute(fs::path(folder)).lexically_normal();
  std::error_code ec;
  fs::create_directories(target.parent_path(), ec);
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(target.string());
  if (!staged) return staged.error();
  for (const std::string& name : result.files) {
    const fs::path to = fs::path(staged->path()) / name;
    fs::create_directories(to.parent_path(), ec);
    fs::copy_file(fs::path(result.folder) / name, to, fs::copy_options::overwrite_existing, ec);
    if (ec)
      return core::Error{core::ErrorCode::WriteFailed, "cannot copy " + name + ": " + ec.message(),
                         (fs::path(result.folder) / name).string()};
  }
  return commitFolder(*staged);
}

}  // namespace multidir::apart
