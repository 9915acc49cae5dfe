#include "report_command.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "multidir/core/common/atomic_file.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/supports/support_report.h"
#include "number_text.h"

namespace multidir::cli {

const char* const kReportHelp =
    "Usage: multidir report MODEL... [options]\n"
    "\n"
    "For each MODEL, decomposes it, generates projected tree supports for the plan and for printing the whole\n"
    "model along up (an ordinary 3-axis printer, same generator), and prints one row of the paper's table:\n"
    "triangles, search time, parts, J_G before and after, support volume fixed and multi-directional.\n"
    "\n"
    "Options:\n"
    "  --up DIRECTION        the models' up: x, y, z, -x, -y, -z or a,b,c (default: z)\n"
    "  --machine KIND        3dof, 4dof, 5dof or apart (default: 5dof)\n"
    "  --beam-width B        beams kept per level, 1 to 1000 (default: 10)\n"
    "  --normals N           candidate normals sampled on the sphere, 1 to 100000 (default: 250)\n"
    "  --threads N           worker threads of the search, 0 = all (default: 0)\n"
    "  --support-spacing MM  overhang sampling distance R, strut radius R/4 (default: 2; 3 suits a 0.8 mm nozzle)\n"
    "  --scale FACTOR        multiply the models' coordinates by FACTOR (0.001: micrometres, 25.4: inches)\n"
    "  --json FILE           also write the rows as JSON to FILE\n"
    "  -h, --help            show this help\n"
    "\n"
    "Exit codes: 0 ok, 1 a model cannot be read or the JSON file written, 2 usage error.\n";

namespace {

namespace core = multidir::core;

const std::string kCommand = "multidir report";

struct Settings {
  std::vector<std::string> models;
  core::LoadOptions loadOptions;  // --scale
  std::string jsonPath;
  core::MachineSpec machine;
  core::SearchOptions search;
  core::SupportOptions supports;
};

int wholeNumber(const std::string& text, const std::string& option) {
  const double value = parseNumber(text, option);
  if (value != std::floor(value) || std::abs(value) > 1e9)
    throw UsageError(kCommand + ": " + option + " expects a whole number, got '" + text + "'");
  return static_cast<int>(value);
}

Settings settingsFrom(const std::vector<std::string>& args, bool& helpOnly) {
  const ParsedArgs parsed = parseArgs(
      args, {"--up", "--machine", "--beam-width", "--normals", "--threads", "--support-spacing", "--json", "--scale"},
      {"--help"},
      "report");
  helpOnly = parsed.has("--help");
  Settings s;
  if (helpOnly) return s;
  if (parsed.positionals.empty()) throw UsageError(kCommand + ": which models? Usage: multidir report MODEL...");
  s.models = parsed.positionals;
  s.loadOptions = modelLoadOptions(parsed, "report");
  if (parsed.has("--machine")) {
    const core::Result<core::MachineKind> kind = core::parseMachineKind(parsed.value("--machine", ""));
    if (!kind) throw UsageError(kCommand + ": --machine: " + kind.error().message);
    s.machine.kind = *kind;
  }
  if (parsed.has("--up")) {
    const core::Result<core::Vec3> up = core::parseDirection(parsed.value("--up", ""));
    if (!up) throw UsageError(kCommand + ": --up: " + up.error().message);
    s.machine.up = *up;
  }
  s.machine.rotationAxis = core::platformFrameX(s.machine.up);
  if (const core::Status valid = core::validate(s.machine); !valid)
    throw UsageError(kCommand + ": " + valid.error().describe());
  if (parsed.has("--beam-width")) s.search.beamWidth = wholeNumber(parsed.value("--beam-width", ""), "--beam-width");
  if (parsed.has("--normals"))
    s.search.candidates.normalSamples = wholeNumber(parsed.value("--normals", ""), "--normals");
  if (parsed.has("--threads")) s.search.threads = wholeNumber(parsed.value("--threads", ""), "--threads");
  if (const core::Status valid = core::validate(s.search); !valid)
    throw UsageError(kCommand + ": " + valid.error().describe());
  if (parsed.has("--support-spacing")) {
    s.supports.samplingSpacingMm = parseNumber(parsed.value("--support-spacing", ""), "--support-spacing");
    s.supports.contactRadiusMm = std::min(s.supports.contactRadiusMm, s.supports.samplingSpacingMm / 4.0);
    if (const core::Status valid = core::validate(s.supports); !valid)
      throw UsageError(kCommand + ": --support-spacing: " + valid.error().message);
  }
  if (parsed.has("--json")) {
    s.jsonPath = parsed.value("--json", "");
    if (s.jsonPath.empty()) throw UsageError(kCommand + ": --json needs a file name");
  }
  return s;
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

void printHeader(std::ostream& out) {
  char line[256];
  std::snprintf(line, sizeof line, "%-18s %9s %9s %6s %12s %12s %14s %14s\n", "model", "triangles", "search s",
                "parts", "J_G before", "J_G after", "support fixed", "support multi");
  out << line;
  std::snprintf(line, sizeof line, "%-18s %9s %9s %6s %12s %12s %14s %14s\n", "", "", "", "", "mm^2", "mm^2", "mm^3",
                "mm^3");
  out << line;
}

void printRow(std::ostream& out, const std::string& model, const core::SupportReport& r) {
  char line[256];
  std::snprintf(line, sizeof line, "%-18s %9s %9.1f %6d %12.2f %12.2f %14.2f %14.2f%s\n", baseName(model).c_str(),
                withThousands(static_cast<long long>(r.triangles)).c_str(), r.searchSeconds, r.regions, r.jgBeforeMm2,
                r.jgAfterMm2, r.fixedVolumeMm3, r.multiVolumeMm3, r.cancelled ? "  (cancelled)" : "");
  out << line;
}

nlohmann::json statisticsJson(const core::SupportStatistics& s) {
  return {{"face_samples", s.faceSamples}, {"edge_samples", s.edgeSamples}, {"point_samples", s.pointSamples},
          {"dropped_samples", s.droppedSamples}, {"merges", s.merges},       {"projections", s.projections},
          {"on_platform", s.onPlatform},         {"on_model", s.onModel},     {"stuck", s.stuck},
          {"seconds", s.seconds}};
}

nlohmann::json rowJson(const std::string& model, const core::SupportReport& r) {
  return {{"model", model},
          {"triangles", r.triangles},
          {"search_seconds", r.searchSeconds},
          {"parts", r.regions},
          {"jg_before", r.jgBeforeMm2},
          {"jg_after", r.jgAfterMm2},
          {"support_volume_fixed", r.fixedVolumeMm3},
          {"support_volume_multi", r.multiVolumeMm3},
          {"contact_area_fixed", r.fixedContactAreaMm2},
          {"contact_area_multi", r.multiContactAreaMm2},
          {"support_seconds", r.supportSeconds},
          {"cancelled", r.cancelled},
          {"fixed", statisticsJson(r.fixedStatistics)},
          {"multi", statisticsJson(r.multiStatistics)}};
}

}  // namespace

int runReport(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool helpOnly = false;
  const Settings s = settingsFrom(args, helpOnly);
  if (helpOnly) {
    out << kReportHelp;
    return kExitOk;
  }
  out << "Machine " << core::machineKindName(s.machine.kind) << ", beam width " << s.search.beamWidth << ", alpha "
      << formatNumber("%.0f", s.search.alphaMaxDegrees) << " degrees, support spacing R "
      << formatNumber("%.1f", s.supports.samplingSpacingMm) << " mm\n";
  printHeader(out);
  nlohmann::json rows = nlohmann::json::array();
  int status = kExitOk;
  for (const std::string& model : s.models) {
    const core::Result<core::LoadedMesh> loaded = core::loadMesh(model, s.loadOptions);
    if (!loaded) {
      err << kCommand << ": " << loaded.error().describe() << "\n";
      status = kExitBadInput;
      continue;
    }
    core::JobContext job;
    const core::Result<core::SupportReport> report =
        core::supportReport(loaded->mesh, s.machine, s.search, s.supports, job);
    if (!report) {
      err << kCommand << ": " << model << ": " << report.error().describe() << "\n";
      status = report.error().code == core::ErrorCode::Internal ? kExitInternal : kExitBadInput;
      continue;
    }
    printRow(out, model, *report);
    out.flush();
    rows.push_back(rowJson(model, *report));
  }
  if (!s.jsonPath.empty()) {
    // Through core's atomic writer: a link at the path is replaced, never written through.
    if (const core::Status written = core::writeTextFileAtomically(s.jsonPath, rows.dump(2) + "\n"); !written)
      throw FileError(kCommand + ": cannot write the JSON file: " + written.error().describe());
  }
  return status;
}

}  // namespace multidir::cli
