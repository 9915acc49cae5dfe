#include "multidir/slicing/step_recheck.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "multidir/slicing/gcode_program.h"

namespace multidir::slicing {

StepBounds stepBoundsFor(const PrinterProfile& profile, double retractRestartExtraMm, int step, double baseZMm) {
  StepBounds b;
  b.step = step;
  b.baseZMm = baseZMm;
  b.bedMin = profile.bedMin();
  b.bedMax = profile.bedMax();
  b.maxZMm = profile.maxPrintHeightMm;
  b.retractToleranceMm = 0.01 + std::max(0.0, -retractRestartExtraMm);
  return b;
}

namespace {

// The profile's retract_restart_extra (first extruder), 0 when it has none: as `slice` reads it.
double retractRestartExtra(const PrinterProfile& profile) {
  const auto found = profile.settings.find("retract_restart_extra");
  if (found == profile.settings.end()) return 0.0;
  char* end = nullptr;
  const double value = std::strtod(found->second.c_str(), &end);
  return end == found->second.c_str() || !std::isfinite(value) ? 0.0 : value;
}

}  // namespace

core::Status recheckStepPrograms(const std::vector<StepProgramText>& programs, const PrinterProfile& profile) {
  const double restartExtra = retractRestartExtra(profile);
  FilamentState filament;
  for (const StepProgramText& p : programs) {
    const core::Result<GcodeProgram> program = parseGcode(p.text, profile.rotaryAxis, p.fileName);
    if (!program) return program.error();
    const StepBounds bounds = stepBoundsFor(profile, restartExtra, p.step, p.baseZMm);
    const core::Result<StepTotals> totals =
        checkStepProgram(*program, bounds, p.fileName, p.endClearanceZMm ? &*p.endClearanceZMm : nullptr, filament);
    if (!totals) return totals.error();
    filament = totals->filamentAtEnd;
  }
  return core::Done{};
}

}  // namespace multidir::slicing
