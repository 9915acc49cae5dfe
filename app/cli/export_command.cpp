#include "export_command.h"

#include <cstdio>
#include <filesystem>

#include "cli_args.h"
#include "multidir/core/plan/print_job.h"
#include "number_text.h"

namespace multidir::cli {

const char* const kExportHelp =
    "Usage: multidir export PLAN_DIR -o OUTDIR [options]\n"
    "\n"
    "Turns a plan folder written by 'multidir decompose' into what the printer needs: one mesh per region in\n"
    "printing order (step-01-region.stl, ...), the supports printed with each region (step-01-supports.stl,\n"
    "...), and print-job.json with the machine angles and start height of every step (docs/plan-format.md).\n"
    "It prints a table of the steps.\n"
    "\n"
    "Options:\n"
    "  -o OUTDIR              folder for the print job (created if missing; required)\n"
    "  --format FORMAT        mesh files: stl (binary), obj, ply or off (default: stl)\n"
    "  --frame FRAME          machine: each region as the machine holds it while printing it, up turned to +Z\n"
    "                         and the platform centre at the origin, so its base lies flat at its lowest z;\n"
    "                         model: as in the model (default: machine)\n"
    "  --no-supports          leave the supports out\n"
    "  -h, --help             show this help\n"
    "\n"
    "Exit codes: 0 ok, 1 the plan cannot be read or the job written, 2 usage error.\n";

namespace {

namespace core = multidir::core;
namespace fs = std::filesystem;

const std::string kCommand = "multidir export";

struct Settings {
  std::string planDir;
  std::string outDir;
  core::PrintJobOptions options;
};

Settings settingsFrom(const std::vector<std::string>& args, bool& helpOnly) {
  const ParsedArgs parsed = parseArgs(args, {"-o", "--format", "--frame"}, {"--help", "--no-supports"}, "export");
  helpOnly = parsed.has("--help");
  Settings s;
  if (helpOnly) return s;
  s.planDir = onlyPositional(parsed, "export", "plan", "multidir export PLAN_DIR -o OUTDIR");
  s.outDir = outputFolder(parsed, "export", "the print job");
  s.options.format = parsed.value("--format", s.options.format);
  if (const core::Status valid = core::validate(s.options); !valid)
    throw UsageError(kCommand + ": --format: " + valid.error().message);
  if (parsed.has("--frame")) {
    const core::Result<core::PrintJobOptions::Frame> frame = core::parsePrintJobFrame(parsed.value("--frame", ""));
    if (!frame) throw UsageError(kCommand + ": --frame: " + frame.error().message);
    s.options.frame = *frame;
  }
  s.options.supports = !parsed.has("--no-supports");
  return s;
}

void printTable(std::ostream& out, const core::PrintJob& job) {
  out << "Print job steps (" << job.steps.size() << " regions; " << core::machineKindName(job.machine.kind) << ", "
      << core::printJobFrameName(job.options.frame) << " frame)\n";
  char header[200];
  std::snprintf(header, sizeof header, "  %3s  %-22s  %-24s  %-28s  %12s\n", "#", "region file", "supports file",
                "machine angles (degrees)", "start z mm");
  out << header;
  for (const core::PrintJobStep& step : job.steps) {
    char row[240];
    std::snprintf(row, sizeof row, "  %3d  %-22s  %-24s  %-28s  %12.2f\n", step.index, step.regionFile.c_str(),
                  step.supportsFile.empty() ? "-" : step.supportsFile.c_str(),
                  machineAnglesText(job.machine.kind, step.angles).c_str(), step.lowestHeightMm);
    out << row;
  }
}

}  // namespace

int runExport(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool helpOnly = false;
  // Every option is checked before the plan is read, so a typo costs no loading time.
  const Settings s = settingsFrom(args, helpOnly);
  if (helpOnly) {
    out << kExportHelp;
    return kExitOk;
  }
  std::error_code ec;
  if (!fs::exists(s.planDir, ec))
    throw FileError(kCommand + ": there is no plan folder '" + s.planDir +
                    "'; write one with 'multidir decompose MODEL -o " + s.planDir + "'");
  const core::Result<core::LoadedPlan> plan = core::loadPlan(s.planDir);
  if (!plan) throw FileError(kCommand + ": cannot read the plan in '" + s.planDir + "': " + plan.error().describe());

  const core::Result<core::PrintJob> job = core::buildPrintJob(*plan, s.options);
  if (!job) {
    err << kCommand << ": " << s.planDir << ": " << job.error().describe() << "\n";
    return job.error().code == core::ErrorCode::Internal ? kExitInternal : kExitBadInput;
  }
  printTable(out, *job);
  if (const core::Status written = core::writePrintJob(*job, s.outDir); !written)
    throw FileError(kCommand + ": cannot write the print job: " + written.error().describe());
  int supportFiles = 0;
  for (const core::PrintJobStep& step : job->steps) supportFiles += step.supportsFile.empty() ? 0 : 1;
  out << "Print job saved   " << s.outDir << "/print-job.json, " << job->steps.size() << " region files";
  if (supportFiles > 0) out << " and " << supportFiles << " support files";
  out << " (" << s.options.format << ")\n";
  return kExitOk;
}

}  // namespace multidir::cli
