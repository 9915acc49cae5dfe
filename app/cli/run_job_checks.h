#pragma once
// Everything `multidir run` checks before the first move, for the whole job at once: the job's machine limits
// describe the plan, not the platform, so every step's angles are checked against the platform's own machine
// profile (--machine), and every step's G-code is checked again by the checks `multidir slice` ran
// (step_recheck.h), on the files as they are now. A job that fails is refused before anything moves, with one
// message naming the file, the field and the allowed range.
#include <string>
#include <vector>

#include "multidir/core/search/machine.h"
#include "multidir/slicing/printer_profile.h"
#include "run_job_file.h"

namespace multidir::cli {

// The machine profile at `path` (--machine): the connected platform's limits. Throws FileError naming the
// option, the file and the field.
core::MachineSpec loadPlatformProfile(const std::string& path);

// The printer profile the G-code is checked against: `option` (--printer-profile NAME|FILE) when given, else
// the one the job was sliced with (slicing.printer.profile; a relative path is also looked for beside the
// job). Throws FileError saying which to give.
slicing::PrinterProfile loadRunPrinterProfile(const RunJob& job, const std::string& option);

// Throws FileError at the first step the platform (`platform`, read from `platformSource`, "--machine
// lab.json") cannot take or whose G-code fails the slicer's checks against `printer`; names the job file, the
// field and the allowed range (or the G-code file, step, line and reason). Returns, for each step of
// `job.steps`, the SHA-256 of the G-code bytes it checked (content_digest.h): the run gives it to the printer
// link, which refuses a file that no longer has it, so what is printed is what was checked.
[[nodiscard]] std::vector<std::string> checkRunJob(const RunJob& job, const core::MachineSpec& platform, const std::string& platformSource,
                 const slicing::PrinterProfile& printer);

}  // namespace multidir::cli
