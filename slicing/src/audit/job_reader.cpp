// readAuditJob: a sliced job folder read for the audit (print-job.json, step meshes, G-code, profile, plan).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gcode_replay.h"
#include "multidir/slicing/audit.h"
#include "multidir/slicing/printer_profile.h"
#include "stl_soup.h"

namespace multidir::slicing {

namespace {

namespace fs = std::filesystem;
using core::Error;
using core::ErrorCode;
using core::Vec3;
using Json = nlohmann::json;

core::Result<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::FileNotFound, "cannot read the file", path};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Error malformed(const std::string& file, const std::string& field, const std::string& what) {
  return Error{ErrorCode::MalformedFile, field + " " + what + ": write the job again with 'multidir slice'", file};
}

bool readVec3(const Json& value, Vec3& out) {
  if (!value.is_array() || value.size() != 3) return false;
  for (int k = 0; k < 3; ++k) {
    if (!value[static_cast<std::size_t>(k)].is_number()) return false;
    out[k] = value[static_cast<std::size_t>(k)].get<double>();
  }
  return true;
}

bool readPose(const Json& rows, Eigen::Isometry3d& pose) {
  if (!rows.is_array() || rows.size() != 3) return false;
  pose = Eigen::Isometry3d::Identity();
  for (std::size_t r = 0; r < 3; ++r) {
    if (!rows[r].is_array() || rows[r].size() != 4) return false;
    for (std::size_t c = 0; c < 4; ++c) {
      if (!rows[r][c].is_number()) return false;
      pose.matrix()(static_cast<int>(r), static_cast<int>(c)) = rows[r][c].get<double>();
    }
  }
  return true;
}

// A PrusaSlicer length: "0.45", or "110%" of `percentOf`; 0 or unreadable: `fallback`.
double lengthSetting(const std::string& text, double percentOf, double fallback) {
  if (text.empty()) return fallback;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(value) || value <= 0.0) return fallback;
  return *end == '%' ? value / 100.0 * percentOf : value;
}

// The bead of a step: the profile's settings, then the slicer's own (what it really used, --set included).
BeadGeometry beadOf(const PrinterProfile& profile, const std::string& gcode) {
  const auto value = [&](const std::string& key) {
    std::string fromGcode = audit::slicerSetting(gcode, key);
    if (!fromGcode.empty()) return fromGcode;
    const auto found = profile.settings.find(key);
    return found == profile.settings.end() ? std::string() : found->second;
  };
  const double nozzle = lengthSetting(value("nozzle_diameter").substr(0, value("nozzle_diameter").find(',')), 0.0,
                                      profile.nozzleDiameterMm);
  BeadGeometry bead;
  bead.layerHeightMm = lengthSetting(value("layer_height"), 0.0, 0.3);
  bead.firstLayerHeightMm = lengthSetting(value("first_layer_height"), bead.layerHeightMm, bead.layerHeightMm);
  bead.widthMm = lengthSetting(value("extrusion_width"), bead.layerHeightMm, 1.125 * nozzle);
  return bead;
}

// plan.json's search.alphaMaxDegrees, when the plan is found beside or under the job; 45 otherwise.
double planAlpha(const Json& job, const fs::path& directory) {
  if (!job.contains("plan") || !job["plan"].is_string()) return 45.0;
  const std::string plan = job["plan"].get<std::string>();
  std::error_code ec;
  for (const fs::path& candidate : {fs::path(plan), directory / plan, directory.parent_path() / plan}) {
    if (!fs::exists(candidate / "plan.json", ec)) continue;
    const core::Result<std::string> text = readText((candidate / "plan.json").string());
    if (!text) continue;
    const Json parsed = Json::parse(*text, nullptr, false);
    if (parsed.is_object() && parsed.contains("search") && parsed["search"].contains("alphaMaxDegrees") &&
        parsed["search"]["alphaMaxDegrees"].is_number())
      return parsed["search"]["alphaMaxDegrees"].get<double>();
  }
  return 45.0;
}

AuditRotaryAxis auditAxis(const FirmwareRotaryAxis& axis) {
  return {axis.letter, axis.klipperStepper, axis.zeroDegrees, axis.direction, axis.minDegrees, axis.maxDegrees};
}

// The two axes as the profile gives them: for a job written before print-job.json recorded them.
AuditTwoAxes profileAxes(const PrinterProfile& profile) {
  AuditTwoAxes axes;
  axes.tilt = auditAxis(profile.twoAxis.tilt);
  axes.rotation = auditAxis(profile.twoAxis.rotation);
  axes.tiltAlongX = profile.twoAxis.tiltAlong == TiltAlong::X;
  axes.tiltHeightMm = profile.twoAxis.tiltHeightMm;
  axes.rotationCenterMm = profile.twoAxis.rotationCenter;
  axes.platformCenterMm = profile.platformCenter;
  axes.platformZMm = profile.platformZMm;
  return axes;
}

bool readNumber(const Json& object, const char* key, double& out) {
  if (!object.contains(key) || !object[key].is_number()) return false;
  out = object[key].get<double>();
  return std::isfinite(out);
}

bool readVec2(const Json& value, Eigen::Vector2d& out) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) return false;
  out = Eigen::Vector2d(value[0].get<double>(), value[1].get<double>());
  return out.allFinite();
}

// slicing.printer.axes of a firmware-2axis job; `error` names the field that is missing or wrong.
core::Result<AuditTwoAxes> readTwoAxes(const Json& json, const std::string& file) {
  const std::string at = "slicing.printer.axes";
  if (!json.is_object()) return malformed(file, at, "is not an object");
  AuditTwoAxes axes;
  for (const auto& [name, axis] : {std::pair<const char*, AuditRotaryAxis*>{"tilt", &axes.tilt},
                                   std::pair<const char*, AuditRotaryAxis*>{"rotation", &axes.rotation}}) {
    const std::string where = at + "." + name;
    if (!json.contains(name) || !json[name].is_object()) return malformed(file, where, "is missing");
    const Json& a = json[name];
    if (!a.contains("letter") || !a["letter"].is_string() || a["letter"].get<std::string>().size() != 1)
      return malformed(file, where + ".letter", "is missing or not one letter");
    axis->letter = a["letter"].get<std::string>();
    axis->stepper = a.value("stepper", std::string());
    for (const auto& [key, out] : {std::pair<const char*, double*>{"zero", &axis->zeroDegrees},
                                   std::pair<const char*, double*>{"direction", &axis->direction},
                                   std::pair<const char*, double*>{"min", &axis->minDegrees},
                                   std::pair<const char*, double*>{"max", &axis->maxDegrees}})
      if (!readNumber(a, key, *out)) return malformed(file, where + "." + key, "is missing or not a number");
    if (axis->direction != 1.0 && axis->direction != -1.0) return malformed(file, where + ".direction", "is not 1 or -1");
  }
  if (axes.tilt.letter == axes.rotation.letter)
    return malformed(file, at + ".rotation.letter", "is the tilt axis' letter too");
  const std::string along = json.value("tiltAlong", std::string());
  if (along != "X" && along != "Y") return malformed(file, at + ".tiltAlong", "is not \"X\" or \"Y\"");
  axes.tiltAlongX = along == "X";
  if (!readNumber(json, "tiltHeightMm", axes.tiltHeightMm))
    return malformed(file, at + ".tiltHeightMm", "is missing or not a number");
  if (!json.contains("rotationCenterMm") || !readVec2(json["rotationCenterMm"], axes.rotationCenterMm))
    return malformed(file, at + ".rotationCenterMm", "is missing or not two numbers");
  if (!json.contains("platformCenterMm") || !readVec2(json["platformCenterMm"], axes.platformCenterMm))
    return malformed(file, at + ".platformCenterMm", "is missing or not two numbers");
  if (!readNumber(json, "platformZMm", axes.platformZMm))
    return malformed(file, at + ".platformZMm", "is missing or not a number");
  return axes;
}

core::TriangleMesh moved(core::TriangleMesh mesh, const Eigen::Isometry3d& motion) {
  for (Vec3& v : mesh.vertices) v = motion * v;
  return mesh;
}

}  // namespace

core::Result<AuditJob> readAuditJob(const std::string& directoryText) {
  const fs::path directory =
      fs::is_regular_file(directoryText) ? fs::path(directoryText).parent_path() : fs::path(directoryText);
  const std::string file = (directory / "print-job.json").string();
  const core::Result<std::string> text = readText(file);
  if (!text)
    return Error{ErrorCode::FileNotFound, "no print-job.json: give a job folder written by 'multidir slice'", file};
  const Json job = Json::parse(*text, nullptr, false);
  if (job.is_discarded() || !job.is_object()) return malformed(file, "the file", "is not JSON");
  if (job.value("schema", std::string()) != "multidir-print-job")
    return malformed(file, "schema", "is not \"multidir-print-job\"");
  if (!job.contains("slicing") || !job["slicing"].is_object())
    return Error{ErrorCode::InvalidParameter,
                 "the job has no G-code (no \"slicing\"): slice it first with 'multidir slice PLAN --printer PROFILE "
                 "-o " +
                     directory.string() + "'",
                 file};
  if (job.value("frame", std::string("machine")) != "machine")
    return malformed(file, "frame", "is not \"machine\" (the slicer was given the machine's poses)");
  if (job.value("format", std::string("stl")) != "stl")
    return Error{ErrorCode::UnsupportedFormat,
                 "the audit reads STL step meshes only (format is '" + job.value("format", std::string()) + "')", file};

  AuditJob out;
  out.directory = directory.string();
  const Json& machine = job.value("machine", Json());
  const core::Result<core::MachineKind> kind = core::parseMachineKind(machine.value("kind", std::string()));
  if (!kind) return malformed(file, "machine.kind", "is not 3dof, 4dof or 5dof");
  out.machine.kind = *kind;
  if (!machine.contains("up") || !readVec3(machine["up"], out.machine.up))
    return malformed(file, "machine.up", "is missing or not three numbers");
  out.machine.up.normalize();
  if (machine.contains("rotationAxis") && !readVec3(machine["rotationAxis"], out.machine.rotationAxis))
    return malformed(file, "machine.rotationAxis", "is not three numbers");
  out.machine.rotationAxis.normalize();
  if (!job.contains("pivot") || !job["pivot"].contains("point") || !readVec3(job["pivot"]["point"], out.machine.pivot))
    return malformed(file, "pivot.point", "is missing or not three numbers");

  const Json& slicing = job["slicing"];
  const Json printer = slicing.value("printer", Json::object());
  const std::string profilePath = printer.value("profile", std::string());
  core::Result<PrinterProfile> profile = loadPrinterProfile(profilePath);
  // A profile named by a relative path was found from where `multidir slice` ran: try beside the job too.
  if (!profile && !profilePath.empty() && fs::path(profilePath).is_relative() &&
      fs::is_regular_file(directory / profilePath))
    profile = loadPrinterProfile((directory / profilePath).string());
  if (!profile)
    return Error{profile.error().code,
                 "the job's printer profile '" + profilePath + "' (slicing.printer.profile) cannot be read: " +
                     profile.error().message + "; the audit needs its platform_center and platform_z",
                 file};
  out.printerOffset = Vec3(profile->platformCenter.x(), profile->platformCenter.y(), profile->platformZMm);
  out.rotaryAxis = profile->rotaryAxis;
  const std::string platform = printer.value("platform", std::string(platformDriveName(profile->platform)));
  out.platform = platform == "firmware-axis"    ? AuditPlatform::FirmwareAxis
                 : platform == "firmware-2axis" ? AuditPlatform::FirmwareTwoAxis
                 : platform == "modbus"         ? AuditPlatform::Modbus
                                                : AuditPlatform::None;
  const bool twoAxis = out.platform == AuditPlatform::FirmwareTwoAxis;
  if (twoAxis) {
    if (printer.contains("axes")) {
      core::Result<AuditTwoAxes> axes = readTwoAxes(printer["axes"], file);
      if (!axes) return axes.error();
      out.twoAxes = *axes;
    } else {
      out.twoAxes = profileAxes(*profile);
    }
  }
  out.alphaMaxDegrees = planAlpha(job, directory);

  if (!job.contains("steps") || !job["steps"].is_array() || job["steps"].empty())
    return malformed(file, "steps", "is missing or empty");
  const Json& sliced = slicing.value("steps", Json::array());
  if (!sliced.is_array() || sliced.size() != job["steps"].size())
    return malformed(file, "slicing.steps", "does not have one entry per step");
  for (std::size_t i = 0; i < job["steps"].size(); ++i) {
    const Json& s = job["steps"][i];
    const std::string where = "steps[" + std::to_string(i) + "]";
    AuditStep step;
    step.index = s.value("index", static_cast<int>(i) + 1);
    if (!s.contains("printingDirection") || !readVec3(s["printingDirection"], step.printingDirection))
      return malformed(file, where + ".printingDirection", "is missing or not three numbers");
    if (!s.contains("modelToFile") || !readPose(s["modelToFile"], step.recordedModelToFile))
      return malformed(file, where + ".modelToFile", "is missing or not three rows of four numbers");
    const Json angles = s.value("angles", Json::object());
    step.angles.rotaryDegrees = angles.value("rotaryDegrees", 0.0);
    step.angles.tiltDegrees = angles.value("tiltDegrees", 0.0);
    step.angles.azimuthDegrees = angles.value("azimuthDegrees", 0.0);
    const Json files = s.value("files", Json::object());
    if (!files.contains("region") || !files["region"].is_string())
      return malformed(file, where + ".files.region", "is missing");
    const Eigen::Isometry3d toModel = step.recordedModelToFile.inverse();
    core::Result<core::TriangleMesh> region =
        audit::readStlSoup((directory / files["region"].get<std::string>()).string());
    if (!region) return region.error();
    step.region = moved(std::move(region).value(), toModel);
    if (files.contains("supports") && files["supports"].is_string()) {
      core::Result<core::TriangleMesh> supports =
          audit::readStlSoup((directory / files["supports"].get<std::string>()).string());
      if (!supports) return supports.error();
      step.supports = moved(std::move(supports).value(), toModel);
    }
    const std::string gcode = sliced[i].value("gcode", std::string());
    if (gcode.empty() || gcode.find('/') != std::string::npos)
      return malformed(file, "slicing.steps[" + std::to_string(i) + "].gcode", "is not a file name in the job folder");
    step.gcodeFile = gcode;
    if (twoAxis) {
      // The coordinates the step prints at, by the axes' letters: {"U": 60.8, "V": 28.1}.
      const std::string where = "slicing.steps[" + std::to_string(i) + "].axisDegrees";
      const Json coordinates = sliced[i].value("axisDegrees", Json());
      AuditAxisCoordinates at;
      if (!coordinates.is_object() || !readNumber(coordinates, out.twoAxes.tilt.letter.c_str(), at.tiltDegrees) ||
          !readNumber(coordinates, out.twoAxes.rotation.letter.c_str(), at.rotationDegrees))
        return malformed(file, where,
                         "is missing or lacks a number for " + out.twoAxes.tilt.letter + " or " +
                             out.twoAxes.rotation.letter + " (a firmware-2axis job records both axes per step)");
      step.axisDegrees = at;
    }
    core::Result<std::string> program = readText((directory / gcode).string());
    if (!program) return program.error();
    step.gcode = std::move(program).value();
    step.bead = beadOf(*profile, step.gcode);
    out.steps.push_back(std::move(step));
  }
  if (slicing.contains("stitched") && slicing["stitched"].is_string()) {
    out.stitchedFile = slicing["stitched"].get<std::string>();
    core::Result<std::string> program = readText((directory / out.stitchedFile).string());
    if (!program) return program.error();
    out.stitchedGcode = std::move(program).value();
  }
  return out;
}

}  // namespace multidir::slicing
