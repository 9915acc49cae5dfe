#pragma once
// A Moonraker server in front of a simulated Klipper printer (printer_simulator.h), for tests, demos and
// `multidir simulate --printer moonraker`: the endpoints MoonrakerLink uses, with Moonraker's request and
// reply shapes (docs/hardware.md, "Moonraker"), plus GET /printer/info and POST /printer/firmware_restart.
#include "multidir/hardware/printer_simulator.h"

namespace multidir::hardware {

using MoonrakerSimulatorOptions = PrinterSimulatorOptions;

class MoonrakerSimulator : public PrinterSimulator {
 public:
  explicit MoonrakerSimulator(MoonrakerSimulatorOptions options = {});
};

}  // namespace multidir::hardware
