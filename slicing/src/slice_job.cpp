#include "multidir/slicing/slice_job.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "multidir/core/common/atomic_file.h"
#include "multidir/core/common/staged_folder.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/slicing/clearance.h"
#include "multidir/slicing/gcode_program.h"
#include "multidir/slicing/interface_settings.h"
#include "multidir/slicing/job_folder.h"
#include "multidir/slicing/placement.h"
#include "multidir/slicing/side_by_side.h"
#include "multidir/slicing/slicer_engine.h"
#include "multidir/slicing/step_recheck.h"
#include "multidir/slicing/two_axis_motion.h"
#include "setting_ranges.h"

namespace multidir::slicing {

namespace {

namespace fs = std::filesystem;
using core::Error;
using core::ErrorCode;
using core::Vec3;

std::string fixed(double value, int digits = 3) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

std::string stepName(int index, const char* suffix) {
  char text[64];
  std::snprintf(text, sizeof text, "step-%02d%s", index, suffix);
  return text;
}

// A mesh moved rigidly (vertices only).
core::TriangleMesh moved(const core::TriangleMesh& mesh, const Eigen::Isometry3d& motion) {
  core::TriangleMesh out = mesh;
  for (Vec3& v : out.vertices) v = motion * v;
  return out;
}

// Both meshes in one (the slicer unites overlapping shells).
core::TriangleMesh joined(const core::TriangleMesh& a, const core::TriangleMesh& b) {
  core::TriangleMesh out = a;
  const auto offset = static_cast<std::int32_t>(out.vertices.size());
  out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (core::Triangle t : b.triangles) out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  out.origins.insert(out.origins.end(), b.origins.begin(), b.origins.end());
  return out;
}

double lowestZ(const core::TriangleMesh& mesh) {
  double low = std::numeric_limits<double>::infinity();
  for (const Vec3& v : mesh.vertices) low = std::min(low, v.z());
  return low;
}

double heightOf(const core::TriangleMesh& mesh) {
  double high = -std::numeric_limits<double>::infinity();
  for (const Vec3& v : mesh.vertices) high = std::max(high, v.z());
  return mesh.vertices.empty() ? 0.0 : high - lowestZ(mesh);
}

// Every file of the job goes through core's atomic writer: never through a link planted at its name or its
// temporary's, never half-written where the job's reader looks.
core::Status writeText(const std::string& path, const std::string& text) {
  return core::writeTextFileAtomically(path, text, path);
}

core::Result<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::FileNotFound, "cannot read the file", path};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string setting(const PrinterProfile& profile, const SliceJobOptions& options, const std::string& key,
                    const std::string& fallback) {
  for (auto it = options.settings.rbegin(); it != options.settings.rend(); ++it)
    if (it->first == key) return it->second;
  const auto found = profile.settings.find(key);
  return found == profile.settings.end() ? fallback : found->second;
}

// A temporary folder for meshes and config overlays, removed when the job ends (or before it is committed).
struct WorkFolder {
  fs::path path;
  WorkFolder() = default;
  WorkFolder(const WorkFolder&) = delete;
  WorkFolder& operator=(const WorkFolder&) = delete;
  ~WorkFolder() { remove(); }
  void remove() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
    path.clear();
  }
};

// The printer's XY and Z for a machine-frame point: the platform centre and plane of the profile.
Eigen::Isometry3d machineToPrinter(const PrinterProfile& profile) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Vec3(profile.platformCenter.x(), profile.platformCenter.y(), profile.platformZMm);
  return t;
}

core::Status writeOverlay(const std::string& path, const std::vector<std::pair<std::string, std::string>>& settings) {
  std::string text = "# MultiDir: settings for one slicing run, applied after the printer profile\n";
  for (const auto& [key, value] : settings) text += key + " = " + value + "\n";
  return writeText(path, text);
}

// Adds the "slicing" object to print-job.json (rewritten beside itself and renamed into place).
core::Status recordInJobFile(const std::string& directory, const SlicedJob& sliced, const std::string& engine) {
  const std::string path = (fs::path(directory) / "print-job.json").string();
  core::Result<std::string> text = readText(path);
  if (!text) return text.error();
  nlohmann::ordered_json job = nlohmann::ordered_json::parse(*text, nullptr, false);
  if (job.is_discarded()) return Error{ErrorCode::Internal, "print-job.json just written does not parse", path};
  const auto estimateJson = [](const Estimate& e) {
    return nlohmann::ordered_json{{"printSeconds", e.printSeconds},
                                  {"filamentMm", e.filamentMm},
                                  {"filamentCm3", e.filamentCm3},
                                  {"filamentGrams", e.filamentGrams}};
  };
  nlohmann::ordered_json slicing;
  slicing["engine"] = engine;
  slicing["printer"] = {{"name", sliced.profile.name},
                        {"profile", sliced.profile.path},
                        {"platform", platformDriveName(sliced.profile.platform)},
                        {"dialect", dialectName(sliced.dialect)}};
  const TwoAxisPlatform& axes = sliced.profile.twoAxis;
  const bool twoAxis = sliced.profile.platform == PlatformDrive::FirmwareTwoAxis;
  if (twoAxis) {
    const auto axisJson = [](const FirmwareRotaryAxis& a) {
      return nlohmann::ordered_json{{"letter", a.letter},     {"stepper", a.klipperStepper}, {"zero", a.zeroDegrees},
                                    {"direction", a.direction}, {"min", a.minDegrees},       {"max", a.maxDegrees}};
    };
    slicing["printer"]["axes"] = {{"tilt", axisJson(axes.tilt)},
                                  {"rotation", axisJson(axes.rotation)},
                                  {"tiltAlong", axes.tiltAlong == TiltAlong::X ? "X" : "Y"},
                                  {"tiltHeightMm", axes.tiltHeightMm},
                                  {"rotationCenterMm", {axes.rotationCenter.x(), axes.rotationCenter.y()}},
                                  {"platformCenterMm", {sliced.profile.platformCenter.x(), sliced.profile.platformCenter.y()}},
                                  {"platformZMm", sliced.profile.platformZMm}};
  }
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (const SlicedStep& s : sliced.steps) {
    nlohmann::ordered_json step = {{"index", s.index}, {"gcode", s.gcodeFile}};
    step["estimate"] = estimateJson(s.estimate);
    step["extrusions"] = s.totals.extrusions;
    step["baseZMm"] = s.baseZMm;
    step["firstLayerZMm"] = s.firstLayerZMm;
    step["highestZMm"] = s.totals.highestZMm;
    step["sliceSeconds"] = s.sliceSeconds;
    if (s.axisDegrees)
      step["axisDegrees"] = {{axes.tilt.letter, s.axisDegrees->tiltDegrees},
                             {axes.rotation.letter, s.axisDegrees->rotationDegrees}};
    steps.push_back(step);
  }
  slicing["steps"] = steps;
  slicing["placementMm"] = {sliced.placementMm.x(), sliced.placementMm.y()};
  nlohmann::ordered_json turns = nlohmann::ordered_json::array();
  for (const TurnPlan& t : sliced.turns) {
    nlohmann::ordered_json turn = {{"fromStep", t.fromStep},
                                   {"fromDegrees", t.fromDegrees},
                                   {"toDegrees", t.toDegrees},
                                   {"sweptTopZMm", t.sweptTopZMm},
                                   {"clearanceZMm", t.clearanceZMm}};
    if (t.twoAxis) {
      nlohmann::ordered_json moves = nlohmann::ordered_json::array();
      for (const AxisMove& m : t.twoAxis->moves)
        moves.push_back({{"axis", m.axis == AxisMove::Axis::Tilt ? axes.tilt.letter : axes.rotation.letter},
                         {"fromDegrees", m.fromDegrees},
                         {"toDegrees", m.toDegrees}});
      turn["moves"] = moves;
    }
    turns.push_back(turn);
  }
  slicing["turns"] = turns;
  slicing["total"] = estimateJson(sliced.total);
  slicing["stitched"] = sliced.stitchedFile.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(sliced.stitchedFile);
  slicing["fixedDirection"] =
      sliced.fixedDirection ? estimateJson(*sliced.fixedDirection) : nlohmann::ordered_json();
  job["slicing"] = slicing;
  return writeText(path, job.dump(2) + "\n");
}

// What `directory` holds, refused when it holds files that are not a MultiDir job and the caller did not allow
// writing into such a folder (job_folder.h).
core::Result<JobFolder> outputFolder(const std::string& directory, bool writeIntoOtherFolder) {
  core::Result<JobFolder> folder = inspectJobFolder(directory);
  if (!folder) return folder.error();
  if (folder->kind == JobFolder::Kind::Other && !writeIntoOtherFolder)
    return Error{ErrorCode::InvalidParameter,
                 "the folder holds files that are not a MultiDir job ('" + folder->firstOtherEntry +
                     "' is one), so nothing was written: choose an empty folder or one holding an earlier job (the "
                     "new job replaces it once complete), or pass --force to write the job into this folder anyway "
                     "(files of the job's names are replaced, the others kept)",
                 directory};
  return folder;
}

// Puts the complete job in `directory`'s place. The folder is looked at again: slicing takes minutes, and the
// user may have put files in it meanwhile. An empty folder or an earlier job is replaced as a whole, in one
// step; a folder holding other files (allowed) gets the job's files moved in, print-job.json last.
core::Status commitJob(core::StagedFolder& staged, const std::string& directory, bool writeIntoOtherFolder) {
  const core::Result<JobFolder> folder = outputFolder(directory, writeIntoOtherFolder);
  if (!folder) return folder.error();
  if (folder->kind == JobFolder::Kind::Other) return staged.moveEntriesInto("print-job.json");
  return staged.replaceTarget();
}

// Replaced, in every step after the first, by the lines that prime it (primeCommands).
constexpr const char* kPrimeMarker = "; MULTIDIR PRIME";

// The first number of a setting ("35,35" per extruder: 35).
double firstNumber(const std::string& text, double fallback) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return end == text.c_str() || !std::isfinite(value) ? fallback : value;
}

PrimeSettings primeSettings(const PrinterProfile& profile, const SliceJobOptions& options) {
  PrimeSettings prime;
  prime.retractLengthMm = firstNumber(setting(profile, options, "retract_length", ""), profile.retractLengthMm);
  prime.restartExtraMm = firstNumber(setting(profile, options, "retract_restart_extra", "0"), 0.0);
  const double retractSpeed = firstNumber(setting(profile, options, "retract_speed", "40"), 40.0);
  const double deretractSpeed = firstNumber(setting(profile, options, "deretract_speed", "0"), 0.0);
  prime.speedMmPerS = deretractSpeed > 0.0 ? deretractSpeed : (retractSpeed > 0.0 ? retractSpeed : 40.0);
  return prime;
}

// The same bounds `multidir run` checks the step files against again (step_recheck.h).
StepBounds stepBounds(const PrinterProfile& profile, const PrimeSettings& prime, int step, double baseZMm) {
  return stepBoundsFor(profile, prime.restartExtraMm, step, baseZMm);
}

// The z of the step's first extrusion after its marker (its first layer).
double firstLayerZ(const GcodeProgram& program, int step) {
  for (const GcodeMove& m : program.moves)
    if (m.step == step && m.extrudes()) return std::min(m.from.z(), m.to.z());
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

core::Result<std::vector<TurnPlan>> planTurns(const core::PrintJob& job, const PrinterProfile& profile,
                                               const Vec3& placementMm) {
  std::vector<TurnPlan> turns;
  const double lift = profile.platformZMm + profile.clearanceMarginMm;
  if (profile.platform == PlatformDrive::FirmwareTwoAxis) {
    // The two axes turn the part about their own lines, one at a time, in the order that keeps it lowest; the
    // platform's disc and cradle sweep with it (two_axis_motion.h).
    const TwoAxisMachine machine(profile, job.platform.radiusMm, placementMm);
    const core::Result<std::vector<TwoAxisAngles>> angles = machine.stepAngles(job);
    if (!angles) return angles.error();
    for (std::size_t k = 0; k + 1 < job.steps.size(); ++k) {
      const Eigen::Isometry3d toRest = machine.pose((*angles)[k]).inverse();
      std::vector<Vec3> printed = printedPoints(job, k);
      for (Vec3& p : printed) p = toRest * p;
      TurnPlan turn;
      turn.fromStep = job.steps[k].index;
      turn.twoAxis = machine.planTurn(printed, (*angles)[k], (*angles)[k + 1]);
      turn.fromDegrees = turn.twoAxis->from.tiltDegrees;
      turn.toDegrees = turn.twoAxis->to.tiltDegrees;
      turn.sweptTopZMm = turn.twoAxis->sweptTopZ + profile.platformZMm;
      turn.clearanceZMm = turn.twoAxis->sweptTopZ + lift;
      turns.push_back(turn);
    }
    return turns;
  }
  for (std::size_t k = 0; k + 1 < job.steps.size(); ++k) {
    const std::vector<Vec3> points = printedPoints(job, k);
    TurnPlan turn;
    turn.fromStep = job.steps[k].index;
    double top = -std::numeric_limits<double>::infinity();
    switch (job.machine.kind) {
      case core::MachineKind::RotaryPlatform: {
        turn.fromDegrees = job.steps[k].angles.rotaryDegrees;
        turn.toDegrees = job.steps[k + 1].angles.rotaryDegrees;
        const Vec3 axis = job.steps[k].modelToFile.linear() * job.machine.rotationAxis.normalized();
        const double turnRadians = -(turn.toDegrees - turn.fromDegrees) * M_PI / 180.0;
        // The next pose must be this one turned about the axis through the pivot (the machine frame's origin).
        const Eigen::Matrix3d expected = Eigen::AngleAxisd(turnRadians, axis).toRotationMatrix() *
                                         job.steps[k].modelToFile.linear();
        if ((expected - job.steps[k + 1].modelToFile.linear()).cwiseAbs().maxCoeff() > 1e-6)
          return Error{ErrorCode::Internal,
                       "the poses of steps " + std::to_string(k + 1) + " and " + std::to_string(k + 2) +
                           " do not differ by a turn about the rotation axis",
                       "print job"};
        top = sweptTopZ(points, axis, turnRadians);
        break;
      }
      case core::MachineKind::TiltRotate:
      case core::MachineKind::Apart:  // refused by sliceJob before it gets here
        top = anyTurnTopZ(points);
        break;
      case core::MachineKind::ThreeAxis:
        for (const Vec3& p : points) top = std::max(top, p.z());
        break;
    }
    turn.sweptTopZMm = top + profile.platformZMm;
    turn.clearanceZMm = top + lift;
    turns.push_back(turn);
  }
  return turns;
}

core::Result<SlicedJob> sliceJob(const core::PrintJob& input, const PrinterProfile& profile,
                                 const SliceJobOptions& options, const std::string& directory,
                                 core::JobContext& context) {
  if (input.options.frame != core::PrintJobOptions::Frame::Machine)
    return Error{ErrorCode::InvalidParameter, "slicing needs the job in the machine frame (as the machine holds it)",
                 "print job"};
  if (input.steps.empty()) return Error{ErrorCode::InvalidParameter, "the job has no steps", "print job"};
  if (input.machine.kind == core::MachineKind::Apart && input.steps.size() > 1)
    return Error{ErrorCode::InvalidParameter,
                 "a plan for the apart machine is printed as separate parts, not as one multi-step job: run "
                 "'multidir apart PLAN -o OUT --printer PROFILE'",
                 "print job"};
  // The settings given over the profile's (--set, the studio's Slice dialog) pass the profile's ranges too: the
  // slicer takes any number it is given (a temperature of 1e308 became M104 S1).
  for (const auto& [key, value] : options.settings)
    if (core::Status s = checkSettingValue(key, value, "slicer settings: " + key); !s) return s.error();
  // A folder that must not take the job is refused before anything is placed, sliced or written.
  if (core::Result<JobFolder> folder = outputFolder(directory, options.writeIntoOtherFolder); !folder)
    return folder.error();
  SlicedJob sliced;
  sliced.profile = profile;
  sliced.dialect = options.dialect.value_or(profile.dialect);
  if (input.steps.size() > 1 && profile.platform == PlatformDrive::None)
    return Error{ErrorCode::InvalidParameter,
                 "the printer '" + profile.name + "' cannot turn its platform (multidir.platform = none) but the job has " +
                     std::to_string(input.steps.size()) +
                     " steps: choose a profile with a rotary platform (firmware-axis or modbus)",
                 profile.path};
  if (profile.platform == PlatformDrive::FirmwareAxis && input.machine.kind == core::MachineKind::TiltRotate &&
      input.steps.size() > 1)
    return Error{ErrorCode::InvalidParameter,
                 "the printer turns its platform about one firmware axis, but the plan is for a 5-DOF robot arm: "
                 "decompose for a 4-DOF machine, or use a profile whose platform is driven over Modbus",
                 profile.path};

  // Every step prints from its base plane up (its supports clipped there), and the part is placed where it
  // fits the printer, or refused now rather than after the slicer ran (placement.h).
  // Two firmware axes hold the part as their own kinematics do (two_axis_motion.h), not as the plan's machine
  // would: every step is posed again, the first at rest.
  std::optional<core::PrintJob> twoAxisJob;
  std::optional<TwoAxisMachine> twoAxisMachine;
  std::vector<TwoAxisAngles> axisAngles;
  if (profile.platform == PlatformDrive::FirmwareTwoAxis) {
    twoAxisMachine.emplace(profile, input.platform.radiusMm);
    core::Result<std::vector<TwoAxisAngles>> angles = twoAxisMachine->stepAngles(input);
    if (!angles) return angles.error();
    axisAngles = std::move(angles).value();
    twoAxisJob = twoAxisMachine->posed(input, axisAngles);
  }
  const core::Result<core::PrintJob> clipped = withSupportsOnTheirBasePlanes(twoAxisJob ? *twoAxisJob : input);
  if (!clipped) return clipped.error();
  const core::Result<Placement> placement = placeOnPlatform(*clipped, profile);
  if (!placement) return placement.error();
  const core::PrintJob& job = placement->job;
  sliced.placementMm = placement->offsetMm;
  sliced.turns = placement->turns;  // planTurns of the placed job, computed once by the fit check
  if (twoAxisMachine) {
    twoAxisMachine.emplace(profile, input.platform.radiusMm, placement->offsetMm);  // the disc where the part is
    // The platform's own body must stay below the nozzle while it prints each step (the turns' clearance
    // includes it already): conservatively, below the step's base plane, under which the nozzle never goes.
    for (std::size_t k = 0; k < job.steps.size(); ++k) {
      const double body = twoAxisMachine->bodyTopZ(axisAngles[k]);
      if (body > job.steps[k].lowestHeightMm + 1e-3)
        return Error{ErrorCode::InvalidParameter,
                     "step " + std::to_string(job.steps[k].index) + ": with the axes at " +
                         profile.twoAxis.tilt.letter + " " + fixed(axisAngles[k].tiltDegrees, 1) + ", " +
                         profile.twoAxis.rotation.letter + " " + fixed(axisAngles[k].rotationDegrees, 1) +
                         " the platform's body (its disc of radius " + fixed(twoAxisMachine->platformRadiusMm(), 1) +
                         " mm and the tilt cradle) reaches z " + fixed(body + profile.platformZMm, 2) +
                         " mm, above the step's base plane at z " +
                         fixed(job.steps[k].lowestHeightMm + profile.platformZMm, 2) +
                         " mm where the nozzle prints its first layer: the nozzle would hit it. Plan with smaller "
                         "tilts, or check multidir.platform_radius, platform_thickness, cradle_box and tilt_height",
                     profile.path};
    }
  }
  if (profile.platform == PlatformDrive::FirmwareAxis && job.machine.kind == core::MachineKind::RotaryPlatform &&
      job.steps.size() > 1) {
    // The firmware's axis runs along the printer's X: the plan's axis must too, and A counts the plan's
    // angle with the sign that matches the axis' direction (positive A tilts the platform's top towards +Y).
    const Vec3 axis = job.steps.front().modelToFile.linear() * job.machine.rotationAxis.normalized();
    if (std::abs(std::abs(axis.x()) - 1.0) > 1e-6)
      return Error{ErrorCode::InvalidParameter,
                   "the plan turns the part about (" + fixed(axis.x()) + ", " + fixed(axis.y()) + ", " +
                       fixed(axis.z()) + ") in the printer's frame, but the printer's " + profile.rotaryAxis +
                       " axis runs along X: decompose with the machine's rotation axis along the platform frame's x "
                       "(no axis search)",
                   profile.path};
    if (axis.x() < 0.0)
      for (TurnPlan& turn : sliced.turns) {
        turn.fromDegrees = -turn.fromDegrees;
        turn.toDegrees = -turn.toDegrees;
      }
  }

  // The job is written into a fresh folder beside `directory` and takes its place only once complete
  // (commitJob): a slice that fails or is cancelled leaves `directory` as it was, an earlier good job included,
  // and nothing can be planted in the fresh folder while the job is written.
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) return Error{ErrorCode::WriteFailed, "cannot create the folder: " + ec.message(), directory};
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(directory);
  if (!staged) return staged.error();
  const std::string jobDir = staged->path();
  if (core::Status written = core::writePrintJob(job, jobDir); !written) return written.error();

  WorkFolder work;
  work.path = fs::path(jobDir) / (".slicing-" + std::to_string(::getpid()));
  fs::create_directories(work.path, ec);
  if (ec) return Error{ErrorCode::WriteFailed, "cannot create the work folder: " + ec.message(), work.path.string()};
  const std::string userOverlay = (work.path / "settings.ini").string();
  if (core::Status s = writeOverlay(userOverlay, options.settings); !s) return s.error();

  const PrusaSlicerEngine engine(options.slicerExecutable);
  sliced.engine = engine.name();
  const std::size_t n = job.steps.size();
  const double shares = static_cast<double>(n) + (options.fixedDirection ? 1.0 : 0.0) + 1.0;
  const Eigen::Isometry3d toPrinter = machineToPrinter(profile);
  const std::string layerHeight = setting(profile, options, "layer_height", "0.3");
  const std::string endSequence = "; MULTIDIR END SEQUENCE\\n";
  const PrimeSettings prime = primeSettings(profile, options);

  // Every slicing run the job needs (the steps, then the comparison), written out before any starts.
  std::vector<SliceTask> tasks;
  for (std::size_t k = 0; k < n; ++k) {
    const core::PrintJobStep& step = job.steps[k];
    const core::TriangleMesh solid = moved(joined(step.region, step.supports), toPrinter);
    const std::string meshPath = (work.path / stepName(step.index, ".stl")).string();
    if (core::Status s = core::saveMesh(solid, meshPath); !s) return s.error();

    // Step 1 starts the printer; later steps print on plastic: no skirt, brim or purge, normal first layer,
    // and the filament pushed back where the previous step drew it back (the prime, written once that
    // step's G-code says how far: kPrimeMarker).
    const bool first = k == 0;
    const bool last = k + 1 == n;
    std::vector<std::pair<std::string, std::string>> overlay;
    const std::string startText = first ? profile.startGcode : profile.stepStartGcode + "\\n" + kPrimeMarker;
    overlay.push_back({"start_gcode", "; MULTIDIR START SEQUENCE\\n" + startText + "\\n; MULTIDIR STEP " +
                                          std::to_string(step.index)});
    std::string end = profile.endGcode;
    if (!last && profile.platform != PlatformDrive::None) {
      // The slicer's end of print has drawn the filament back by retract_length: it stays so while the
      // platform turns, and the next step primes it.
      const TurnPlan& turn = sliced.turns[k];
      end = "G90\\nG1 Z" + fixed(turn.clearanceZMm) + " F600 ; lift above the swept part\\nG1 X" +
            fixed(profile.park.x()) + " Y" + fixed(profile.park.y()) + " F" +
            fixed(profile.travelSpeedMmPerS * 60.0, 0) + " ; park: the platform turns next";
    }
    overlay.push_back({"end_gcode", endSequence + end});
    overlay.push_back({"support_material", "0"});
    if (!first) {
      overlay.push_back({"skirts", "0"});
      overlay.push_back({"brim_width", "0"});
      overlay.push_back({"first_layer_height", layerHeight});
      overlay.push_back({"first_layer_temperature", setting(profile, options, "temperature", "200")});
      overlay.push_back({"first_layer_bed_temperature", setting(profile, options, "bed_temperature", "0")});
      for (const auto& entry : interfaceSettings()) overlay.push_back(entry);
    }
    const std::string overlayPath = (work.path / stepName(step.index, ".ini")).string();
    if (core::Status s = writeOverlay(overlayPath, overlay); !s) return s.error();

    SliceTask task;
    task.request.meshFile = meshPath;
    task.request.configFiles = {profile.path, userOverlay, overlayPath};
    // The clipped supports reach no lower than the base plane, so the solid's lowest point is on it and the
    // slicer's first layer lies one first_layer_height above it.
    task.request.zOffsetMm = lowestZ(solid);
    task.request.heightMm = heightOf(solid);
    task.request.outputFile = (work.path / stepName(step.index, ".gcode")).string();
    tasks.push_back(std::move(task));
  }
  if (options.fixedDirection) {
    // The whole model as it stands on the platform at rest (the first step's pose), the slicer's supports on.
    core::TriangleMesh model;
    const Eigen::Isometry3d rest = job.steps.front().modelToFile;
    for (const core::PrintJobStep& step : job.steps)
      model = joined(model, moved(step.region, toPrinter * rest * step.modelToFile.inverse()));
    const std::string meshPath = (work.path / "fixed-direction.stl").string();
    if (core::Status s = core::saveMesh(model, meshPath); !s) return s.error();
    const std::string overlayPath = (work.path / "fixed-direction.ini").string();
    if (core::Status s = writeOverlay(overlayPath, {{"support_material", "1"},
                                                    {"support_material_auto", "1"},
                                                    {"start_gcode", "; MULTIDIR START SEQUENCE\\n" + profile.startGcode +
                                                                        "\\n; MULTIDIR STEP 1"},
                                                    {"end_gcode", endSequence + profile.endGcode}});
        !s)
      return s.error();
    SliceTask task;
    task.request.meshFile = meshPath;
    task.request.configFiles = {profile.path, userOverlay, overlayPath};
    task.request.zOffsetMm = lowestZ(model);
    task.request.heightMm = heightOf(model);
    task.request.outputFile = (work.path / "fixed-direction.gcode").string();
    tasks.push_back(std::move(task));
  }

  if (core::Status s = runSideBySide(engine, tasks, n, shares, context); !s) return s.error();

  // In printing order: each step's prime from how the previous one left the filament, then its checks.
  std::vector<StepGcode> gcodes;
  FilamentState filament;
  for (std::size_t k = 0; k < n; ++k) {
    const core::PrintJobStep& step = job.steps[k];
    SliceRun& run = *tasks[k].run;
    SlicedStep out;
    out.index = step.index;
    out.gcodeFile = stepName(step.index, ".gcode");
    out.baseZMm = step.lowestHeightMm + profile.platformZMm;
    out.zOffsetMm = tasks[k].request.zOffsetMm;
    out.modelToPrinter = toPrinter * step.modelToFile;
    out.sliceSeconds = run.seconds;
    if (!axisAngles.empty()) out.axisDegrees = axisAngles[k];
    if (k > 0) {
      const std::size_t at = run.gcode.find(kPrimeMarker);
      if (at == std::string::npos)
        return Error{ErrorCode::Internal, "the slicer's G-code lacks MultiDir's prime marker", out.gcodeFile};
      std::string primeText = primeCommands(filament, prime);
      if (!primeText.empty() && primeText.back() == '\n') primeText.pop_back();
      run.gcode.replace(at, std::string(kPrimeMarker).size(), primeText);
    }

    const core::Result<GcodeProgram> program = parseGcode(run.gcode, rotaryAxisNames(profile), out.gcodeFile);
    if (!program) return program.error();
    StepBounds bounds = stepBounds(profile, prime, step.index, out.baseZMm);
    const bool turnsAfter = k + 1 < n && profile.platform != PlatformDrive::None;
    const core::Result<StepTotals> totals = checkStepProgram(
        *program, bounds, out.gcodeFile, turnsAfter ? &sliced.turns[k].clearanceZMm : nullptr, filament);
    if (!totals) return totals.error();
    out.totals = *totals;
    filament = totals->filamentAtEnd;
    out.firstLayerZMm = firstLayerZ(*program, step.index);
    const core::Result<Estimate> estimate = parseEstimate(run.gcode, out.gcodeFile);
    if (!estimate) return estimate.error();
    out.estimate = *estimate;
    sliced.total += out.estimate;
    sliced.steps.push_back(out);
    gcodes.push_back({step.index, run.gcode});
  }
  for (std::size_t k = 0; k < n; ++k)
    if (core::Status s = writeText((fs::path(jobDir) / sliced.steps[k].gcodeFile).string(), gcodes[k].text); !s)
      return s.error();

  if (options.fixedDirection) {
    const SliceRun& run = *tasks.back().run;
    sliced.fixedDirectionSliceSeconds = run.seconds;
    const core::Result<Estimate> estimate = parseEstimate(run.gcode, "fixed-direction.gcode");
    if (!estimate) return estimate.error();
    sliced.fixedDirection = *estimate;
  }

  if (profile.platform == PlatformDrive::FirmwareAxis || profile.platform == PlatformDrive::FirmwareTwoAxis) {
    context.setProgress((shares - 1.0) / shares, "stitching one program");
    const core::Result<std::string> stitched =
        stitchProgram(gcodes, sliced.turns, profile, sliced.dialect, sliced.total, prime);
    if (!stitched) return stitched.error();
    const core::Result<GcodeProgram> program = parseGcode(*stitched, rotaryAxisNames(profile), "job.gcode");
    if (!program) return program.error();
    std::vector<StepBounds> bounds;
    for (const SlicedStep& s : sliced.steps) bounds.push_back(stepBounds(profile, prime, s.index, s.baseZMm));
    std::vector<TurnClearance> clearances;
    for (const TurnPlan& t : sliced.turns) clearances.push_back({t.fromStep, t.clearanceZMm});
    const core::Result<std::vector<StepTotals>> checked = checkStitchedProgram(*program, bounds, clearances, "job.gcode");
    if (!checked) return checked.error();
    if (core::Status s = writeText((fs::path(jobDir) / "job.gcode").string(), *stitched); !s) return s.error();
    sliced.stitchedFile = "job.gcode";
  }
  if (core::Status s = recordInJobFile(jobDir, sliced, sliced.engine); !s) return s.error();
  work.remove();
  if (core::Status s = commitJob(*staged, directory, options.writeIntoOtherFolder); !s) return s.error();
  context.setProgress(1.0, "sliced");
  return sliced;
}

core::Result<SlicedJob> slicePlan(const core::LoadedPlan& plan, const PrinterProfile& profile,
                                  const SliceJobOptions& options, const std::string& directory,
                                  core::JobContext& context) {
  core::PrintJobOptions jobOptions;
  jobOptions.frame = core::PrintJobOptions::Frame::Machine;
  const core::Result<core::PrintJob> job = core::buildPrintJob(plan, jobOptions);
  if (!job) return job.error();
  return sliceJob(*job, profile, options, directory, context);
}

SliceStage sliceStageAt(double fraction, int stepCount, bool fixedDirection) {
  // The shares sliceJob reports: it starts step k (from 0) at k / shares, the comparison at n / shares and
  // stitching at (shares - 1) / shares. The small bias keeps k / shares * shares from rounding below k.
  const int n = std::max(0, stepCount);
  const double shares = static_cast<double>(n) + (fixedDirection ? 1.0 : 0.0) + 1.0;
  SliceStage stage;
  if (fraction >= 1.0) {
    stage.kind = SliceStage::Kind::Done;
    stage.step = n;
    return stage;
  }
  const int share = static_cast<int>(std::floor(std::max(0.0, fraction) * shares + 1e-6));
  if (share < n) {
    stage.step = share + 1;
  } else if (fixedDirection && share == n) {
    stage.kind = SliceStage::Kind::FixedDirection;
    stage.step = n;
  } else {
    stage.kind = SliceStage::Kind::Stitching;
    stage.step = n;
  }
  return stage;
}

}  // namespace multidir::slicing
