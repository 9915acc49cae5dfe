#pragma once
// Reads the reply of Moonraker's /printer/objects/query (the "result" object: {"eventtime", "status": {...}}).
#include <nlohmann/json.hpp>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"
#include "printer/http_printer_link.h"

namespace multidir::hardware {

// "standby" ... "error" -> the state; anything else is Unknown.
PrinterJobState parsePrinterJobState(const std::string& text);

// A print_stats.state outside parsePrinterJobState's words reads Unknown, its message naming the word.
// Errors: DeviceFault naming `printer` when the reply has no status.print_stats.state (not Klipper's Moonraker).
core::Result<PrinterReading> readMoonrakerStatus(const nlohmann::json& result, const std::string& printer);

}  // namespace multidir::hardware
