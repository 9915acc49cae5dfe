#include "multidir/slicing/slice_job.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/slicing/clearance.h"
#include "multidir/slicing/gcode_program.h"
#include "multidir/slicing/slicer_engine.h"

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

core::Status writeText(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".part";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) return Error{ErrorCode::WriteFailed, "cannot write the file (disk full or no permission?)", path};
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) return Error{ErrorCode::WriteFailed, "cannot move the file into place: " + ec.message(), path};
  return core::Done{};
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

// A temporary folder for meshes and config overlays, removed when the job ends.
struct WorkFolder {
  fs::path path;
  ~WorkFolder() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

// The printer's XY and Z for a machine-frame point: the platform centre and plane of the profile.
Eigen::Isometry3d machineToPrinter(const PrinterProfile& profile) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Vec3(profile.platformCenter.x(), profile.platformCenter.y(), profile.platformZMm);
  return t;
}

// Every point printed up to step k (regions and supports of steps 1..k), posed for step k (machine frame).
std::vector<Vec3> printedPoints(const core::PrintJob& job, std::size_t k) {
  std::vector<Vec3> points;
  const Eigen::Isometry3d toK = job.steps[k].modelToFile;
  for (std::size_t i = 0; i <= k; ++i) {
    const Eigen::Isometry3d motion = toK * job.steps[i].modelToFile.inverse();
    for (const core::TriangleMesh* mesh : {&job.steps[i].region, &job.steps[i].supports})
      for (const Vec3& v : mesh->vertices) points.push_back(motion * v);
  }
  return points;
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
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (const SlicedStep& s : sliced.steps) {
    nlohmann::ordered_json step = {{"index", s.index}, {"gcode", s.gcodeFile}};
    step["estimate"] = estimateJson(s.estimate);
    step["extrusions"] = s.totals.extrusions;
    step["baseZMm"] = s.baseZMm;
    step["highestZMm"] = s.totals.highestZMm;
    step["sliceSeconds"] = s.sliceSeconds;
    steps.push_back(step);
  }
  slicing["steps"] = steps;
  nlohmann::ordered_json turns = nlohmann::ordered_json::array();
  for (const TurnPlan& t : sliced.turns)
    turns.push_back({{"fromStep", t.fromStep},
                     {"fromDegrees", t.fromDegrees},
                     {"toDegrees", t.toDegrees},
                     {"sweptTopZMm", t.sweptTopZMm},
                     {"clearanceZMm", t.clearanceZMm}});
  slicing["turns"] = turns;
  slicing["total"] = estimateJson(sliced.total);
  slicing["stitched"] = sliced.stitchedFile.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(sliced.stitchedFile);
  slicing["fixedDirection"] =
      sliced.fixedDirection ? estimateJson(*sliced.fixedDirection) : nlohmann::ordered_json();
  job["slicing"] = slicing;
  return writeText(path, job.dump(2) + "\n");
}

}  // namespace

core::Result<std::vector<TurnPlan>> planTurns(const core::PrintJob& job, const PrinterProfile& profile) {
  std::vector<TurnPlan> turns;
  const double lift = profile.platformZMm + profile.clearanceMarginMm;
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

core::Result<SlicedJob> sliceJob(const core::PrintJob& job, const PrinterProfile& profile,
                                 const SliceJobOptions& options, const std::string& directory,
                                 core::JobContext& context) {
  if (job.options.frame != core::PrintJobOptions::Frame::Machine)
    return Error{ErrorCode::InvalidParameter, "slicing needs the job in the machine frame (as the machine holds it)",
                 "print job"};
  if (job.steps.empty()) return Error{ErrorCode::InvalidParameter, "the job has no steps", "print job"};
  SlicedJob sliced;
  sliced.profile = profile;
  sliced.dialect = options.dialect.value_or(profile.dialect);
  if (job.steps.size() > 1 && profile.platform == PlatformDrive::None)
    return Error{ErrorCode::InvalidParameter,
                 "the printer '" + profile.name + "' cannot turn its platform (multidir.platform = none) but the job has " +
                     std::to_string(job.steps.size()) +
                     " steps: choose a profile with a rotary platform (firmware-axis or modbus)",
                 profile.path};
  if (profile.platform == PlatformDrive::FirmwareAxis && job.machine.kind == core::MachineKind::TiltRotate &&
      job.steps.size() > 1)
    return Error{ErrorCode::InvalidParameter,
                 "the printer turns its platform about one firmware axis, but the plan is for a 5-DOF robot arm: "
                 "decompose for a 4-DOF machine, or use a profile whose platform is driven over Modbus",
                 profile.path};

  const core::Result<std::vector<TurnPlan>> turns = planTurns(job, profile);
  if (!turns) return turns.error();
  sliced.turns = *turns;
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
  for (const TurnPlan& turn : sliced.turns)
    if (turn.clearanceZMm > profile.maxPrintHeightMm)
      return Error{ErrorCode::CheckFailed,
                   "step " + std::to_string(turn.fromStep) + ": while the platform turns to the next step the part "
                   "sweeps up to z " + fixed(turn.sweptTopZMm, 2) + " mm; with the margin the nozzle would have to "
                   "rise to " + fixed(turn.clearanceZMm, 2) + " mm, above the printer's height (max_print_height " +
                   fixed(profile.maxPrintHeightMm, 2) + " mm)",
                   profile.path};

  std::error_code ec;
  fs::create_directories(directory, ec);
  if (core::Status written = core::writePrintJob(job, directory); !written) return written.error();

  WorkFolder work;
  work.path = fs::path(directory) / (".slicing-" + std::to_string(::getpid()));
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
  std::vector<StepGcode> gcodes;

  for (std::size_t k = 0; k < n; ++k) {
    if (context.isCancelled()) return Error{ErrorCode::Cancelled, "slicing was cancelled", "slicing"};
    const core::PrintJobStep& step = job.steps[k];
    context.setProgress(static_cast<double>(k) / shares,
                        "slicing step " + std::to_string(step.index) + " of " + std::to_string(n));
    const core::TriangleMesh solid = moved(joined(step.region, step.supports), toPrinter);
    const std::string meshPath = (work.path / stepName(step.index, ".stl")).string();
    if (core::Status s = core::saveMesh(solid, meshPath); !s) return s.error();

    // Step 1 starts the printer; later steps print on plastic: no skirt, brim or purge, normal first layer.
    const bool first = k == 0;
    const bool last = k + 1 == n;
    std::vector<std::pair<std::string, std::string>> overlay;
    const std::string startText = first ? profile.startGcode : profile.stepStartGcode;
    overlay.push_back({"start_gcode", "; MULTIDIR START SEQUENCE\\n" + startText + "\\n; MULTIDIR STEP " +
                                          std::to_string(step.index)});
    std::string end = profile.endGcode;
    if (!last && profile.platform != PlatformDrive::None) {
      const TurnPlan& turn = sliced.turns[k];
      end = "G92 E0\\nG1 E" + fixed(-profile.retractLengthMm, 4) + " F2400 ; retract\\nG90\\nG1 Z" +
            fixed(turn.clearanceZMm) + " F600 ; lift above the swept part\\nG1 X" + fixed(profile.park.x()) + " Y" +
            fixed(profile.park.y()) + " F" + fixed(profile.travelSpeedMmPerS * 60.0, 0) +
            " ; park: the platform turns next";
    }
    overlay.push_back({"end_gcode", endSequence + end});
    overlay.push_back({"support_material", "0"});
    if (!first) {
      overlay.push_back({"skirts", "0"});
      overlay.push_back({"brim_width", "0"});
      overlay.push_back({"first_layer_height", layerHeight});
      overlay.push_back({"first_layer_temperature", setting(profile, options, "temperature", "200")});
      overlay.push_back({"first_layer_bed_temperature", setting(profile, options, "bed_temperature", "0")});
    }
    const std::string overlayPath = (work.path / stepName(step.index, ".ini")).string();
    if (core::Status s = writeOverlay(overlayPath, overlay); !s) return s.error();

    SlicedStep out;
    out.index = step.index;
    out.gcodeFile = stepName(step.index, ".gcode");
    out.baseZMm = step.lowestHeightMm + profile.platformZMm;
    out.zOffsetMm = lowestZ(solid);
    out.modelToPrinter = toPrinter * step.modelToFile;
    SliceRequest request;
    request.meshFile = meshPath;
    request.configFiles = {profile.path, userOverlay, overlayPath};
    request.zOffsetMm = out.zOffsetMm;
    request.outputFile = (work.path / out.gcodeFile).string();
    core::Result<SliceRun> run = engine.slice(request, context);
    if (!run) return run.error();
    out.sliceSeconds = run->seconds;

    const core::Result<GcodeProgram> program = parseGcode(run->gcode, profile.rotaryAxis, out.gcodeFile);
    if (!program) return program.error();
    StepBounds bounds;
    bounds.step = step.index;
    bounds.baseZMm = out.baseZMm;
    bounds.bedMin = profile.bedMin();
    bounds.bedMax = profile.bedMax();
    bounds.maxZMm = profile.maxPrintHeightMm;
    const bool turnsAfter = !last && profile.platform != PlatformDrive::None;
    const core::Result<StepTotals> totals =
        checkStepProgram(*program, bounds, out.gcodeFile, turnsAfter ? &sliced.turns[k].clearanceZMm : nullptr);
    if (!totals) return totals.error();
    out.totals = *totals;
    const core::Result<Estimate> estimate = parseEstimate(run->gcode, out.gcodeFile);
    if (!estimate) return estimate.error();
    out.estimate = *estimate;
    sliced.total += out.estimate;
    if (core::Status s = writeText((fs::path(directory) / out.gcodeFile).string(), run->gcode); !s) return s.error();
    gcodes.push_back({step.index, std::move(run->gcode)});
    sliced.steps.push_back(out);
  }

  if (options.fixedDirection) {
    // The whole model as it stands on the platform at rest (the first step's pose), the slicer's supports on.
    context.setProgress(static_cast<double>(n) / shares, "slicing the fixed-direction print for comparison");
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
    SliceRequest request;
    request.meshFile = meshPath;
    request.configFiles = {profile.path, userOverlay, overlayPath};
    request.zOffsetMm = lowestZ(model);
    request.outputFile = (work.path / "fixed-direction.gcode").string();
    core::Result<SliceRun> run = engine.slice(request, context);
    if (!run) return run.error();
    sliced.fixedDirectionSliceSeconds = run->seconds;
    const core::Result<Estimate> estimate = parseEstimate(run->gcode, "fixed-direction.gcode");
    if (!estimate) return estimate.error();
    sliced.fixedDirection = *estimate;
  }

  if (profile.platform == PlatformDrive::FirmwareAxis) {
    context.setProgress((shares - 1.0) / shares, "stitching one program");
    const core::Result<std::string> stitched = stitchProgram(gcodes, sliced.turns, profile, sliced.dialect, sliced.total);
    if (!stitched) return stitched.error();
    const core::Result<GcodeProgram> program = parseGcode(*stitched, profile.rotaryAxis, "job.gcode");
    if (!program) return program.error();
    std::vector<StepBounds> bounds;
    for (const SlicedStep& s : sliced.steps) {
      StepBounds b;
      b.step = s.index;
      b.baseZMm = s.baseZMm;
      b.bedMin = profile.bedMin();
      b.bedMax = profile.bedMax();
      b.maxZMm = profile.maxPrintHeightMm;
      bounds.push_back(b);
    }
    std::vector<TurnClearance> clearances;
    for (const TurnPlan& t : sliced.turns) clearances.push_back({t.fromStep, t.clearanceZMm});
    const core::Result<std::vector<StepTotals>> checked = checkStitchedProgram(*program, bounds, clearances, "job.gcode");
    if (!checked) return checked.error();
    if (core::Status s = writeText((fs::path(directory) / "job.gcode").string(), *stitched); !s) return s.error();
    sliced.stitchedFile = "job.gcode";
  }
  if (core::Status s = recordInJobFile(directory, sliced, sliced.engine); !s) return s.error();
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
