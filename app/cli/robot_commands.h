#pragma once
// The robot cell's commands (docs/robot-cell.md): `multidir cell check CELL` validates a cell file;
// `multidir robot-program JOB --cell CELL -o OUT` turns a job sliced with the cell's profile into URScript.
#include <ostream>
#include <string>
#include <vector>

namespace multidir::cli {

extern const char* const kCellHelp;
extern const char* const kRobotProgramHelp;

// Run the commands on the arguments after "cell" / "robot-program". Return an exit code (cli_args.h); throw
// UsageError for command-line mistakes and FileError for a cell or job that cannot be read, a cell with
// problems, a job the cell cannot run, or an output folder that cannot be written.
int runCell(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int runRobotProgram(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli
