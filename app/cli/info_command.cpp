#include "info_command.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "multidir/core/common/atomic_file.h"
#include "multidir/core/search/pose_search.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_io.h"

namespace multidir::cli {

const char* const kInfoHelp =
    "Usage: multidir info MODEL [--up DIRECTION] [--alpha DEGREES] [--scale FACTOR] [--poses] [--json FILE]\n"
    "\n"
    "Loads MODEL (.stl, .obj, .off, .ply; millimetres), checks and repairs it, and prints its statistics,\n"
    "the defects found and repaired, and the area that would need support printed along the up direction.\n"
    "\n"
    "Options:\n"
    "  --up DIRECTION   printing direction: x, y, z, -x, -y, -z or three numbers a,b,c (default: z)\n"
    "  --alpha DEGREES  maximal self-supporting angle, at least 0 and below 90 (default: 45)\n"
    "  --scale FACTOR   multiply the model's coordinates by FACTOR, for a model in other units\n"
    "                   (0.001: micrometres, 25.4: inches; default: 1)\n"
    "  --poses          also list the candidate poses of 'decompose --pose auto' (the given up, then poses\n"
    "                   the model stands in; at most 24) with the contact area they stand on, the centre of\n"
    "                   mass's margin inside it (negative: it tips over) and their single-direction risky area\n"
    "  --json FILE      also write everything as JSON to FILE\n"
    "  -h, --help       show this help\n"
    "\n"
    "Exit codes: 0 ok, 1 the model cannot be loaded (or FILE written), 2 usage error.\n";

namespace {

namespace core = multidir::core;

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

nlohmann::json toJson(const core::Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

nlohmann::json toJson(const core::MeshStatistics& s) {
  return {{"triangles", s.triangles},
          {"vertices", s.vertices},
          {"shells", s.shells},
          {"genus", s.genus},
          {"closed", s.closed},
          {"bounds", {{"min", toJson(s.bounds.min)}, {"max", toJson(s.bounds.max)}, {"size", toJson(s.bounds.size())}}},
          {"areaMm2", s.areaMm2},
          {"volumeMm3", s.volumeMm3}};
}

nlohmann::json toJson(const core::MeshReport& report) {
  nlohmann::json defects = nlohmann::json::array();
  for (const core::MeshDefect& d : report.defects)
    defects.push_back({{"kind", d.kind},
                       {"count", d.count},
                       {"firstIndices", d.firstIndices},
                       {"description", d.description},
                       {"repaired", d.repaired},
                       {"needsRepair", d.needsRepair}});
  return {{"defects", defects}, {"repairs", report.repairs}};
}

// Through core's atomic writer, like every file MultiDir writes: a link at `path` is replaced, never written
// through, and a reader never sees half a file.
void writeJson(const std::string& path, const nlohmann::json& document) {
  if (const core::Status written = core::writeTextFileAtomically(path, document.dump(2) + "\n"); !written)
    throw FileError("multidir info: cannot write the JSON file: " + written.error().describe());
}

void printText(std::ostream& out, const std::string& model, const core::LoadedMesh& loaded, const core::Vec3& up,
               double alphaDegrees, const core::OverhangAnalysis& overhang) {
  const core::MeshStatistics& s = loaded.report.statistics;
  const core::Vec3 size = s.bounds.size();
  out << model << "\n"
      << "  triangles    " << s.triangles << "\n"
      << "  vertices     " << s.vertices << "\n"
      << "  shells       " << s.shells << "\n"
      << "  genus        " << s.genus << "\n"
      << "  closed       " << (s.closed ? "yes" : "no") << "\n"
      << "  size         " << format("%.2f", size.x()) << " x " << format("%.2f", size.y()) << " x "
      << format("%.2f", size.z()) << " mm\n"
      << "  area         " << format("%.2f", s.areaMm2) << " mm^2\n"
      << "  volume       " << format("%.2f", s.volumeMm3) << " mm^3\n";
  out << "Checks\n";
  if (loaded.report.defects.empty()) out << "  no defects found\n";
  for (const core::MeshDefect& d : loaded.report.defects)
    out << "  " << d.kind << " (" << d.count << "): " << d.description
        << (d.repaired ? " [repaired]" : (d.needsRepair ? "" : " [information]")) << "\n";
  for (const std::string& repair : loaded.report.repairs) out << "  repair: " << repair << "\n";
  const double fraction = s.areaMm2 > 0.0 ? overhang.riskyAreaMm2 / s.areaMm2 : 0.0;
  out << "Overhang (up " << format("%.4g", up.x()) << "," << format("%.4g", up.y()) << "," << format("%.4g", up.z())
      << ", alpha_max " << format("%.4g", alphaDegrees) << " degrees)\n"
      << "  risky faces  " << overhang.riskyFaces << "\n"
      << "  risky area   " << format("%.2f", overhang.riskyAreaMm2) << " mm^2 (" << format("%.1f", 100.0 * fraction)
      << " % of the surface)\n";
}

}  // namespace

int runInfo(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const ParsedArgs parsed = parseArgs(args, {"--up", "--alpha", "--json", "--scale"}, {"--help", "--poses"}, "info");
  if (parsed.has("--help")) {
    out << kInfoHelp;
    return kExitOk;
  }
  const std::string model = onlyPositional(parsed, "info", "model", "multidir info MODEL [options]");

  // Every option is checked before the model is read, so a typo costs no loading time.
  const core::Result<core::Vec3> up = core::parseDirection(parsed.value("--up", "z"));
  if (!up) throw UsageError("multidir info: --up: " + up.error().message);
  core::OverhangOptions overhangOptions;
  if (parsed.has("--alpha")) overhangOptions.alphaMaxDegrees = parseNumber(parsed.value("--alpha", ""), "--alpha");
  if (const core::Status valid = core::validate(overhangOptions); !valid)
    throw UsageError("multidir info: --alpha: " + valid.error().message);
  const std::string jsonPath = parsed.value("--json", "");
  if (parsed.has("--json") && jsonPath.empty()) throw UsageError("multidir info: --json needs a file name");

  const core::LoadOptions loadOptions = modelLoadOptions(parsed, "info");
  const core::Result<core::LoadedMesh> loaded = core::loadMesh(model, loadOptions);
  if (!loaded) {
    err << "multidir info: " << loaded.error().describe() << "\n";
    if (!jsonPath.empty())
      writeJson(jsonPath, {{"file", model},
                           {"error", {{"code", core::errorCodeName(loaded.error().code)},
                                      {"message", loaded.error().message},
                                      {"where", loaded.error().where}}}});
    return kExitBadInput;
  }
  const core::Result<core::OverhangAnalysis> overhang = core::analyzeOverhang(loaded->mesh, *up, overhangOptions);
  if (!overhang) throw UsageError("multidir info: " + overhang.error().describe());

  printText(out, model, *loaded, *up, overhangOptions.alphaMaxDegrees, *overhang);
  nlohmann::json poses = nlohmann::json::array();
  if (parsed.has("--poses")) {
    core::SearchOptions searchOptions;
    searchOptions.alphaMaxDegrees = overhangOptions.alphaMaxDegrees;
    const auto candidates = core::candidatePoses(loaded->mesh, *up, core::PoseOptions{}, searchOptions);
    if (!candidates) {
      err << "multidir info: poses: " << candidates.error().describe() << "\n";
      return kExitBadInput;
    }
    out << "Candidate poses (up, source, contact mm^2, margin mm, risky mm^2)\n";
    for (const core::PoseCandidate& c : *candidates) {
      out << "  " << format("%7.3f", c.up.x()) << " " << format("%7.3f", c.up.y()) << " " << format("%7.3f", c.up.z())
          << "  " << core::poseSourceName(c.source) << "  " << format("%.2f", c.contactAreaMm2) << "  "
          << format("%.2f", c.stabilityMarginMm) << "  " << format("%.2f", c.riskyAreaMm2) << "\n";
      poses.push_back({{"up", toJson(c.up)}, {"source", core::poseSourceName(c.source)},
                       {"contactAreaMm2", c.contactAreaMm2}, {"stabilityMarginMm", c.stabilityMarginMm},
                       {"riskyAreaMm2", c.riskyAreaMm2}, {"stands", c.stands()}});
    }
    const core::PoseCandidate& given = candidates->front();
    if (!given.stands())
      out << "  the given up does not stand (" << (given.contactAreaMm2 > 0 ? "its centre of mass falls outside the contact" : "the bed touches a point or an edge")
          << "): decompose --pose auto does not try it\n";
  }
  if (!jsonPath.empty()) {
    const double area = loaded->report.statistics.areaMm2;
    writeJson(jsonPath,
              {{"file", model},
               {"poses", poses},
               {"statistics", toJson(loaded->report.statistics)},
               {"checks", toJson(loaded->report)},
               {"overhang",
                {{"up", toJson(*up)},
                 {"alphaMaxDegrees", overhangOptions.alphaMaxDegrees},
                 {"riskyFaces", overhang->riskyFaces},
                 {"riskyAreaMm2", overhang->riskyAreaMm2},
                 {"riskyAreaFraction", area > 0.0 ? overhang->riskyAreaMm2 / area : 0.0}}}});
  }
  return kExitOk;
}

}  // namespace multidir::cli
