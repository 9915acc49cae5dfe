#include "run_job_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_args.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/plan/print_job.h"

namespace multidir::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

[[noreturn]] void bad(const std::string& file, const std::string& what) {
  throw FileError("multidir run: " + file + ": " + what);
}

double numberAt(const Json& object, const char* key, const std::string& file, const std::string& where) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number())
    bad(file, where + "." + key + " is missing or not a number");
  return object[key].get<double>();
}

// The job's machine through core's machine-profile reader (every field checked as a profile's would be).
core::MachineSpec readMachine(const Json& machine, const std::string& file) {
  if (!machine.is_object()) bad(file, "\"machine\" is missing or not an object");
  Json profile = machine;
  profile["schema"] = "multidir-machine";
  profile["version"] = core::kMachineProfileVersion;
  const fs::path temp = fs::temp_directory_path() / ("multidir-run-machine-" + std::to_string(::getpid()) + ".json");
  {
    std::ofstream out(temp);
    out << profile.dump();
    if (!out) bad(temp.string(), "cannot write the machine for checking (is the temporary folder writable?)");
  }
  core::Result<core::MachineSpec> spec = core::loadMachineProfile(temp.string());
  std::error_code ignored;
  fs::remove(temp, ignored);
  if (!spec) bad(file, "\"machine\": " + spec.error().message);
  return *spec;
}

}  // namespace

RunJob readRunJob(const std::string& path) {
  fs::path file = path;
  if (fs::is_directory(file)) file /= "print-job.json";
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in) bad(name, "cannot be read: give a job folder written by 'multidir slice' or its print-job.json");
  std::stringstream text;
  text << in.rdbuf();
  const Json job = Json::parse(text.str(), nullptr, false);
  if (job.is_discarded() || !job.is_object()) bad(name, "is not JSON");
  if (!job.contains("schema") || job["schema"] != "multidir-print-job") bad(name, "is not a MultiDir print job");
  if (!job.contains("version") || !job["version"].is_number_integer() ||
      job["version"].get<int>() > core::kPrintJobFormatVersion)
    bad(name, "has a newer format version than this MultiDir reads: update MultiDir");
  RunJob run;
  run.jobFile = name;
  run.machine = readMachine(job.value("machine", Json()), name);
  if (run.machine.kind == core::MachineKind::ThreeAxis)
    bad(name, "is a 3-DOF job: there is no platform to turn; print step-01.gcode on the printer directly");
  if (!job.contains("slicing") || !job["slicing"].is_object())
    bad(name, "has no G-code (no \"slicing\"): run 'multidir slice " + file.parent_path().string() +
                  " --printer PROFILE -o OUTDIR' first and run OUTDIR");
  const Json& slicing = job["slicing"];
  if (slicing.contains("printer") && slicing["printer"].is_object() &&
      slicing["printer"].value("platform", std::string()) == "firmware-axis")
    bad(name,
        "was sliced for a platform the printer's firmware turns (job.gcode): print job.gcode on the printer; "
        "'multidir run' drives a platform over Modbus");
  if (!job.contains("steps") || !job["steps"].is_array() || job["steps"].empty())
    bad(name, "\"steps\" is missing or empty");
  if (!slicing.contains("steps") || !slicing["steps"].is_array() || slicing["steps"].size() != job["steps"].size())
    bad(name, "\"slicing.steps\" does not have one entry per step: slice the job again");
  for (std::size_t i = 0; i < job["steps"].size(); ++i) {
    const Json& step = job["steps"][i];
    const Json& sliced = slicing["steps"][i];
    const std::string where = "steps[" + std::to_string(i) + "]";
    RunJobStep s;
    s.index = static_cast<int>(i) + 1;
    if (!step.contains("angles") || !step["angles"].is_object()) bad(name, where + ".angles is missing");
    const Json& angles = step["angles"];
    if (run.machine.kind == core::MachineKind::RotaryPlatform)
      s.orientation = hardware::PlatformOrientation::rotary(numberAt(angles, "rotaryDegrees", name, where + ".angles"));
    else
      s.orientation =
          hardware::PlatformOrientation::tiltAzimuth(numberAt(angles, "tiltDegrees", name, where + ".angles"),
                                                     numberAt(angles, "azimuthDegrees", name, where + ".angles"));
    if (!sliced.is_object() || !sliced.contains("gcode") || !sliced["gcode"].is_string())
      bad(name, "slicing.steps[" + std::to_string(i) + "].gcode is missing");
    const std::string gcode = sliced["gcode"].get<std::string>();
    if (gcode.empty() || gcode.find('/') != std::string::npos || gcode.find("..") != std::string::npos)
      bad(name,
          "slicing.steps[" + std::to_string(i) + "].gcode must be a file name in the job folder, not '" + gcode + "'");
    s.gcodePath = (file.parent_path() / gcode).string();
    if (!fs::is_regular_file(s.gcodePath))
      bad(s.gcodePath, "is missing (step " + std::to_string(s.index) + "'s G-code): slice the job again");
    if (sliced.contains("estimate") && sliced["estimate"].is_object() && sliced["estimate"].contains("printSeconds") &&
        sliced["estimate"]["printSeconds"].is_number())
      s.estimateSeconds = sliced["estimate"]["printSeconds"].get<double>();
    run.steps.push_back(s);
  }
  return run;
}

}  // namespace multidir::cli
