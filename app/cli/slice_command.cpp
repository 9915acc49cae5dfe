#include "slice_command.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_args.h"
#include "multidir/core/plan/print_job.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/slice_job.h"
#include "number_text.h"
#include "progress_line.h"

namespace multidir::cli {

const char* const kSliceHelp =
    "Usage: multidir slice PLAN_OR_JOB --printer PROFILE -o OUTDIR [options]\n"
    "\n"
    "Slices every step of a plan's print job with PrusaSlicer (prusa-slicer must be installed): each region\n"
    "with its supports, posed as the machine holds it, layers starting on its base plane. Every G-code is\n"
    "read back and checked (extrusions on or above the step's base plane and inside the printer; the platform\n"
    "turns only with the nozzle above the swept part). Writes into OUTDIR the print job (step meshes and\n"
    "print-job.json with the estimates under \"slicing\"), step-01.gcode, ... and, when the printer turns its\n"
    "platform by a firmware axis, job.gcode: one program with one start and one end sequence.\n"
    "PLAN_OR_JOB is a plan folder (multidir decompose) or a print-job folder (multidir export) whose plan is\n"
    "still where print-job.json says.\n"
    "\n"
    "Options:\n"
    "  --printer PROFILE      a PrusaSlicer .ini with MultiDir's keys (docs/slicing.md) or a shipped profile:\n"
    "                         SHIPPED_PROFILES (required)\n"
    "  -o OUTDIR              output folder (created if missing; required): empty, or holding an earlier job,\n"
    "                         which the new job replaces only once it is complete\n"
    "  --force                also write into an OUTDIR holding other files (the job's files replace those of\n"
    "                         the same names; the others stay)\n"
    "  --dialect DIALECT      how the firmware turns the platform: klipper, marlin or rrf (default: the profile's)\n"
    "  --set \"KEY=VALUE ...\"  slicer settings over the profile's, separated by spaces (layer_height=0.3)\n"
    "  --no-comparison        do not slice the fixed-direction print (whole model along up, slicer supports)\n"
    "  --slicer PROGRAM       the prusa-slicer program (default: prusa-slicer on PATH)\n"
    "  -h, --help             show this help\n"
    "\n"
    "The part is placed on the platform where it fits the printer (every step, and on a rotary platform what the\n"
    "turns sweep) before anything is sliced; a part that cannot fit is refused at once, saying by how much.\n"
    "Steps are sliced side by side, one slicer per core. On a terminal a status line shows the progress (plain\n"
    "lines elsewhere). Ctrl-C stops every slicer and removes the work folder; OUTDIR stays as it was.\n"
    "\n"
    "Exit codes: 0 ok, 1 a file cannot be read, OUTDIR holds other files (without --force), the part does not\n"
    "fit, the slicer failed or a check refused the G-code, 2 usage error, 130 interrupted (Ctrl-C or SIGTERM).\n";

namespace {

namespace core = multidir::core;
namespace slicing = multidir::slicing;

// "klipper-2axis, klipper-rotary, ...": the shipped printer profiles, as --printer takes them.
std::string shippedProfileList() {
  std::string list;
  for (const std::string& name : slicing::builtinPrinterNames()) list += (list.empty() ? "" : ", ") + name;
  return list;
}
namespace fs = std::filesystem;

const std::string kCommand = "multidir slice";
constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as a shell reports a command Ctrl-C ended

volatile std::sig_atomic_t gInterrupted = 0;

extern "C" void onSliceInterrupt(int) { gInterrupted = 1; }

// SIGINT and SIGTERM only raise a flag while the job runs: the command then cancels it, so every slicer is
// stopped and the work folder removed (the default action would end the process and leave both behind). A
// second signal changes nothing (a Ctrl-C reaches the process and its group, timeout(1) sends two); stopping
// takes at most about a second (a slicer that ignores SIGTERM gets SIGKILL).
class InterruptScope {
 public:
  InterruptScope() {
    gInterrupted = 0;
    struct sigaction action {};
    action.sa_handler = onSliceInterrupt;
    sigemptyset(&action.sa_mask);
    m_int = sigaction(SIGINT, &action, &m_previousInt) == 0;
    m_term = sigaction(SIGTERM, &action, &m_previousTerm) == 0;
  }
  ~InterruptScope() {
    if (m_int) sigaction(SIGINT, &m_previousInt, nullptr);
    if (m_term) sigaction(SIGTERM, &m_previousTerm, nullptr);
  }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  struct sigaction m_previousInt {};
  struct sigaction m_previousTerm {};
  bool m_int = false;
  bool m_term = false;
};

struct Settings {
  std::string input;
  std::string outDir;
  std::string printer;
  slicing::SliceJobOptions options;
};

Settings settingsFrom(const std::vector<std::string>& args, bool& helpOnly) {
  const ParsedArgs parsed =
      parseArgs(args, {"-o", "--printer", "--dialect", "--set", "--slicer"}, {"--help", "--no-comparison", "--force"}, "slice");
  helpOnly = parsed.has("--help");
  Settings s;
  if (helpOnly) return s;
  s.input = onlyPositional(parsed, "slice", "plan or print job", "multidir slice PLAN_OR_JOB --printer PROFILE -o OUTDIR");
  s.outDir = outputFolder(parsed, "slice", "the G-code and the print job");
  if (!parsed.has("--printer"))
    throw UsageError(kCommand + ": --printer is required: a PrusaSlicer .ini or one of " + shippedProfileList());
  s.printer = parsed.value("--printer", "");
  if (parsed.has("--dialect")) {
    const core::Result<slicing::Dialect> d = slicing::parseDialect(parsed.value("--dialect", ""));
    if (!d) throw UsageError(kCommand + ": --dialect: " + d.error().message);
    s.options.dialect = *d;
  }
  const core::Result<std::vector<std::pair<std::string, std::string>>> settings =
      slicing::parseSettingAssignments(parsed.value("--set", ""));
  if (!settings) throw UsageError(kCommand + ": --set: " + settings.error().message);
  s.options.settings = *settings;
  s.options.fixedDirection = !parsed.has("--no-comparison");
  s.options.slicerExecutable = parsed.value("--slicer", s.options.slicerExecutable);
  s.options.writeIntoOtherFolder = parsed.has("--force");
  return s;
}

// A plan folder, or a print-job folder whose print-job.json names its plan.
std::string planFolderOf(const std::string& input) {
  fs::path path(input);
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) path = path.parent_path();
  if (fs::exists(path / "plan.json", ec)) return path.string();
  const fs::path jobFile = path / "print-job.json";
  if (!fs::exists(jobFile, ec))
    throw FileError(kCommand + ": '" + input + "' holds neither plan.json nor print-job.json; make a plan with "
                    "'multidir decompose MODEL -o DIR'");
  std::ifstream in(jobFile);
  const nlohmann::json job = nlohmann::json::parse(in, nullptr, false);
  if (job.is_discarded() || !job.contains("plan") || !job["plan"].is_string())
    throw FileError(kCommand + ": " + jobFile.string() + ": no \"plan\" field naming the plan folder");
  const std::string plan = job["plan"].get<std::string>();
  for (const fs::path& candidate : {fs::path(plan), path / plan, path.parent_path() / plan})
    if (fs::exists(candidate / "plan.json", ec)) return candidate.string();
  throw FileError(kCommand + ": " + jobFile.string() + " names the plan '" + plan +
                  "', which is not there any more; slice the plan folder itself");
}

void printTable(std::ostream& out, const slicing::SlicedJob& job) {
  out << "Sliced with " << job.engine << " for " << job.profile.name << " (platform: "
      << slicing::platformDriveName(job.profile.platform) << ")\n";
  char line[256];
  if (job.placementMm.norm() > 1e-6) {
    std::snprintf(line, sizeof line, "Part placed X %+.1f, Y %+.1f mm on the platform (where it fits the bed best)\n",
                  job.placementMm.x(), job.placementMm.y());
    out << line;
  }
  std::snprintf(line, sizeof line, "  %4s  %-14s  %10s  %11s  %12s  %11s  %12s  %9s\n", "step", "G-code", "base z mm",
                "1st layer", "print time", "filament m", "filament g", "slice s");
  out << line;
  for (const slicing::SlicedStep& s : job.steps) {
    // The first layer's height above the base plane: the slicer's first_layer_height (layer_height on plastic).
    std::snprintf(line, sizeof line, "  %4d  %-14s  %10.2f  %11.2f  %12s  %11.2f  %12.1f  %9.2f\n", s.index,
                  s.gcodeFile.c_str(), s.baseZMm, s.firstLayerZMm - s.baseZMm,
                  slicing::durationText(s.estimate.printSeconds).c_str(), s.estimate.filamentMm / 1000.0,
                  s.estimate.filamentGrams, s.sliceSeconds);
    out << line;
  }
  double sliceSeconds = 0.0;
  for (const slicing::SlicedStep& s : job.steps) sliceSeconds += s.sliceSeconds;
  std::snprintf(line, sizeof line, "  %4s  %-14s  %10s  %11s  %12s  %11.2f  %12.1f  %9.2f\n", "all",
                job.stitchedFile.empty() ? "-" : job.stitchedFile.c_str(), "", "",
                slicing::durationText(job.total.printSeconds).c_str(), job.total.filamentMm / 1000.0,
                job.total.filamentGrams, sliceSeconds);
  out << line;
  if (job.fixedDirection) {
    std::snprintf(line, sizeof line, "  %-45s  %12s  %11.2f  %12.1f  %9.2f\n",
                  "fixed direction, slicer supports", slicing::durationText(job.fixedDirection->printSeconds).c_str(),
                  job.fixedDirection->filamentMm / 1000.0, job.fixedDirection->filamentGrams,
                  job.fixedDirectionSliceSeconds);
    out << line;
  }
  for (const slicing::TurnPlan& t : job.turns) {
    // Only a rotary platform's turn has one angle; a robot arm's is a tilt and an azimuth (print-job.json).
    std::string angles;
    if (t.twoAxis) {
      // Two firmware axes: each move in the order the program makes it.
      const slicing::TwoAxisPlatform& axes = job.profile.twoAxis;
      for (const slicing::AxisMove& m : t.twoAxis->moves) {
        const std::string& letter = m.axis == slicing::AxisMove::Axis::Tilt ? axes.tilt.letter : axes.rotation.letter;
        std::snprintf(line, sizeof line, "%s %s %.1f -> %.1f", angles.empty() ? "" : ", then", letter.c_str(),
                      m.fromDegrees, m.toDegrees);
        angles += line;
      }
      std::snprintf(line, sizeof line, "  turn after step %d: %s; part and platform sweep to z %.2f mm, nozzle at %.2f mm\n",
                    t.fromStep, angles.empty() ? "the axes stay" : angles.c_str() + 1, t.sweptTopZMm, t.clearanceZMm);
      out << line;
      continue;
    } else if (t.fromDegrees != 0.0 || t.toDegrees != 0.0) {
      std::snprintf(line, sizeof line, " %.1f -> %.1f degrees,", t.fromDegrees, t.toDegrees);
      angles = line;
    }
    std::snprintf(line, sizeof line, "  turn after step %d:%s part sweeps to z %.2f mm, nozzle at %.2f mm\n",
                  t.fromStep, angles.c_str(), t.sweptTopZMm, t.clearanceZMm);
    out << line;
  }
}

}  // namespace

int runSlice(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool helpOnly = false;
  const Settings s = settingsFrom(args, helpOnly);
  if (helpOnly) {
    std::string help = kSliceHelp;
    help.replace(help.find("SHIPPED_PROFILES"), std::string("SHIPPED_PROFILES").size(), shippedProfileList());
    out << help;
    return kExitOk;
  }
  const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(s.printer);
  if (!profile) throw FileError(kCommand + ": --printer: " + profile.error().describe());
  const std::string planDir = planFolderOf(s.input);
  const core::Result<core::LoadedPlan> plan = core::loadPlan(planDir);
  if (!plan) throw FileError(kCommand + ": cannot read the plan in '" + planDir + "': " + plan.error().describe());

  ProgressLine progress(err, isatty(STDERR_FILENO) != 0);
  core::JobContext context([&progress](double fraction, const std::string& phase) { progress.show(fraction, phase); });
  const InterruptScope interrupts;
  std::future<core::Result<slicing::SlicedJob>> running = std::async(
      std::launch::async, [&] { return slicing::slicePlan(*plan, *profile, s.options, s.outDir, context); });
  while (running.wait_for(std::chrono::milliseconds(10)) != std::future_status::ready)
    if (gInterrupted) context.cancel();
  const core::Result<slicing::SlicedJob> sliced = running.get();
  progress.clear();
  if (gInterrupted) {
    err << kCommand << ": interrupted: every slicer was stopped and nothing was written (" << s.outDir
        << " is as it was)\n";
    return kExitInterrupted;
  }
  if (!sliced) {
    err << kCommand << ": " << sliced.error().describe() << "\n";
    return sliced.error().code == core::ErrorCode::Internal ? kExitInternal : kExitBadInput;
  }
  printTable(out, *sliced);
  out << "G-code saved     " << s.outDir << "/step-01.gcode ... step-" << (sliced->steps.size() < 10 ? "0" : "")
      << sliced->steps.size() << ".gcode";
  if (!sliced->stitchedFile.empty()) out << " and " << s.outDir << "/" << sliced->stitchedFile;
  out << "; estimates in " << s.outDir << "/print-job.json\n";
  return kExitOk;
}

}  // namespace multidir::cli
