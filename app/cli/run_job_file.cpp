#include "run_job_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cli_args.h"
#include "multidir/core/plan/json_text.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/plan/print_job.h"
#include "number_text.h"

namespace multidir::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Heights (mm) a job may give for a base plane or a turn's clearance: no printer is ten metres tall.
constexpr double kMaxHeightMm = 10000.0;

[[noreturn]] void bad(const std::string& file, const std::string& what) {
  throw FileError("multidir run: " + file + ": " + what);
}

// Whole numbers in full (31536000), others in six significant digits (1e+308, not 309 digits).
std::string numberText(double value) {
  if (std::abs(value) < 1e15 && value == std::floor(value)) return formatNumber("%.0f", value);
  return formatNumber("%.6g", value);
}

double numberAt(const Json& object, const char* key, const std::string& file, const std::string& where) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number())
    bad(file, where + "." + key + " is missing or not a number");
  return object[key].get<double>();
}

// A number of `object[key]` from `low` to `high` (the range is named in the refusal, in `unit`).
double numberIn(const Json& object, const char* key, double low, double high, const std::string& unit,
                const std::string& file, const std::string& where) {
  const double value = numberAt(object, key, file, where);
  if (value < low || value > high)
    bad(file, where + "." + key + " is " + numberText(value) + ", outside the allowed range " + numberText(low) +
                  " to " + numberText(high) + " " + unit + ": slice the job again");
  return value;
}

// The job's machine through core's machine-profile checks, in memory (no temporary file: one at a fixed
// name could be planted or swapped between writing and reading).
core::MachineSpec readMachine(const Json& machine, const std::string& file) {
  if (!machine.is_object()) bad(file, "\"machine\" is missing or not an object");
  Json profile = machine;
  profile["schema"] = "multidir-machine";
  profile["version"] = core::kMachineProfileVersion;
  const core::Result<core::MachineSpec> spec = core::parseMachineProfile(profile.dump(), "machine");
  if (!spec) bad(file, "\"machine\": " + spec.error().message);
  return *spec;
}

// Why the step's G-code at `path` cannot be uploaded, or "" when it is a regular file. The file itself is
// looked at (lstat), not what a link points to: a link could lead out of the job folder.
std::string gcodeFileProblem(const std::string& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0)
    return errno == ENOENT ? std::string("is missing: slice the job again")
                           : std::string("cannot be read (") + std::strerror(errno) + ")";
  if (S_ISLNK(info.st_mode))
    return "is a symbolic link: 'multidir run' uploads only regular files inside the job folder; copy the file "
           "there in its place";
  if (S_ISREG(info.st_mode)) return "";
  const char* kind = S_ISFIFO(info.st_mode)   ? "a FIFO"
                     : S_ISDIR(info.st_mode)  ? "a folder"
                     : S_ISSOCK(info.st_mode) ? "a socket"
                                              : "a device";
  return std::string("is not a regular file (it is ") + kind + "): give the G-code file 'multidir slice' wrote";
}

// The stitched program of a job for a platform the printer's firmware turns: the file slicing.stitched names,
// in the job folder, a regular file.
RunStitchedProgram readStitchedProgram(const Json& slicing, const std::string& platform, const fs::path& file,
                                       std::size_t steps) {
  const std::string name = file.string();
  RunStitchedProgram stitched;
  stitched.platform = platform;
  if (slicing["printer"].contains("dialect") && slicing["printer"]["dialect"].is_string())
    stitched.dialect = slicing["printer"]["dialect"].get<std::string>();
  if (!slicing.contains("stitched") || !slicing["stitched"].is_string())
    bad(name, "was sliced for a platform the printer's firmware turns (" + platform +
                  ") but names no stitched program (slicing.stitched): slice the job again");
  stitched.gcodeName = slicing["stitched"].get<std::string>();
  if (stitched.gcodeName.empty() || stitched.gcodeName.find('/') != std::string::npos ||
      stitched.gcodeName.find("..") != std::string::npos)
    bad(name, "slicing.stitched must be a file name in the job folder, not '" + stitched.gcodeName + "'");
  stitched.gcodePath = (file.parent_path() / stitched.gcodeName).string();
  if (const std::string problem = gcodeFileProblem(stitched.gcodePath); !problem.empty())
    bad(stitched.gcodePath, "the stitched program (slicing.stitched) " + problem);
  const Json slicedSteps = slicing.value("steps", Json::array());
  for (std::size_t i = 0; i < steps; ++i) {
    double seconds = 0.0;
    if (slicedSteps.is_array() && i < slicedSteps.size() && slicedSteps[i].is_object() &&
        slicedSteps[i].contains("estimate") && slicedSteps[i]["estimate"].is_object() &&
        slicedSteps[i]["estimate"].contains("printSeconds"))
      seconds = numberIn(slicedSteps[i]["estimate"], "printSeconds", 0.0, kMaxStepPrintSeconds, "s", name,
                         "slicing.steps[" + std::to_string(i) + "].estimate");
    stitched.stepEstimateSeconds.push_back(seconds);
  }
  return stitched;
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
  if (core::Status json = core::checkJsonText(text.str(), "print-job.json"); !json) bad(name, json.error().message);
  const Json job = Json::parse(text.str(), nullptr, false);
  if (job.is_discarded() || !job.is_object()) bad(name, "is not a JSON object: give a print-job.json");
  if (!job.contains("schema") || job["schema"] != "multidir-print-job") bad(name, "is not a MultiDir print job");
  const std::string versions = "1 to " + std::to_string(core::kPrintJobFormatVersion);
  if (!job.contains("version") || !job["version"].is_number_integer())
    bad(name, "version is missing or not a whole number (this MultiDir reads versions " + versions + ")");
  const long long version = job["version"].get<long long>();
  if (version > core::kPrintJobFormatVersion)
    bad(name, "version " + std::to_string(version) + " is newer than this MultiDir reads (" + versions +
                  "): update MultiDir");
  if (version < 1)
    bad(name, "version " + std::to_string(version) + " is not a print-job version (this MultiDir reads " + versions +
                  "): export and slice the job again");
  RunJob run;
  run.jobFile = name;
  run.folder = file.parent_path().string();
  run.machine = readMachine(job.value("machine", Json()), name);
  if (run.machine.kind == core::MachineKind::ThreeAxis)
    bad(name, "is a 3-DOF job: there is no platform to turn; print step-01.gcode on the printer directly");
  if (!job.contains("slicing") || !job["slicing"].is_object())
    bad(name, "has no G-code (no \"slicing\"): run 'multidir slice " + file.parent_path().string() +
                  " --printer PROFILE -o OUTDIR' first and run OUTDIR");
  const Json& slicing = job["slicing"];
  std::string platformDrive;
  if (slicing.contains("printer") && slicing["printer"].is_object()) {
    const Json& printer = slicing["printer"];
    if (printer.contains("platform") && printer["platform"].is_string())
      platformDrive = printer["platform"].get<std::string>();
    if (printer.contains("profile") && printer["profile"].is_string())
      run.printerProfile = printer["profile"].get<std::string>();
  }
  if (!job.contains("steps") || !job["steps"].is_array() || job["steps"].empty())
    bad(name, "\"steps\" is missing or empty");
  if (platformDrive == "firmware-axis" || platformDrive == "firmware-2axis") {
    run.stitched = readStitchedProgram(slicing, platformDrive, file, job["steps"].size());
    return run;
  }
  if (!slicing.contains("steps") || !slicing["steps"].is_array() || slicing["steps"].size() != job["steps"].size())
    bad(name, "\"slicing.steps\" does not have one entry per step: slice the job again");
  const Json turns = slicing.value("turns", Json::array());
  if (!turns.is_array()) bad(name, "slicing.turns is not a list: slice the job again");
  std::set<std::string> gcodeNames;
  for (std::size_t i = 0; i < job["steps"].size(); ++i) {
    const Json& step = job["steps"][i];
    const Json& sliced = slicing["steps"][i];
    const std::string where = "steps[" + std::to_string(i) + "]";
    const std::string slicedWhere = "slicing.steps[" + std::to_string(i) + "]";
    RunJobStep s;
    s.index = static_cast<int>(i) + 1;
    if (!step.is_object() || !step.contains("angles") || !step["angles"].is_object())
      bad(name, where + ".angles is missing");
    const Json& angles = step["angles"];
    s.anglesField = where + ".angles";
    if (run.machine.kind == core::MachineKind::RotaryPlatform)
      s.orientation = hardware::PlatformOrientation::rotary(numberAt(angles, "rotaryDegrees", name, s.anglesField));
    else
      s.orientation =
          hardware::PlatformOrientation::tiltAzimuth(numberAt(angles, "tiltDegrees", name, s.anglesField),
                                                     numberAt(angles, "azimuthDegrees", name, s.anglesField));
    s.gcodeField = slicedWhere + ".gcode";
    if (!sliced.is_object() || !sliced.contains("gcode") || !sliced["gcode"].is_string())
      bad(name, s.gcodeField + " is missing");
    const std::string gcode = sliced["gcode"].get<std::string>();
    if (gcode.empty() || gcode.find('/') != std::string::npos || gcode.find("..") != std::string::npos)
      bad(name, s.gcodeField + " must be a file name in the job folder, not '" + gcode + "'");
    if (!gcodeNames.insert(gcode).second)
      bad(name, s.gcodeField + " names '" + gcode +
                    "', the G-code of an earlier step too: every step needs its own file; slice the job again");
    s.gcodePath = (file.parent_path() / gcode).string();
    if (const std::string problem = gcodeFileProblem(s.gcodePath); !problem.empty())
      bad(s.gcodePath, "step " + std::to_string(s.index) + "'s G-code (" + s.gcodeField + ") " + problem);
    if (sliced.contains("estimate") && sliced["estimate"].is_object() && sliced["estimate"].contains("printSeconds"))
      s.estimateSeconds =
          numberIn(sliced["estimate"], "printSeconds", 0.0, kMaxStepPrintSeconds, "s", name, slicedWhere + ".estimate");
    s.baseZMm = numberIn(sliced, "baseZMm", 0.0, kMaxHeightMm, "mm", name, slicedWhere);
    run.steps.push_back(s);
  }
  // The nozzle's height each turn needs: the step before it must end there (the same check as `slice`'s).
  for (std::size_t t = 0; t < turns.size(); ++t) {
    const std::string where = "slicing.turns[" + std::to_string(t) + "]";
    const Json& turn = turns[t];
    if (!turn.is_object() || !turn.contains("fromStep") || !turn["fromStep"].is_number_integer())
      bad(name, where + ".fromStep is missing or not a whole number");
    const long long from = turn["fromStep"].get<long long>();
    if (from < 1 || from >= static_cast<long long>(run.steps.size()))
      bad(name, where + ".fromStep is " + std::to_string(from) + ", outside the allowed range 1 to " +
                    std::to_string(run.steps.size() - 1) + " (a turn between two steps): slice the job again");
    run.steps[static_cast<std::size_t>(from - 1)].turnClearanceZMm =
        numberIn(turn, "clearanceZMm", 0.0, kMaxHeightMm, "mm", name, where);
  }
  for (std::size_t i = 0; i + 1 < run.steps.size(); ++i)
    if (!run.steps[i].turnClearanceZMm)
      bad(name, "slicing.turns has no turn after step " + std::to_string(i + 1) +
                    " (its clearanceZMm is what the step's G-code must end above): slice the job again");
  return run;
}

}  // namespace multidir::cli
