#pragma once
// The printer link for Klipper through Moonraker's HTTP API (JSON replies; docs/hardware.md, "Moonraker"):
//   POST /server/files/upload (multipart: file, root=gcodes)      upload
//   POST /printer/print/start?filename=NAME                        start
//   POST /printer/print/pause | resume | cancel                    pause, resume, cancel
//   POST /printer/emergency_stop                                   emergency stop (Klipper shuts down)
//   GET  /printer/objects/query?webhooks&print_stats&virtual_sdcard&extruder&heater_bed   status
// Plain HTTP (cpp-httplib, no TLS): use it on the lab's own network or through a tunnel.
#include <memory>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

struct MoonrakerSettings {
  std::string host = "127.0.0.1";  // a host name or IPv4 address
  int port = 7125;                 // Moonraker's default; 80 behind Mainsail's or Fluidd's web server
  std::string apiKey;              // sent as X-Api-Key when not empty (Moonraker's [authorization])
};

// "http://HOST[:PORT]" (PORT 80 when absent), "HOST:PORT" or "HOST" (port 7125). Errors: InvalidParameter
// naming what is wrong (https, a path, a port out of 1..65535).
core::Result<MoonrakerSettings> parseMoonrakerUrl(const std::string& url);

// InvalidParameter for bad settings or options (nothing started).
core::Result<std::unique_ptr<PrinterLink>> makeMoonrakerLink(const MoonrakerSettings& settings,
                                                             const PrinterLinkOptions& options = {});

}  // namespace multidir::hardware
