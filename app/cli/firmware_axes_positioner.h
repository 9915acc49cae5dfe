#pragma once
// The platform of a job whose printer turns it with its own firmware axes (a stitched program: the turns are
// lines of the program the printer runs), as the print-run sequencer's positioner. It has no motion of its
// own outside that program: it stands at rest, where the program starts, as long as the printer answers, and
// what stops it is what stops the printer (the run cancels the printer's job, or sends its emergency stop, at
// the same time as it asks this positioner to stop, which it confirms at once for that reason).
#include <memory>

#include "multidir/hardware/print_run.h"
#include "multidir/hardware/printer_link.h"

namespace multidir::cli {

// `printer` must outlive the positioner. Moves other than to the rest orientation (rotary 0) are refused.
std::unique_ptr<hardware::Positioner> makeFirmwareAxesPositioner(const hardware::PrinterLink& printer);

}  // namespace multidir::cli
