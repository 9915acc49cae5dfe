#pragma once
// The printer link for OctoPrint's REST API (JSON; docs/hardware.md, "OctoPrint"):
//   POST /api/files/local (multipart: file, select=false, print=false)        upload
//   POST /api/files/local/NAME {"command": "select", "print": true}           start
//   POST /api/job {"command": "pause", "action": "pause" | "resume"}          pause, resume
//   POST /api/job {"command": "cancel"}                                       cancel
//   POST /api/printer/command {"commands": ["M112"]}                          emergency stop (OctoPrint has no
//        endpoint of its own: it sends M112 to the firmware and then closes its serial connection)
//   GET  /api/job, GET /api/printer?exclude=sd                                 status (409 from /api/printer:
//        OctoPrint is not connected to the printer; read as such, not as a lost link)
// Every request carries the API key in X-Api-Key. Plain HTTP (cpp-httplib, no TLS): use it on the lab's own
// network or through a tunnel.
#include <memory>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

struct OctoPrintSettings {
  std::string host = "127.0.0.1";  // a host name or IPv4 address
  int port = 80;                   // OctoPi's web server; OctoPrint's own development server listens on 5000
  std::string apiKey;              // required: a user's or an application's key from OctoPrint's settings
};

// "octoprint://HOST[:PORT]", "http://HOST[:PORT]", "HOST:PORT" or "HOST" (port 80 when absent). Errors:
// InvalidParameter naming what is wrong (https, a path, a port out of 1..65535).
core::Result<OctoPrintSettings> parseOctoPrintUrl(const std::string& url);

// InvalidParameter for bad settings (an empty API key says where OctoPrint shows one) or options (nothing
// started).
core::Result<std::unique_ptr<PrinterLink>> makeOctoPrintLink(const OctoPrintSettings& settings,
                                                             const PrinterLinkOptions& options = {});

}  // namespace multidir::hardware
