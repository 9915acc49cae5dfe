// Machine profiles: one MachineSpec per JSON file.
#include <filesystem>

#include "multidir/core/plan/plan_file.h"
#include "plan/json_field.h"
#include "plan/json_file.h"
#include "plan/settings_json.h"

namespace multidir::core {
namespace {

constexpr const char* kProfileSchema = "multidir-machine";

}  // namespace

Status saveMachineProfile(const MachineSpec& machine, const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (Status valid = validate(machine); !valid)
    return Error{ErrorCode::InvalidParameter, "the machine is not valid: " + valid.error().message, name};
  try {
    nlohmann::ordered_json document = {{"schema", kProfileSchema}, {"version", kMachineProfileVersion}};
    document.update(detail::machineToJson(machine));
    return detail::writeTextFile(path, document.dump(2) + "\n", name);
  } catch (const std::exception& e) {
    return Error{ErrorCode::WriteFailed, std::string("writing the profile failed: ") + e.what(), name};
  }
}

namespace {

// Checks a parsed profile document; `name` names it in errors.
Result<MachineSpec> machineFromDocument(const nlohmann::json& document, const std::string& name) {
  try {
    const detail::JsonField root(document, "", name);
    const detail::JsonField schema = root["schema"];
    if (schema.string() != kProfileSchema)
      schema.fail(std::string("must be \"") + kProfileSchema + "\": this is not a MultiDir machine profile");
    const detail::JsonField version = root["version"];
    if (version.integer(1, 1'000'000) > kMachineProfileVersion)
      version.fail("is newer than the version this MultiDir reads (" + std::to_string(kMachineProfileVersion) +
                   "): update MultiDir to use this profile");
    return detail::machineFromJson(root, false);
  } catch (const detail::JsonFieldError& e) {
    return e.error();
  } catch (const std::exception& e) {
    return Error{ErrorCode::Internal, std::string("unexpected failure while loading the profile (") + e.what() + ")",
                 name};
  }
}

}  // namespace

Result<MachineSpec> loadMachineProfile(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  Result<nlohmann::json> document = detail::readJsonFile(path, name);
  if (!document) return document.error();
  return machineFromDocument(*document, name);
}

Result<MachineSpec> parseMachineProfile(const std::string& jsonText, const std::string& name) {
  Result<nlohmann::json> document = detail::parseJsonText(jsonText, name);
  if (!document) return document.error();
  return machineFromDocument(*document, name);
}

}  // namespace multidir::core
