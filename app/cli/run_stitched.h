#pragma once
// `multidir run` for a job whose platform the printer's firmware turns (RunJob::stitched): the printer alone
// prints one program, the stitched job.gcode (or, resumed at a later step, the part of it from there on). What
// this file holds: which program is sent and what it was checked to be, and the check that the printer has the
// axes the program turns. run_command.cpp runs it like any other run (one step, the platform on the printer's
// own axes: firmware_axes_positioner.h).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "multidir/hardware/printer_link.h"
#include "run_job_file.h"
#include "stitched_program.h"

namespace multidir::cli {

struct StitchedRun {
  int from = 1;                         // the job step the program starts at
  int steps = 1;                        // the job's steps
  std::string uploadPath;               // job.gcode, or the resumed program written to a temporary folder
  std::string remoteName;               // as the printer stores it: "job.gcode", "job-from-03.gcode"
  std::string sha256;                   // of the bytes checked: the link refuses a file that no longer has it
  std::size_t bytes = 0;                // the program's size
  StitchedProgramAxes axes;             // the rotary axes it turns
  std::vector<std::size_t> stepBegins;  // the byte where each step from `from` on begins in it
  std::vector<double> estimates;        // the slicer's estimate of each step from `from` on (seconds)
  std::shared_ptr<const std::string> temporaryFolder;  // removed with the last copy ("": none)

  // The job step the printer is in when it has read `progress` (0..1) of the program.
  [[nodiscard]] int stepAt(double progress) const;
};

// Reads the stitched program once, takes its SHA-256, finds the axes it turns and where its steps begin; for
// `from` > 1, writes the resumed program (stitched_program.h) to a temporary folder. Throws FileError naming the
// file and what is wrong (a step marker missing, unreadable).
StitchedRun prepareStitchedRun(const RunJob& job, int from);

// Asks the printer which axes its firmware has and throws std::runtime_error when one the program turns is
// missing, naming it and where to add it; OctoPrint cannot be asked: without `axesConfirmed`
// (--yes-axes-configured) that is refused too, saying why. Returns the log line saying what was checked.
std::string checkPrinterHasTheAxes(hardware::PrinterLink& printer, const StitchedProgramAxes& axes, bool axesConfirmed);

}  // namespace multidir::cli
