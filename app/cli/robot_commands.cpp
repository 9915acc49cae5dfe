#include "robot_commands.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "cli_args.h"
#include "multidir/assembly/picture.h"
#include "multidir/core/common/atomic_file.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/reach_map.h"
#include "multidir/robot/robot_program.h"

namespace multidir::cli {

const char* const kCellHelp =
    "Usage: multidir cell check CELL\n"
    "       multidir cell reach PLAN --cell CELL [-o MAP.ply] [--grid MM]\n"
    "\n"
    "cell reach: where to put the extruder. Nozzle positions are sampled on a grid (--grid, default 100 mm) over\n"
    "the arm's workspace, the nozzle axis as the cell has it, and each is scored by the share of the plan's\n"
    "needed platform poses (every step's region and supports: the corners and centre of their bounding box, at\n"
    "the step's best rotation about the nozzle axis and arm configuration) reachable within the joint limits\n"
    "with the cell's reach and wrist margins. Prints the best position and the cell's own; -o writes the map as\n"
    "a PLY point cloud with the scores (docs/robot-cell.md, \"Reach map\").\n"
    "\n"
    "cell check:\n"
    "Checks a robot cell file (docs/robot-cell.md, \"The cell file\"): a known robot model, the nozzle axis a\n"
    "unit vector, joint limits ordered within +-360 deg, home within the limits, reachable and holding the\n"
    "platform above the table, the flange-to-platform transform sane, collision bodies well formed, the table\n"
    "below the nozzle tip, margins and motion parameters in range. Every problem is listed with its key and\n"
    "what to do.\n"
    "\n"
    "Exit codes: 0 the cell is sound, 1 the file cannot be read or has problems, 2 usage error.\n";

const char* const kRobotProgramHelp =
    "Usage: multidir robot-program JOB --cell CELL -o OUT [options]\n"
    "\n"
    "Turns a job sliced with the cell's profile (multidir slice PLAN --printer ur5-cell-0.8 -o JOB) into the\n"
    "robot cell's URScript programs, one per step (docs/robot-cell.md, \"Programs\"): every G-code move becomes a\n"
    "platform pose that puts the fixed nozzle tip at the move's point with the step's printing direction along\n"
    "the nozzle axis. Checked before anything is written, each refusal naming the step, the G-code line and the\n"
    "reason: reach and joint limits, one arm configuration per step with no joint jump (wrist flip), singularity\n"
    "margins, joint speeds at the G-code's feeds (a move too fast is slowed and counted), collisions of the\n"
    "platform and part with the extruder's bodies and the table, and the joint moves from home to each step and\n"
    "back (links, platform and part along the joint path; via points where the straight joint move is blocked).\n"
    "\n"
    "Writes OUT/robot-job.json, OUT/cell.json (the cell used), OUT/step-NN.script and OUT/summary.txt; a step\n"
    "above the cell's maxProgramBytes (default 100000) is split at travel moves into complete programs\n"
    "OUT/step-NN-part-MMM.script that the run sends one after another.\n"
    "\n"
    "Options:\n"
    "  --cell CELL            the cell file (required; resources/cells/ur5-fixed-extruder.json is the paper's)\n"
    "  -o OUT                 the output folder (required; replaced as a whole once complete)\n"
    "  --rotation-step DEG    sampling of the free rotation about the nozzle axis per step (default 10)\n"
    "  --sample-mm MM         moves are checked at points this far apart (default 5)\n"
    "  --no-via-points        only straight joint moves between home and the steps: a blocked one is refused\n"
    "  -h, --help             show this help\n"
    "\n"
    "Exit codes: 0 ok, 1 a file cannot be read or written, the cell has problems or the job cannot run on it,\n"
    "2 usage error.\n";

namespace {

int cellCheck(const std::vector<std::string>& args, std::ostream& out) {
  const ParsedArgs parsed = parseArgs(args, {}, {"-h", "--help"}, "multidir cell check");
  if (parsed.has("-h") || parsed.has("--help")) {
    out << kCellHelp;
    return kExitOk;
  }
  const std::string path = onlyPositional(parsed, "multidir cell check", "cell file", "multidir cell check CELL");
  const auto cell = robot::parseCell(path);
  if (!cell) throw FileError("multidir cell check: " + cell.error().describe());
  const auto problems = robot::checkCell(cell.value());
  if (!problems.empty()) {
    std::string message = "multidir cell check: " + path + " has " + std::to_string(problems.size()) + " problem(s):";
    for (const auto& p : problems) message += "\n  " + p.key + ": " + p.message;
    throw FileError(message);
  }
  const robot::Cell& c = cell.value();
  out << "Cell " << path << ": sound\n";
  out << "  robot        " << c.arm.name << (c.name.empty() ? "" : " (" + c.name + ")") << "\n";
  out << std::fixed << std::setprecision(1);
  out << "  nozzle tip   (" << c.nozzleTipMm.x() << ", " << c.nozzleTipMm.y() << ", " << c.nozzleTipMm.z()
      << ") mm, axis (" << std::setprecision(3) << c.nozzleAxis.x() << ", " << c.nozzleAxis.y() << ", "
      << c.nozzleAxis.z() << ")\n"
      << std::setprecision(1);
  out << "  bodies       " << c.boxes.size() << " box(es), " << c.cylinders.size() << " cylinder(s); table at z "
      << c.tableZMm << " mm\n";
  return kExitOk;
}

int cellReach(const std::vector<std::string>& args, std::ostream& out) {
  const std::string command = "multidir cell reach";
  const ParsedArgs parsed = parseArgs(args, {"--cell", "-o", "--grid"}, {"-h", "--help"}, command);
  if (parsed.has("-h") || parsed.has("--help")) {
    out << kCellHelp;
    return kExitOk;
  }
  const std::string planPath = onlyPositional(parsed, command, "plan", "multidir cell reach PLAN --cell CELL");
  if (!parsed.has("--cell")) throw UsageError(command + ": --cell CELL is required (the robot cell file)");
  robot::ReachMapOptions options;
  if (parsed.has("--grid")) {
    options.gridMm = parseNumber(parsed.value("--grid", ""), "--grid");
    if (!(options.gridMm >= 10.0 && options.gridMm <= 500.0)) throw UsageError(command + ": --grid must be from 10 to 500 mm");
  }
  const auto cell = robot::loadCell(parsed.value("--cell", ""));
  if (!cell) throw FileError(command + ": " + cell.error().describe());
  const auto plan = core::loadPlan(planPath);
  if (!plan) throw FileError(command + ": " + plan.error().describe());
  const auto steps = robot::reachStepsOfPlan(plan.value());
  if (!steps) throw FileError(command + ": " + steps.error().describe());
  const auto map = robot::reachMap(steps.value(), cell.value(), options, core::JobContext());
  if (!map) throw FileError(command + ": " + map.error().describe());
  const robot::ReachPoint own = robot::reachScore(steps.value(), cell.value(), cell->nozzleTipMm, options);
  out << std::fixed << std::setprecision(1);
  out << "Reach map of " << planPath << " (" << steps->size() << " steps) for a " << cell->arm.name << ": "
      << map->points.size() << " nozzle positions every " << options.gridMm << " mm\n";
  out << "  best position   (" << map->best.nozzleTipMm.x() << ", " << map->best.nozzleTipMm.y() << ", "
      << map->best.nozzleTipMm.z() << ") mm: " << 100.0 * map->best.score << " % of the needed poses reachable, least reach margin "
      << map->best.leastMarginMm << " mm\n";
  out << "  the cell's own  (" << own.nozzleTipMm.x() << ", " << own.nozzleTipMm.y() << ", " << own.nozzleTipMm.z()
      << ") mm: " << 100.0 * own.score << " %, least reach margin " << own.leastMarginMm << " mm\n";
  int full = 0;
  for (const auto& p : map->points) full += p.score >= 1.0 ? 1 : 0;
  out << "  positions reaching every pose: " << full << "\n";
  if (parsed.has("-o")) {
    const auto written = robot::writeReachPly(map.value(), parsed.value("-o", ""));
    if (!written) throw FileError(command + ": " + written.error().describe());
    out << "  map saved in " << parsed.value("-o", "") << "\n";
    // Beside the PLY: the slice through the best position as a PNG (docs/robot-cell.md, "Reach map").
    const robot::ReachSlice slice = robot::reachSlice(map.value(), options.gridMm);
    assembly::Image image;
    image.width = slice.width;
    image.height = slice.height;
    image.rgb = slice.rgb;
    const std::vector<std::uint8_t> png = assembly::encodePng(image);
    const std::string pngPath = std::filesystem::path(parsed.value("-o", "")).replace_extension(".png").string();
    const auto pictured = core::writeFileAtomically(pngPath, pngPath, [&](std::ostream& stream) -> core::Status {
      stream.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
      return core::Done{};
    });
    if (!pictured) throw FileError(command + ": " + pictured.error().describe());
    out << "  slice at z " << slice.zMm << " mm (through the best position, seen from above) saved in " << pngPath
        << "\n";
  }
  return kExitOk;
}

}  // namespace

int runCell(const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
  if (args.empty() || args[0] == "-h" || args[0] == "--help") {
    out << kCellHelp;
    return args.empty() ? kExitUsage : kExitOk;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "check") return cellCheck(rest, out);
  if (args[0] == "reach") return cellReach(rest, out);
  throw UsageError("multidir cell: unknown subcommand '" + args[0] + "'. Run 'multidir help cell'.");
}

int runRobotProgram(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const std::string command = "multidir robot-program";
  const ParsedArgs parsed =
      parseArgs(args, {"--cell", "-o", "--rotation-step", "--sample-mm"}, {"-h", "--help", "--no-via-points"}, command);
  if (parsed.has("-h") || parsed.has("--help")) {
    out << kRobotProgramHelp;
    return kExitOk;
  }
  const std::string job = onlyPositional(parsed, command, "job folder", "multidir robot-program JOB --cell CELL -o OUT");
  if (!parsed.has("--cell")) throw UsageError(command + ": --cell CELL is required (the robot cell file)");
  const std::string cellPath = parsed.value("--cell", "");
  const std::string outDir = outputFolder(parsed, command, "the robot programs");
  robot::RobotProgramOptions options;
  if (parsed.has("--rotation-step")) {
    options.rotationStepDegrees = parseNumber(parsed.value("--rotation-step", ""), "--rotation-step");
    if (!(options.rotationStepDegrees >= 1.0 && options.rotationStepDegrees <= 180.0))
      throw UsageError(command + ": --rotation-step must be from 1 to 180 degrees");
  }
  options.viaPoints = !parsed.has("--no-via-points");
  if (parsed.has("--sample-mm")) {
    options.sampleMm = parseNumber(parsed.value("--sample-mm", ""), "--sample-mm");
    if (!(options.sampleMm >= 0.1 && options.sampleMm <= 100.0))
      throw UsageError(command + ": --sample-mm must be from 0.1 to 100 mm");
  }
  checkOutputFolder(outDir, command);
  const auto cell = robot::loadCell(cellPath);
  if (!cell) throw FileError(command + ": " + cell.error().describe());
  core::JobContext context;
  const auto planned = robot::planRobotJob(job, cell.value(), options, context);
  if (!planned) throw FileError(command + ": " + planned.error().describe());
  const auto written = robot::writeRobotJob(planned.value(), cellPath, outDir);
  if (!written) throw FileError(command + ": " + written.error().describe());
  out << robot::robotJobSummary(planned.value());
  std::ostringstream timing;
  int moves = 0;
  for (const auto& s : planned->steps) moves += s.moves;
  timing << std::fixed << std::setprecision(2) << "Converted " << moves << " moves in " << planned->conversionSeconds
         << " s; programs saved in " << outDir << "\n";
  out << timing.str();
  (void)err;
  return kExitOk;
}

}  // namespace multidir::cli
