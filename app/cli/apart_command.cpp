#include "apart_command.h"

#include <cstdio>
#include <filesystem>
#include <iomanip>

#include "cli_args.h"
#include "multidir/apart/print_apart.h"
#include "multidir/assembly/dowels.h"
#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "multidir/slicing/estimates.h"
#include "multidir/slicing/printer_profile.h"

namespace multidir::cli {

const char* const kApartHelp =
    "Usage: multidir apart PLAN_OR_MODEL -o OUTDIR [--printer PROFILE] [options]\n"
    "\n"
    "Prints a plan on an ordinary printer: every region becomes a part laid on the bed on its cut face, parts\n"
    "that do not fit the printer are cut further, and the parts are joined by printed dowels in holes drilled\n"
    "into both faces of every joint (docs/apart.md). PLAN_OR_MODEL is a plan folder (multidir decompose; any\n"
    "machine's plan, printed apart as it is) or a model, searched first for the apart machine.\n"
    "\n"
    "Writes to OUTDIR: part-NN.stl and dowel-NN.stl (each laid cap down, in its own frame), plate-K.stl (what\n"
    "one plate of the bed holds), parts.3mf (every part and dowel placed on its plate, read back and checked),\n"
    "with --printer plate-K.gcode and whole.gcode (PrusaSlicer with its supports where a part still needs them,\n"
    "and the model in one piece with them), assembly.html with its pictures in sheet/ (the parts with their numbers, the order of\n"
    "gluing, the plates and the estimates), and apart.json with every number the table shows.\n"
    "\n"
    "Options:\n"
    "  -o OUTDIR            folder for the files (created if missing; required)\n"
    "  --printer PROFILE    printer profile (.ini, or a shipped name such as marlin-220): the bed and height\n"
    "                       parts must fit, the plates, and the slicer's settings. Without it parts are not\n"
    "                       limited in size and nothing is sliced\n"
    "  --up DIRECTION       a model's up: x, y, z, -x, -y, -z or a,b,c (default: z)\n"
    "  --scheme NAME        a model's search: beam, greedy or cgreedy (default: beam)\n"
    "  --part-cost MM2      a model's search: the risky area one more part must save, for its dowels and\n"
    "                       handling (default: 120) ...\n"
    "  --cut-face-cost C    ... and C mm^2 more per mm^2 of its cut face (default: 0.28; docs/apart.md)\n"
    "  --max-parts N        refuse a plan that needs more parts than this to fit the printer (default: 64)\n"
    "  --no-slice           with --printer: lay out and write the parts, but run no slicer\n"
    "  --scale FACTOR       multiply a model's coordinates by FACTOR (default: 1)\n"
    "  -h, --help           show this help\n"
    "\n"
    "Exit codes: 0 ok, 1 a file cannot be read or written or the plan cannot be printed apart, 2 usage error.\n";

namespace {

namespace fs = std::filesystem;
const std::string kCommand = "multidir apart";

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The plan to print apart: a saved plan as it is, or the model searched for the apart machine.
core::Decomposition planFrom(const ParsedArgs& parsed, const std::string& input, double& alphaMaxDegrees,
                             std::ostream& out) {
  const bool isPlan = fs::is_directory(input) || fs::path(input).filename() == "plan.json";
  if (isPlan) {
    for (const char* option : {"--up", "--scheme", "--part-cost", "--cut-face-cost", "--scale"})
      if (parsed.has(option))
        throw UsageError(kCommand + ": " + option + " is for a model; a plan is printed apart as it was searched");
    core::Result<core::LoadedPlan> loaded = core::loadPlan(input);
    if (!loaded) throw FileError(kCommand + ": " + loaded.error().describe());
    alphaMaxDegrees = loaded->metadata.options.alphaMaxDegrees;
    out << "Plan " << input << " (" << core::machineKindName(loaded->metadata.machine.kind) << ", "
        << loaded->decomposition.regions.size() << " regions), printed apart as it is\n";
    return std::move(loaded->decomposition);
  }
  core::Result<core::LoadedMesh> model = core::loadMesh(input, modelLoadOptions(parsed, kCommand));
  if (!model) throw FileError(kCommand + ": " + model.error().describe());
  core::MachineSpec machine;
  machine.kind = core::MachineKind::Apart;
  if (parsed.has("--up")) {
    const core::Result<core::Vec3> up = core::parseDirection(parsed.value("--up", ""));
    if (!up) throw UsageError(kCommand + ": --up: " + up.error().message);
    machine.up = *up;
  }
  machine.rotationAxis = core::platformFrameX(machine.up);
  core::SearchOptions options;
  if (parsed.has("--scheme")) {
    const core::Result<core::SearchScheme> scheme = core::parseScheme(parsed.value("--scheme", ""));
    if (!scheme) throw UsageError(kCommand + ": --scheme: " + scheme.error().message);
    options.scheme = *scheme;
  }
  if (parsed.has("--part-cost")) options.partCostMm2 = parseNumber(parsed.value("--part-cost", ""), "--part-cost");
  if (parsed.has("--cut-face-cost"))
    options.cutFaceCost = parseNumber(parsed.value("--cut-face-cost", ""), "--cut-face-cost");
  if (core::Status valid = core::validate(options); !valid)
    throw UsageError(kCommand + ": " + valid.error().message);
  alphaMaxDegrees = options.alphaMaxDegrees;
  out << "Searching " << input << " for the apart machine (" << core::schemeName(options.scheme) << ", part cost "
      << fixed(options.partCostMm2, 0) << " mm^2 + " << fixed(options.cutFaceCost, 2) << " per mm^2 of cut face)\n";
  core::JobContext job;
  core::Result<core::Decomposition> plan = core::decompose(model->mesh, machine, options, job);
  if (!plan) throw FileError(kCommand + ": " + plan.error().describe());
  out << "J_G before " << fixed(plan->jgBeforeMm2, 2) << " mm^2 (one piece along up), after " << fixed(plan->jgAfterMm2, 2)
      << " mm^2 with " << plan->regions.size() << " regions\n";
  return std::move(*plan);
}

}  // namespace

int runApart(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  (void)err;
  const ParsedArgs parsed =
      parseArgs(args, {"-o", "--printer", "--up", "--scheme", "--part-cost", "--cut-face-cost", "--max-parts", "--scale"},
                {"--help", "--no-slice"}, "apart");
  if (parsed.has("--help")) {
    out << kApartHelp;
    return kExitOk;
  }
  const std::string input = onlyPositional(parsed, kCommand, "plan or model", "multidir apart PLAN_OR_MODEL -o OUTDIR");
  const fs::path folder = outputFolder(parsed, kCommand, "the parts, dowels, plates and 3MF");
  checkOutputFolder(folder.string(), kCommand);
  if (parsed.has("--no-slice") && !parsed.has("--printer"))
    throw UsageError(kCommand + ": --no-slice goes with --printer (without a printer nothing is sliced)");

  apart::PrintApartOptions options;
  if (parsed.has("--printer")) {
    core::Result<slicing::PrinterProfile> loaded = slicing::loadPrinterProfile(parsed.value("--printer", ""));
    if (!loaded) throw FileError(kCommand + ": --printer: " + loaded.error().describe());
    options.printer = std::move(*loaded);
  }
  if (parsed.has("--max-parts")) {
    const double n = parseNumber(parsed.value("--max-parts", ""), "--max-parts");
    if (n != std::floor(n) || n < 1 || n > 1000) throw UsageError(kCommand + ": --max-parts expects 1 to 1000");
    options.maxParts = static_cast<int>(n);
  }
  options.slice = !parsed.has("--no-slice");
  options.title = "Assembly of " + fs::path(input).filename().string();

  const core::Decomposition plan = planFrom(parsed, input, options.alphaMaxDegrees, out);
  core::JobContext job;
  const core::Result<apart::ApartResult> result = apart::printApart(plan, options, folder.string(), job);
  if (!result) throw FileError(kCommand + ": " + result.error().describe());

  out << "Parts " << result->plan.parts.size() << " (" << result->plan.cutsToFit << " cut further to fit), joints "
      << result->plan.joints.size() << ", dowels " << result->layout.dowels.size() << ", plates "
      << result->plates.plates << "\n";
  out << "J_G apart " << fixed(result->plan.jgMm2, 2) << " mm^2 (the bed under every part; the plan: "
      << fixed(plan.jgAfterMm2, 2) << " mm^2)\n";
  for (const assembly::JointDowels& joint : result->layout.joints)
    if (!joint.note.empty()) out << "Joint " << joint.joint + 1 << ": " << joint.note << "\n";
  for (const assembly::PartLabel& label : result->labels)
    if (!label.placed) out << "Part " << label.part + 1 << ": " << label.note << "\n";
  if (result->sliced) {
    out << "Plate   time          filament cm^3\n";
    for (const apart::PlateEstimate& p : result->plateEstimates)
      out << std::setw(5) << p.plate + 1 << "   " << std::setw(12) << slicing::durationText(p.estimate.printSeconds)
          << "  " << fixed(p.estimate.filamentCm3, 2) << "\n";
    out << "Total   " << std::setw(12) << slicing::durationText(result->total.printSeconds) << "  "
        << fixed(result->total.filamentCm3, 2) << "\n";
    out << "One piece with supports " << slicing::durationText(result->whole.printSeconds) << "  "
        << fixed(result->whole.filamentCm3, 2) << " cm^3, of which support " << fixed(result->whole.supportCm3, 2)
        << " cm^3\n";
  }
  out << "Written to " << folder.string() << "\n";
  return kExitOk;
}

}  // namespace multidir::cli
