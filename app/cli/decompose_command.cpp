#include "decompose_command.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <algorithm>
#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "multidir/core/common/atomic_file.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/plan/checksum.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/plan/pose_runners_up.h"
#include "multidir/core/search/decompose.h"
#include "multidir/core/search/pose_search.h"
#include "multidir/core/supports/projected_supports.h"
#include "number_text.h"
#include "search_runner.h"

namespace multidir::cli {

const char* const kDecomposeHelp =
    "Usage: multidir decompose MODEL -o OUTDIR [options]\n"
    "\n"
    "Cuts MODEL (.stl, .obj, .off, .ply; millimetres) into regions that a multi-directional printer can print\n"
    "with as little support as possible, prints a table of the regions, and writes the plan to OUTDIR:\n"
    "plan.json and one STL per region (docs/plan-format.md). When risky faces remain (J_G > 0) it also grows\n"
    "projected tree supports for them and saves one support STL per region that needs any.\n"
    "\n"
    "Options:\n"
    "  -o OUTDIR            folder for the plan (created if missing; required)\n"
    "  --up DIRECTION       the model's up: x, y, z, -x, -y, -z or a,b,c (default: z, or the profile's)\n"
    "  --machine KIND       3dof, 4dof, 5dof or apart (default: 5dof, or the profile's); apart: an ordinary\n"
    "                       printer prints every region as a part of its own on its cut face, and the parts\n"
    "                       are glued with dowels (multidir apart; docs/apart.md)\n"
    "  --axis X,Y,Z         4dof: the platform's rotation axis, perpendicular to up (default: x, or y if up is x)\n"
    "  --axis-search N      4dof: also try N rotation axes over 180 degrees and keep the best plan\n"
    "  --pose MODE          up: stand the model on --up (default); auto: choose the pose too, among the\n"
    "                       given up and the poses the model stands in: on a patch of its convex hull that\n"
    "                       holds its centre of mass (the given up is always tried, so never worse)\n"
    "  --poses N            --pose auto: candidate poses, 1 to 200 (default: 24)\n"
    "  --pose-searches K    --pose auto: poses given the full search, 1 to N (default: 3)\n"
    "  --profile FILE       machine profile (JSON); --machine, --up and --axis override its fields\n"
    "  --scheme NAME        beam, greedy or cgreedy (default: beam)\n"
    "  --beam-width B       beams kept per level, 1 to 1000 (default: 10)\n"
    "  --alpha DEGREES      maximal self-supporting angle, at least 0 and below 90 (default: 45)\n"
    "  --normals N          candidate normals sampled on the sphere, 1 to 100000 (default: 250)\n"
    "  --refine N           beam: refine the best planes between the sampled normals in N rounds, 0 = off\n"
    "                       (default: 3)\n"
    "  --offset-step MM     spacing of candidate planes along a normal, 0.01 to 1000 (default: 1)\n"
    "  --w W                every region keeps at least 1/W of the model's volume, 1 to 1000 (default: 40)\n"
    "  --scales S           beam: search at S region scales, W, 2W, ..., side by side, the beams shared\n"
    "                       among them, 1 to 4 (default: 2)\n"
    "  --min-region-height MM\n"
    "                       no region is thinner than this along its printing direction (default: 2)\n"
    "  --min-plane-gain PERCENT\n"
    "                       a plane stays only if removing it would raise J_G by at least this share of\n"
    "                       J_G before (default: 1) ...\n"
    "  --min-plane-gain-area MM2\n"
    "                       ... and by at least this area (default: 1)\n"
    "  --part-cost MM2      apart: the fixed price of one more part, the risky area whose supports cost as much\n"
    "                       print time as its dowels (default: 120; docs/apart.md) ...\n"
    "  --cut-face-cost C    apart: ... plus C mm^2 per mm^2 of its cut face, whose two sides are printed solid\n"
    "                       (default: 0.28). A plane stays only if removing it would raise J_G by its price\n"
    "  --threads N          worker threads, 0 = all (default: 0)\n"
    "  --proxy-faces N      a model of more than N faces is searched on a simplified copy of at most N faces\n"
    "                       (and fewer where that changes the surface by less than 0.01 mm); its planes then\n"
    "                       cut the full model, and every number is the full model's. 1000 to 10000000\n"
    "                       (default: 50000)\n"
    "  --no-proxy           always search the full model (slow on models of a million faces)\n"
    "  --polish             after the search, move every plane continuously (normal and offset) to lower\n"
    "                       J_G further, every constraint kept (default: on)\n"
    "  --no-polish          keep the search's planes as found\n"
    "  --polish-effort E    how finely polishing goes, 1 to 6: its steps halve E - 1 times; each level costs\n"
    "                       about as much as the one before (default: 1)\n"
    "  --polish-finalists   also polish the search's best plan for every other number of cuts that may beat\n"
    "                       it and keep the least J_G after polishing: steadier plans (default: on)\n"
    "  --no-polish-finalists\n"
    "                       polish the search's own plan only\n"
    "  --search-tails       after polishing, search the plan's later planes again from each of its polished\n"
    "                       states and keep a lower plan found there: lower J_G on some models, about twice\n"
    "                       the time (default: off)\n"
    "  --no-search-tails    deliver the polished plan (the default)\n"
    "  --summary FILE       also write the key numbers as JSON to FILE\n"
    "  --no-supports        do not generate supports\n"
    "  --support-spacing MM overhang sampling distance R, strut radius R/4 (default: 2; 3 suits a 0.8 mm nozzle)\n"
    "  --scale FACTOR       multiply the model's coordinates by FACTOR, for a model in other units\n"
    "                       (0.001: micrometres, 25.4: inches; default: 1)\n"
    "  -h, --help           show this help\n"
    "\n"
    "On a terminal a status line shows the search's progress. Ctrl-C stops the search and saves the best plan\n"
    "found until then (plan.json then says \"cancelled\": true); a second Ctrl-C quits without saving.\n"
    "\n"
    "Exit codes: 0 ok, 1 the model or profile cannot be read or the plan cannot be written, 2 usage error.\n";

const std::set<std::string> kDecomposeValueOptions = {
    "--up",      "--machine", "--axis",    "--axis-search",     "--scheme",          "--beam-width",
    "--alpha",   "--normals", "--refine",  "--offset-step",     "--w",               "--scales",
    "--min-region-height",    "--min-plane-gain",               "--min-plane-gain-area", "--part-cost", "--cut-face-cost",
    "--threads", "--profile", "-o",        "--summary",         "--support-spacing", "--scale",
    "--pose",    "--poses",   "--pose-searches",                "--proxy-faces",     "--polish-effort"};
const std::set<std::string> kDecomposeFlags = {"--help",      "--no-supports", "--no-proxy",
                                               "--polish",    "--no-polish",   "--polish-finalists",
                                               "--no-polish-finalists", "--search-tails", "--no-search-tails"};

namespace {

namespace core = multidir::core;

const std::string kCommand = "multidir decompose";

int parseInteger(const std::string& text, const std::string& option) {
  const double value = parseNumber(text, option);
  if (value != std::floor(value) || std::abs(value) > 1e9)
    throw UsageError(kCommand + ": " + option + " expects a whole number, got '" + text + "'");
  return static_cast<int>(value);
}

// The command-line option behind a field validate(MachineSpec) names; the other fields come from --profile.
std::string optionFor(const std::string& where) {
  if (where == "rotation axis") return "--axis";
  if (where == "up") return "--up";
  return where;
}

struct Settings {
  std::string model;
  core::LoadOptions loadOptions;  // --scale
  std::string outDir;
  std::string summaryPath;
  core::Vec3 up = core::Vec3::UnitZ();
  core::MachineSpec machine;
  core::SearchOptions options;
  int axisSearch = 0;
  bool autoPose = false;
  core::PoseOptions poseOptions;
  bool supports = true;
  core::SupportOptions supportOptions;
};

core::MachineSpec machineFrom(const ParsedArgs& parsed) {
  core::MachineSpec machine;
  if (parsed.has("--profile")) {
    const std::string path = parsed.value("--profile", "");
    const core::Result<core::MachineSpec> profile = core::loadMachineProfile(path);
    if (!profile) throw FileError(kCommand + ": --profile: " + profile.error().describe());
    machine = *profile;
  } else {
    machine.rotationAxis = core::platformFrameX(machine.up);
  }
  if (parsed.has("--machine")) {
    const core::Result<core::MachineKind> kind = core::parseMachineKind(parsed.value("--machine", ""));
    if (!kind) throw UsageError(kCommand + ": --machine: " + kind.error().message);
    machine.kind = *kind;
  }
  if (parsed.has("--up")) {
    const core::Result<core::Vec3> up = core::parseDirection(parsed.value("--up", ""));
    if (!up) throw UsageError(kCommand + ": --up: " + up.error().message);
    machine.up = *up;
    // The axis must lie in the new platform plane; keep the profile's when it does.
    if (std::abs(machine.rotationAxis.dot(machine.up)) > 1e-6) machine.rotationAxis = core::platformFrameX(machine.up);
  }
  if (parsed.has("--axis")) {
    if (machine.kind != core::MachineKind::RotaryPlatform)
      throw UsageError(kCommand + ": --axis is the rotation axis of a 4dof machine; add --machine 4dof");
    const core::Result<core::Vec3> axis = core::parseDirection(parsed.value("--axis", ""));
    if (!axis) throw UsageError(kCommand + ": --axis: " + axis.error().message);
    machine.rotationAxis = *axis;
  }
  if (const core::Status valid = core::validate(machine); !valid) {
    const std::string where = optionFor(valid.error().where);
    if (parsed.has("--profile") && !parsed.has(where))
      throw FileError(kCommand + ": --profile " + parsed.value("--profile", "") + ": " + valid.error().message);
    throw UsageError(kCommand + ": " + where + ": " + valid.error().message);
  }
  return machine;
}

core::SearchOptions searchOptionsFrom(const ParsedArgs& parsed) {
  core::SearchOptions options;
  // Each option is checked as it is applied, so the message names the option at fault.
  auto apply = [&](const std::string& option, const std::function<void(const std::string&)>& set) {
    if (!parsed.has(option)) return;
    set(parsed.value(option, ""));
    if (const core::Status valid = core::validate(options); !valid)
      throw UsageError(kCommand + ": " + option + ": " + valid.error().message);
  };
  apply("--scheme", [&](const std::string& text) {
    const core::Result<core::SearchScheme> scheme = core::parseScheme(text);
    if (!scheme) throw UsageError(kCommand + ": --scheme: " + scheme.error().message);
    options.scheme = *scheme;
  });
  apply("--beam-width", [&](const std::string& t) { options.beamWidth = parseInteger(t, "--beam-width"); });
  apply("--alpha", [&](const std::string& t) { options.alphaMaxDegrees = parseNumber(t, "--alpha"); });
  apply("--normals", [&](const std::string& t) { options.candidates.normalSamples = parseInteger(t, "--normals"); });
  apply("--refine", [&](const std::string& t) { options.refinementRounds = parseInteger(t, "--refine"); });
  apply("--offset-step",
        [&](const std::string& t) { options.candidates.offsetStepMm = parseNumber(t, "--offset-step"); });
  apply("--w", [&](const std::string& t) { options.minVolumeDivisor = parseNumber(t, "--w"); });
  apply("--scales", [&](const std::string& t) { options.volumeScales = parseInteger(t, "--scales"); });
  apply("--min-region-height",
        [&](const std::string& t) { options.minRegionHeightMm = parseNumber(t, "--min-region-height"); });
  apply("--min-plane-gain",
        [&](const std::string& t) { options.minPlaneGainPercent = parseNumber(t, "--min-plane-gain"); });
  apply("--min-plane-gain-area",
        [&](const std::string& t) { options.minPlaneGainMm2 = parseNumber(t, "--min-plane-gain-area"); });
  apply("--part-cost", [&](const std::string& t) { options.partCostMm2 = parseNumber(t, "--part-cost"); });
  apply("--cut-face-cost", [&](const std::string& t) { options.cutFaceCost = parseNumber(t, "--cut-face-cost"); });
  apply("--threads", [&](const std::string& t) { options.threads = parseInteger(t, "--threads"); });
  apply("--proxy-faces", [&](const std::string& t) { options.proxyFaces = parseInteger(t, "--proxy-faces"); });
  // Two options that ask for opposite things: a usage error, whatever order they came in.
  const auto refuseBoth = [&](const std::string& one, const std::string& other) {
    if (parsed.has(one) && parsed.has(other))
      throw UsageError(kCommand + ": " + one + " and " + other + " contradict each other");
  };
  // An on/off pair (both refused above): the one given, else `value` as it is.
  const auto onOff = [&](const std::string& on, const std::string& off, bool& value) {
    if (parsed.has(on)) value = true;
    if (parsed.has(off)) value = false;
  };
  refuseBoth("--proxy-faces", "--no-proxy");
  if (parsed.has("--no-proxy")) options.proxyFaces = 0;
  refuseBoth("--polish", "--no-polish");
  refuseBoth("--polish-finalists", "--no-polish-finalists");
  refuseBoth("--polish-effort", "--no-polish");
  refuseBoth("--polish-finalists", "--no-polish");
  if (parsed.has("--no-polish")) {
    options.polish = false;
    options.polishFinalists = false;  // nothing is polished: plan.json says so
  }
  refuseBoth("--search-tails", "--no-search-tails");
  onOff("--search-tails", "--no-search-tails", options.searchTails);
  onOff("--polish-finalists", "--no-polish-finalists", options.polishFinalists);
  apply("--polish-effort", [&](const std::string& t) { options.polishEffort = parseInteger(t, "--polish-effort"); });
  return options;
}

Settings settingsFrom(const std::vector<std::string>& args, bool& helpOnly) {
  const ParsedArgs parsed = parseArgs(args, kDecomposeValueOptions, kDecomposeFlags, "decompose");
  helpOnly = parsed.has("--help");
  Settings s;
  if (helpOnly) return s;
  s.model = onlyPositional(parsed, "decompose", "model", "multidir decompose MODEL -o OUTDIR");
  s.outDir = outputFolder(parsed, "decompose", "the plan");
  s.loadOptions = modelLoadOptions(parsed, "decompose");
  if (parsed.has("--summary")) {
    s.summaryPath = parsed.value("--summary", "");
    if (s.summaryPath.empty()) throw UsageError(kCommand + ": --summary needs a file name");
  }
  s.supports = !parsed.has("--no-supports");
  if (parsed.has("--support-spacing")) {
    if (!s.supports) throw UsageError(kCommand + ": --support-spacing and --no-supports contradict each other");
    s.supportOptions.samplingSpacingMm = parseNumber(parsed.value("--support-spacing", ""), "--support-spacing");
    s.supportOptions.contactRadiusMm = std::min(s.supportOptions.contactRadiusMm, s.supportOptions.samplingSpacingMm / 4);
    if (const core::Status valid = core::validate(s.supportOptions); !valid)
      throw UsageError(kCommand + ": --support-spacing: " + valid.error().message);
  }
  s.machine = machineFrom(parsed);
  s.up = s.machine.up;
  s.options = searchOptionsFrom(parsed);
  if (parsed.has("--axis-search")) {
    if (s.machine.kind != core::MachineKind::RotaryPlatform)
      throw UsageError(kCommand + ": --axis-search turns the rotation axis of a 4dof machine; add --machine 4dof");
    s.axisSearch = parseInteger(parsed.value("--axis-search", ""), "--axis-search");
    if (s.axisSearch < 1 || s.axisSearch > 3600)
      throw UsageError(kCommand + ": --axis-search: the number of axes must be between 1 and 3600");
  }
  if (parsed.has("--pose")) {
    const std::string mode = parsed.value("--pose", "");
    if (mode != "auto" && mode != "up")
      throw UsageError(kCommand + ": --pose: \"" + mode + "\" is not a pose mode; use auto or up");
    s.autoPose = mode == "auto";
  }
  for (const char* option : {"--poses", "--pose-searches"})
    if (parsed.has(option) && !s.autoPose)
      throw UsageError(kCommand + ": " + option + " counts poses of the pose search; add --pose auto");
  if (parsed.has("--poses")) {
    s.poseOptions.poses = parseInteger(parsed.value("--poses", ""), "--poses");
    if (s.poseOptions.poses < 1 || s.poseOptions.poses > 200)
      throw UsageError(kCommand + ": --poses: the number of poses must be between 1 and 200");
    s.poseOptions.fullSearches = std::min(s.poseOptions.fullSearches, s.poseOptions.poses);
  }
  if (parsed.has("--pose-searches")) {
    s.poseOptions.fullSearches = parseInteger(parsed.value("--pose-searches", ""), "--pose-searches");
    if (s.poseOptions.fullSearches < 1 || s.poseOptions.fullSearches > s.poseOptions.poses)
      throw UsageError(kCommand + ": --pose-searches: must be between 1 and the number of poses (" +
                       std::to_string(s.poseOptions.poses) + ")");
  }
  if (s.autoPose && s.axisSearch > 0)
    throw UsageError(kCommand + ": --pose auto and --axis-search cannot be combined; choose one");
  return s;
}

// The pose as plan.json records it: the chosen one and the others tried that have a plan, best J_G first.
core::PlanPose planPoseOf(const core::PoseSearchResult& r) {
  core::PlanPose pose;
  pose.up = r.chosen.up;
  pose.rotation = r.rotation;
  pose.source = core::poseSourceName(r.chosen.source);
  pose.contactAreaMm2 = r.chosen.contactAreaMm2;
  pose.stabilityMarginMm = r.chosen.stabilityMarginMm;
  pose.runnersUp = core::poseRunnersUp(r, r.chosenTrial);
  return pose;
}

nlohmann::json poseSummary(const core::PlanPose& pose) {
  nlohmann::json runnersUp = nlohmann::json::array();
  for (const core::PlanPoseTrial& t : pose.runnersUp)
    runnersUp.push_back({{"up", {t.up.x(), t.up.y(), t.up.z()}}, {"source", t.source}, {"jg_after", t.jgAfterMm2},
                         {"regions", t.regions}, {"searched", t.searched}, {"contact_area", t.contactAreaMm2},
                         {"stability_margin", t.stabilityMarginMm}});
  nlohmann::json rotation = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) rotation.push_back({pose.rotation(r, 0), pose.rotation(r, 1), pose.rotation(r, 2)});
  return {{"up", {pose.up.x(), pose.up.y(), pose.up.z()}}, {"rotation", rotation}, {"source", pose.source},
          {"contact_area", pose.contactAreaMm2}, {"stability_margin", pose.stabilityMarginMm},
          {"runners_up", runnersUp}};
}

std::string vectorText(const core::Vec3& v) {
  return formatNumber("%6.3f", v.x()) + ", " + formatNumber("%6.3f", v.y()) + ", " + formatNumber("%6.3f", v.z());
}

void printTable(std::ostream& out, const Settings& s, const core::Decomposition& plan) {
  out << "Regions in printing order (" << plan.regions.size() << " regions, " << plan.clippingPlanes.size()
      << " clipping planes; " << core::machineKindName(s.machine.kind) << ", " << core::schemeName(s.options.scheme)
      << ")\n";
  char header[160];
  std::snprintf(header, sizeof header, "  %3s  %-24s  %-28s  %14s  %12s\n", "#", "direction (x, y, z)",
                "machine angles (degrees)", "volume mm^3", "risky mm^2");
  out << header;
  for (std::size_t i = 0; i < plan.regions.size(); ++i) {
    const core::Region& r = plan.regions[i];
    char row[200];
    std::snprintf(row, sizeof row, "  %3zu  %-24s  %-28s  %14.2f  %12.2f\n", i + 1,
                  vectorText(r.printingDirection).c_str(), machineAnglesText(s.machine.kind, r.angles).c_str(),
                  r.volumeMm3, r.riskyAreaMm2);
    out << row;
  }
  const double reduction = plan.jgBeforeMm2 > 0 ? 100.0 * (1.0 - plan.jgAfterMm2 / plan.jgBeforeMm2) : 0.0;
  out << "J_G before   " << formatNumber("%.2f", plan.jgBeforeMm2) << " mm^2 (risky area printed along up)\n"
      << "J_G after    " << formatNumber("%.2f", plan.jgAfterMm2) << " mm^2 (" << formatNumber("%.1f", reduction)
      << " % less)\n";
  if (s.machine.kind == core::MachineKind::RotaryPlatform)
    out << "Rotation axis " << vectorText(plan.rotationAxis) << "\n";
  const core::SearchStatistics& st = plan.statistics;
  out << "Search       " << formatNumber("%.2f", st.seconds) << " s, " << st.threads << " threads, "
      << withThousands(st.candidatesScored) << " candidates scored, " << st.levels << " levels\n";
  // A proxy search says so, and what changed on the full mesh (planes moved or dropped).
  for (const std::string& note : st.notes) out << "             " << note << "\n";
}

void writeSummary(const Settings& s, const core::Decomposition& plan, std::size_t triangles,
                  const std::vector<core::SupportSet>& supports, const std::optional<core::PlanPose>& pose) {
  double supportVolume = 0.0;
  std::size_t struts = 0;
  for (const core::SupportSet& set : supports) {
    supportVolume += set.volumeMm3;
    struts += set.struts.size();
  }
  const core::SearchStatistics& st = plan.statistics;
  nlohmann::json summary = {{"model", s.model},
                                  {"machine", core::machineKindName(s.machine.kind)},
                                  {"scheme", core::schemeName(s.options.scheme)},
                                  {"beam_width", s.options.beamWidth},
                                  {"axis_search", s.axisSearch},
                                  {"cancelled", plan.cancelled},
                                  {"triangles", triangles},
                                  {"normals", st.normals},
                                  {"candidates", st.candidatesScored},
                                  {"levels", st.levels},
                                  {"clips", st.clipsPerformed},
                                  {"regions", plan.regions.size()},
                                  {"planes", plan.clippingPlanes.size()},
                                  {"jg_before", plan.jgBeforeMm2},
                                  {"jg_after", plan.jgAfterMm2},
                                  {"seconds", st.seconds},
                                  {"threads", st.threads},
                                  {"proxy_faces", st.proxyFaces},
                                  {"support_volume", supportVolume},
                                  {"support_struts", struts},
                                  {"plan", s.outDir}};
  summary["pose_mode"] = s.autoPose ? "auto" : "up";
  if (pose) summary["pose"] = poseSummary(*pose);
  // Through core's atomic writer: a link at the path is replaced, never written through.
  if (const core::Status written = core::writeTextFileAtomically(s.summaryPath, summary.dump(2) + "\n"); !written)
    throw FileError(kCommand + ": cannot write the summary file: " + written.error().describe());
}

}  // namespace

void checkDecomposeOptions(const std::vector<std::string>& options) {
  std::vector<std::string> args = {"model", "-o", "plan"};
  args.insert(args.end(), options.begin(), options.end());
  bool helpOnly = false;
  settingsFrom(args, helpOnly);
}

int runDecompose(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool helpOnly = false;
  // Every option is checked before the model is read, so a typo costs no loading time.
  const Settings s = settingsFrom(args, helpOnly);
  if (helpOnly) {
    out << kDecomposeHelp;
    return kExitOk;
  }

  // A folder that cannot take the plan is refused before the search, not after it.
  checkOutputFolder(s.outDir, "decompose");
  const core::Result<core::LoadedMesh> loaded = core::loadMesh(s.model, s.loadOptions);
  if (!loaded) {
    err << kCommand << ": " << loaded.error().describe() << "\n";
    return kExitBadInput;
  }
  const core::Result<std::string> checksum = core::fileChecksum(s.model);
  if (!checksum) {
    err << kCommand << ": " << checksum.error().describe() << "\n";
    return kExitBadInput;
  }

  const core::TriangleMesh& model = loaded->mesh;
  const std::string startLine = kCommand + ": searching " + s.model + " (" +
                                withThousands(static_cast<long long>(model.faceCount())) + " triangles, " +
                                core::machineKindName(s.machine.kind) + ", " + core::schemeName(s.options.scheme) +
                                "); Ctrl-C stops and keeps the best plan so far";
  std::optional<core::PlanPose> pose;
  core::MachineSpec machine = s.machine;  // with the chosen pose's up when --pose auto
  const SearchCall search = [&](core::JobContext& job, const core::SearchProgressSink& progress) -> core::Result<core::Decomposition> {
    if (s.autoPose) {
      core::Result<core::PoseSearchResult> found = core::decomposeWithPoseSearch(model, s.machine, s.options, s.poseOptions, job);
      if (!found) return found.error();
      pose = planPoseOf(*found);
      machine = core::machineForPose(s.machine, found->chosen.up);
      return std::move(found->plan);
    }
    if (s.axisSearch > 0)
      return core::decomposeWithAxisSearch(model, s.machine, s.options, s.axisSearch, job, progress);
    return core::decompose(model, s.machine, s.options, job, progress);
  };
  const SearchOutcome outcome = runInterruptibleSearch(search, startLine, isatty(STDERR_FILENO) != 0, err);
  if (!outcome.result) {
    const core::Error& e = outcome.result.error();
    err << kCommand << ": " << e.describe() << "\n";
    if (e.code == core::ErrorCode::Cancelled) {
      err << kCommand << ": nothing was saved\n";
      return kExitBadInput;
    }
    return e.code == core::ErrorCode::Internal ? kExitInternal : kExitBadInput;
  }
  const core::Decomposition& plan = *outcome.result;

  printTable(out, s, plan);
  if (pose) {
    out << "Pose         up " << vectorText(pose->up) << " (" << pose->source << "; " << pose->runnersUp.size()
        << " other poses tried), standing on " << formatNumber("%.2f", pose->contactAreaMm2)
        << " mm^2, centre of mass " << formatNumber("%.2f", pose->stabilityMarginMm) << " mm inside its edge\n";
  }
  std::vector<core::SupportSet> supports;
  if (s.supports && plan.jgAfterMm2 > 0) {
    core::JobContext job;
    const core::Result<core::ProjectedSupports> grown =
        core::generateSupports(model, plan, machine, s.supportOptions, job);
    if (!grown) {
      err << kCommand << ": supports: " << grown.error().describe() << "\n";
      return grown.error().code == core::ErrorCode::Internal ? kExitInternal : kExitBadInput;
    }
    supports = grown->regions;
    int regionsWithSupports = 0;
    for (const core::SupportSet& set : supports) regionsWithSupports += set.empty() ? 0 : 1;
    out << "Supports     " << formatNumber("%.2f", grown->volumeMm3) << " mm^3, " << grown->struts.size()
        << " struts in " << regionsWithSupports << " regions, " << grown->contacts << " contacts ("
        << formatNumber("%.2f", grown->contactAreaMm2) << " mm^2)\n";
  }
  core::PlanMetadata metadata;
  metadata.modelPath = s.model;
  metadata.modelChecksum = *checksum;
  metadata.up = s.up;
  metadata.machine = machine;
  metadata.pose = pose;
  metadata.options = s.options;
  metadata.axisSearchCount = s.axisSearch;
  metadata.multidirVersion = MULTIDIR_VERSION;
  if (const core::Status saved = core::savePlan(plan, metadata, supports, s.outDir); !saved)
    throw FileError(kCommand + ": cannot write the plan: " + saved.error().describe());
  int supportFiles = 0;
  for (const core::SupportSet& set : supports) supportFiles += set.empty() ? 0 : 1;
  out << "Plan saved   " << s.outDir << "/plan.json and " << plan.regions.size() << " region STL files";
  if (supportFiles > 0) out << " and " << supportFiles << " support STL files";
  out << "\n";
  if (plan.cancelled)
    out << "Note: the search was cancelled; this is the best plan found until then, not the result of a full "
           "search\n";
  if (!s.summaryPath.empty()) writeSummary(s, plan, model.faceCount(), supports, pose);
  return kExitOk;
}

}  // namespace multidir::cli
