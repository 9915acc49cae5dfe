#pragma once
// `multidir simulate --ur MODEL [--port P] [--speed X] [--fault NAME] [--trace FILE]`: a Universal Robots
// controller on loopback (hardware/ur_simulator.h) until Ctrl-C: dashboard on P, secondary interface on P+1,
// real-time interface on P+2 (UR's own 29999, 30002, 30003 when --port is not given).
#include <ostream>

#include "cli_args.h"

namespace multidir::cli {

// Returns an exit code; throws UsageError for command-line mistakes.
int simulateUr(const ParsedArgs& parsed, std::ostream& out, std::ostream& err);

}  // namespace multidir::cli
