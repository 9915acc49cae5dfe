#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

const char* printerJobStateName(PrinterJobState state) {
  switch (state) {
    case PrinterJobState::Unknown:
      return "unknown";
    case PrinterJobState::Standby:
      return "standby";
    case PrinterJobState::Printing:
      return "printing";
    case PrinterJobState::Paused:
      return "paused";
    case PrinterJobState::Complete:
      return "complete";
    case PrinterJobState::Cancelled:
      return "cancelled";
    case PrinterJobState::Error:
      return "error";
  }
  return "?";
}

std::future<core::Result<FirmwareAxes>> PrinterLink::readFirmwareAxes() {
  std::promise<core::Result<FirmwareAxes>> promise;
  promise.set_value(core::Error{core::ErrorCode::InvalidParameter,
                                "this printer's link cannot ask the firmware which axes it has (OctoPrint relays no "
                                "firmware reply to its API clients)",
                                name()});
  return promise.get_future();
}

std::future<core::Status> PrinterLink::restartFirmware() {
  std::promise<core::Status> promise;
  promise.set_value(core::Error{core::ErrorCode::InvalidParameter,
                                "this printer cannot be restarted over its link (Marlin halted by M112 answers no "
                                "command): press the printer's reset button or switch it off and on",
                                name()});
  return promise.get_future();
}

core::Status validate(const PrinterLinkOptions& o) {
  const auto bad = [](const std::string& field, const std::string& rule) {
    return core::Error{core::ErrorCode::InvalidParameter, field + " " + rule, field};
  };
  if (o.pollInterval.count() < 1 || o.pollInterval.count() > 60000)
    return bad("printer poll interval", "must be between 1 and 60000 ms");
  if (o.requestTimeout.count() < 1 || o.requestTimeout.count() > 600000)
    return bad("printer request timeout", "must be between 1 and 600000 ms");
  if (o.uploadTimeout < o.requestTimeout || o.uploadTimeout.count() > 3600000)
    return bad("printer upload timeout", "must be at least the request timeout and at most 3600000 ms");
  if (o.linkLostAfter.count() < 1 || o.linkLostAfter.count() > 600000)
    return bad("printer link-lost time", "must be between 1 and 600000 ms");
  if (o.stopRetryInterval.count() < 1 || o.stopRetryInterval.count() > 10000)
    return bad("emergency stop retry interval", "must be between 1 and 10000 ms");
  return core::Done{};
}

}  // namespace multidir::hardware
