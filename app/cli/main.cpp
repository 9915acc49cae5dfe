// multidir: the command line. Dispatches subcommands and turns every failure into an exit code.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "apart_command.h"
#include "audit_command.h"
#include "batch_command.h"
#include "cli_args.h"
#include "decompose_command.h"
#include "export_command.h"
#include "info_command.h"
#include "report_command.h"
#include "robot_commands.h"
#include "run_command.h"
#include "simulate_command.h"
#include "slice_command.h"

namespace {

using namespace multidir::cli;

const char* const kUsage =
    "Usage: multidir COMMAND [ARGUMENTS]\n"
    "\n"
    "Multi-directional 3D printing: analyse a model and plan its printing directions.\n"
    "\n"
    "Commands:\n"
    "  info MODEL                  statistics, load checks and overhang area of a model\n"
    "  decompose MODEL -o OUTDIR   cut a model into regions with printing directions; write the plan\n"
    "  batch INPUT -o OUTDIR       decompose every model of a folder or list file: one plan folder each and\n"
    "                              one results table; --shard I/N, resumable\n"
    "  export PLAN_DIR -o OUTDIR   the print job of a plan: one mesh per step, posed as the machine holds it\n"
    "  slice PLAN_OR_JOB --printer PROFILE -o OUTDIR   G-code for every step (PrusaSlicer), checked\n"
    "  apart PLAN_OR_MODEL -o OUTDIR [--printer PROFILE]   print apart on an ordinary printer: parts on their\n"
    "                              cut faces, joined by dowels; STL, 3MF and G-code per plate\n"
    "  report MODEL...             support volume printed along up against the multi-directional plan\n"
    "  simulate [--port PORT]      run the Modbus simulator of the rotary platform and the robot arm\n"
    "  simulate --printer moonraker|marlin   printer simulator: Klipper behind Moonraker, or Marlin on a pty\n"
    "  simulate --ur MODEL         a Universal Robots controller (dashboard, secondary, real-time interfaces)\n"
    "  audit JOB                   replay a sliced job's G-code through the machine and check it\n"
    "  run JOB --printer URL --platform HOST:PORT --machine PROFILE.json   print a sliced job: platform and\n"
    "                              printer in the loop\n"
    "  run OUT --robot HOST[:PORT] run a robot cell's job on a UR controller\n"
    "  cell check CELL             check a robot cell file (a UR arm carrying the platform, a fixed extruder)\n"
    "  cell reach PLAN --cell CELL   where to put the extruder: nozzle positions scored by the plan's reach\n"
    "  robot-program JOB --cell CELL -o OUT   the robot cell's URScript programs of a job sliced with the\n"
    "                              cell's profile, every pose checked\n"
    "  help [COMMAND]              show this help, or a command's help\n"
    "\n"
    "Options:\n"
    "  -h, --help                  show this help\n"
    "  --version                   show the version\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input file, 2 usage error, 3 internal error, 4 a run that did not complete,\n"
    "5 an audit that found a violation.\n";

int help(const std::vector<std::string>& args) {
  if (args.empty()) {
    std::cout << kUsage;
    return kExitOk;
  }
  if (args.size() > 1) throw UsageError("multidir help: one command at a time");
  if (args[0] == "info") {
    std::cout << kInfoHelp;
    return kExitOk;
  }
  if (args[0] == "decompose") {
    std::cout << kDecomposeHelp;
    return kExitOk;
  }
  if (args[0] == "batch") {
    std::cout << kBatchHelp;
    return kExitOk;
  }
  if (args[0] == "export") {
    std::cout << kExportHelp;
    return kExitOk;
  }
  if (args[0] == "apart") {
    std::cout << kApartHelp;
    return kExitOk;
  }
  if (args[0] == "slice") {
    std::cout << kSliceHelp;
    return kExitOk;
  }
  if (args[0] == "report") {
    std::cout << kReportHelp;
    return kExitOk;
  }
  if (args[0] == "simulate") {
    std::cout << kSimulateHelp;
    return kExitOk;
  }
  if (args[0] == "audit") {
    std::cout << kAuditHelp;
    return kExitOk;
  }
  if (args[0] == "run") {
    std::cout << kRunHelp;
    return kExitOk;
  }
  if (args[0] == "cell") {
    std::cout << kCellHelp;
    return kExitOk;
  }
  if (args[0] == "robot-program") {
    std::cout << kRobotProgramHelp;
    return kExitOk;
  }
  throw UsageError("multidir help: unknown command '" + args[0] + "'. Run 'multidir --help' for the list.");
}

int run(const std::vector<std::string>& args) {
  if (args.empty()) {
    std::cerr << kUsage;
    return kExitUsage;
  }
  const std::string& command = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "-h" || command == "--help") return help({});
  if (command == "--version") {
    std::cout << "multidir " << MULTIDIR_VERSION << "\n";
    return kExitOk;
  }
  if (command == "help") return help(rest);
  if (command == "info") return runInfo(rest, std::cout, std::cerr);
  if (command == "decompose") return runDecompose(rest, std::cout, std::cerr);
  if (command == "batch") return runBatch(rest, std::cout, std::cerr);
  if (command == "simulate") return runSimulate(rest, std::cout, std::cerr);
  if (command == "report") return runReport(rest, std::cout, std::cerr);
  if (command == "export") return runExport(rest, std::cout, std::cerr);
  if (command == "slice") return runSlice(rest, std::cout, std::cerr);
  if (command == "apart") return runApart(rest, std::cout, std::cerr);
  if (command == "audit") return runAudit(rest, std::cout, std::cerr);
  if (command == "run") return runRun(rest, std::cout, std::cerr);
  if (command == "cell") return runCell(rest, std::cout, std::cerr);
  if (command == "robot-program") return runRobotProgram(rest, std::cout, std::cerr);
  if (!command.empty() && command[0] == '-')
    throw UsageError("multidir: unknown option '" + command + "'. Run 'multidir --help' for the list.");
  throw UsageError("multidir: unknown command '" + command + "'. Run 'multidir --help' for the list.");
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    return run(args);
  } catch (const UsageError& e) {
    std::cerr << e.what() << "\n";
    return kExitUsage;
  } catch (const FileError& e) {
    std::cerr << e.what() << "\n";
    return kExitBadInput;
  }
#ifndef MULTIDIR_TESTING_DISABLE_CATCH_ALL
  // Tests build with the catch-all off, so that an unexpected exception reaches them as it is.
  catch (const std::exception& e) {
    std::cerr << "multidir: internal error (" << e.what() << "); please report it with the command line\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "multidir: internal error; please report it with the command line that caused it\n";
    return kExitInternal;
  }
#endif
}
