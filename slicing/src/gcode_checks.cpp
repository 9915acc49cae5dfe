#include "multidir/slicing/gcode_checks.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;

std::string mm(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

Error refusal(const std::string& fileName, int step, int line, const std::string& reason) {
  return Error{ErrorCode::CheckFailed,
               "step " + std::to_string(step) + ", line " + std::to_string(line) + ": " + reason +
                   "; the G-code was refused",
               fileName};
}

// Inside the printer: XY on the bed, z from the bed to the printer's height.
bool insideVolume(const Eigen::Vector3d& p, const StepBounds& b, std::string& why) {
  const double tol = b.toleranceMm;
  if (p.x() < b.bedMin.x() - tol || p.x() > b.bedMax.x() + tol || p.y() < b.bedMin.y() - tol ||
      p.y() > b.bedMax.y() + tol) {
    why = "extrusion at X " + mm(p.x()) + " Y " + mm(p.y()) + " outside the printer's bed (X " + mm(b.bedMin.x()) +
          " to " + mm(b.bedMax.x()) + ", Y " + mm(b.bedMin.y()) + " to " + mm(b.bedMax.y()) + ")";
    return false;
  }
  if (p.z() > b.maxZMm + tol) {
    why = "extrusion at z " + mm(p.z()) + " mm above the printer's height (" + mm(b.maxZMm) + " mm)";
    return false;
  }
  if (p.z() < -tol) {
    why = "extrusion at z " + mm(p.z()) + " mm below the bed (z 0)";
    return false;
  }
  return true;
}

// Checks one extrusion of `step` (0: a start or end sequence) and adds it to `totals`.
core::Status checkExtrusion(const GcodeMove& move, const StepBounds& bounds, const std::string& fileName,
                            StepTotals& totals) {
  std::string why;
  for (const Eigen::Vector3d& p : {move.from, move.to})
    if (!insideVolume(p, bounds, why)) return refusal(fileName, bounds.step, move.line, why);
  if (move.step == 0) return core::Done{};  // the purge of a start sequence stands on the bed
  const double z = std::min(move.from.z(), move.to.z());
  if (z < bounds.baseZMm - bounds.toleranceMm)
    return refusal(fileName, bounds.step, move.line,
                   "extrusion at z " + mm(z) + " mm below the step's base plane (z " + mm(bounds.baseZMm) + " mm)");
  if (totals.extrusions == 0) {
    totals.lowestZMm = z;
    totals.highestZMm = std::max(move.from.z(), move.to.z());
  }
  totals.lowestZMm = std::min(totals.lowestZMm, z);
  totals.highestZMm = std::max(totals.highestZMm, std::max(move.from.z(), move.to.z()));
  ++totals.extrusions;
  totals.filamentMm += move.filamentMm;
  return core::Done{};
}

// Refuses an extruding `move` made while the filament is drawn back, then advances the state past it.
core::Status checkPrimed(FilamentState& filament, const GcodeMove& move, int step, double toleranceMm,
                         const std::string& fileName) {
  if (move.extrudes() && filament.retracted(toleranceMm)) {
    const std::string how = filament.firmwareRetracted
                                ? std::string("retracted by the firmware (G10 without G11)")
                                : "retracted by " + mm(filament.retractedMm) + " mm";
    return refusal(fileName, step, move.line,
                   "extrusion with the filament " + how +
                       ": the line would start without plastic; unretract (prime) before the first extrusion");
  }
  advance(filament, move);
  return core::Done{};
}

// Refuses any move (travel too) that takes the nozzle below the bed: it would press into the bed or the part.
core::Status checkAboveBed(const GcodeMove& move, int step, double toleranceMm, const std::string& fileName) {
  if (move.to.z() >= -toleranceMm) return core::Done{};
  return refusal(fileName, step, move.line,
                 "a move to z " + mm(move.to.z()) + " mm, below the bed (z 0): the nozzle would press into the bed");
}

}  // namespace

void advance(FilamentState& state, const GcodeMove& move) {
  switch (move.firmwareRetraction) {
    case GcodeMove::FirmwareRetraction::Retract:
      state.firmwareRetracted = true;
      return;
    case GcodeMove::FirmwareRetraction::Unretract:
      state.firmwareRetracted = false;
      return;
    case GcodeMove::FirmwareRetraction::None:
      break;
  }
  if (move.filamentMm < 0.0)
    state.retractedMm -= move.filamentMm;
  else
    state.retractedMm = std::max(0.0, state.retractedMm - move.filamentMm);
}

FilamentState filamentAtEnd(const GcodeProgram& program, FilamentState start) {
  for (const GcodeMove& move : program.moves) advance(start, move);
  return start;
}

core::Result<StepTotals> checkStepProgram(const GcodeProgram& program, const StepBounds& bounds,
                                          const std::string& fileName, const double* endClearanceZMm,
                                          FilamentState start) {
  StepTotals totals;
  totals.step = bounds.step;
  FilamentState filament = start;
  for (const GcodeMove& move : program.moves) {
    if (core::Status s = checkPrimed(filament, move, bounds.step, bounds.retractToleranceMm, fileName); !s)
      return s.error();
    if (move.step != 0 && move.step != bounds.step)
      return refusal(fileName, bounds.step, move.line, "a section of step " + std::to_string(move.step) + " in its program");
    if (core::Status s = checkAboveBed(move, bounds.step, bounds.toleranceMm, fileName); !s) return s.error();
    // Any command of the platform's axis, even one to where the parser believes it stands.
    if (move.rotates() || move.commandsRotaryAxis)
      return refusal(fileName, bounds.step, move.line,
                     "the platform turns inside a step's own program (MultiDir turns it between steps)");
    if (move.extrudes())
      if (core::Status s = checkExtrusion(move, bounds, fileName, totals); !s) return s.error();
  }
  if (totals.extrusions == 0)
    return refusal(fileName, bounds.step, program.lineCount, "the step extrudes nothing on or above its base plane");
  if (endClearanceZMm != nullptr) {
    const double z = program.moves.empty() ? 0.0 : program.moves.back().to.z();
    if (z < *endClearanceZMm - bounds.toleranceMm)
      return refusal(fileName, bounds.step, program.lineCount,
                     "the program ends with the nozzle at z " + mm(z) + " mm, below the clearance the platform's turn needs (" +
                         mm(*endClearanceZMm) + " mm)");
  }
  totals.filamentAtEnd = filament;
  return totals;
}

core::Result<std::vector<StepTotals>> checkStitchedProgram(const GcodeProgram& program,
                                                           const std::vector<StepBounds>& bounds,
                                                           const std::vector<TurnClearance>& turns,
                                                           const std::string& fileName) {
  std::vector<StepTotals> totals(bounds.size());
  for (std::size_t i = 0; i < bounds.size(); ++i) totals[i].step = bounds[i].step;
  std::map<int, double> clearance;
  for (const TurnClearance& turn : turns) clearance[turn.fromStep] = turn.clearanceZMm;
  const auto boundsOf = [&](int step) -> const StepBounds* {
    for (const StepBounds& b : bounds)
      if (b.step == step) return &b;
    return nullptr;
  };

  FilamentState filament;
  for (const GcodeMove& move : program.moves) {
    const int step = move.step;
    const StepBounds* own = boundsOf(step == 0 ? (bounds.empty() ? 0 : bounds.front().step) : step);
    if (own == nullptr) return refusal(fileName, step, move.line, "a section of a step the job does not have");
    if (core::Status s = checkPrimed(filament, move, own->step, own->retractToleranceMm, fileName); !s)
      return s.error();
    if (core::Status s = checkAboveBed(move, own->step, own->toleranceMm, fileName); !s) return s.error();
    if (move.inTransition) {
      const auto it = clearance.find(step);
      if (it == clearance.end())
        return refusal(fileName, step, move.line, "a transition after the last step or one MultiDir did not plan");
      const double needed = it->second;
      if (move.extrudes()) return refusal(fileName, step, move.line, "extrusion while the platform is being turned");
      if (move.rotates()) {
        if (move.movesXy() || move.movesZ() || std::abs(move.filamentMm) > 1e-9)
          return refusal(fileName, step, move.line, "the platform turns while the nozzle or the filament moves");
        if (move.from.z() < needed - own->toleranceMm)
          return refusal(fileName, step, move.line,
                         "the platform turns with the nozzle at z " + mm(move.from.z()) +
                             " mm, below the swept part's clearance (" + mm(needed) + " mm)");
      } else if (move.movesXy() && std::min(move.from.z(), move.to.z()) < needed - own->toleranceMm) {
        return refusal(fileName, step, move.line,
                       "a move across the part at z " + mm(std::min(move.from.z(), move.to.z())) +
                           " mm, below the clearance (" + mm(needed) + " mm): lift before parking");
      }
      continue;
    }
    if (move.rotates())
      return refusal(fileName, step, move.line, "the platform turns outside a transition between steps");
    if (!move.extrudes()) continue;
    StepTotals& t = step == 0 ? totals.front() : totals[static_cast<std::size_t>(own - bounds.data())];
    StepTotals scratch;
    if (core::Status s = checkExtrusion(move, *own, fileName, step == 0 ? scratch : t); !s) return s.error();
  }
  for (StepTotals& t : totals) {
    if (t.extrusions == 0) return refusal(fileName, t.step, program.lineCount, "the step extrudes nothing");
    t.filamentAtEnd = filament;
  }
  return totals;
}

}  // namespace multidir::slicing
