#pragma once
// Reads OctoPrint's GET /api/job and GET /api/printer replies and maps OctoPrint's states onto
// PrinterJobState (the table is in docs/hardware.md, "OctoPrint").
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "multidir/core/common/result.h"
#include "printer/http_printer_link.h"

namespace multidir::hardware {

struct OctoPrintJobReading {
  std::string stateText;             // "Operational", "Printing", "Paused", "Offline after error", ...
  std::string error;                 // the reply's "error" ("" when absent or empty)
  std::string file;                  // job.file.name ("" when no file is selected)
  std::optional<double> completion;  // progress.completion, percent (none when null)
};

struct OctoPrintPrinterReading {
  bool operational = false;
  bool error = false;  // flags.error or flags.closedOrError with an error
  HeaterReading tool0;
  HeaterReading bed;
};

// Errors: DeviceFault naming `printer` when the reply has no "state" string (not OctoPrint's /api/job).
core::Result<OctoPrintJobReading> readOctoPrintJob(const nlohmann::json& reply, const std::string& printer);
// Errors: DeviceFault naming `printer` when the reply has no state.flags (not OctoPrint's /api/printer).
core::Result<OctoPrintPrinterReading> readOctoPrintPrinter(const nlohmann::json& reply, const std::string& printer);

// OctoPrint reports a finished, a cancelled and an idle printer alike as "Operational" (with the last file
// still selected): a job is complete when its completion reached 100 %, cancelled when the tracker saw it
// active and it ended short of that. Not thread-safe (the link's worker owns it).
class OctoPrintJobTracker {
 public:
  // `printer` is null when /api/printer answered 409 (OctoPrint is not connected to the printer): the
  // heaters are then the last ones read.
  PrinterReading read(const OctoPrintJobReading& job, const OctoPrintPrinterReading* printer);

 private:
  std::string m_activeFile;  // seen printing or paused, its end not seen yet
  std::string m_endedFile;   // the last job seen ending, and how
  PrinterJobState m_ended = PrinterJobState::Unknown;
  HeaterReading m_tool0;
  HeaterReading m_bed;
};

}  // namespace multidir::hardware
