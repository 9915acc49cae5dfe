#pragma once
// One printer link from the address the operator types, so the studio and the command line need not know
// the protocols: the URL's scheme picks the link.
//   http://HOST[:PORT], HOST:PORT, HOST     Moonraker (Klipper), moonraker_link.h
// Other protocols join this switch with their own schemes.
#include <memory>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::hardware {

// The link for `url` (not connected yet); `apiKey` is sent when not empty. Errors: InvalidParameter naming
// what is wrong with the address (an unknown scheme lists the known ones) or with the options.
core::Result<std::unique_ptr<PrinterLink>> makePrinterLinkFromUrl(const std::string& url, const std::string& apiKey,
                                                                  const PrinterLinkOptions& options = {});

}  // namespace multidir::hardware
