#include "multidir/slicing/stitch.h"

#include <cmath>
#include <cstdio>

#include "multidir/slicing/gcode_program.h"

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;

std::string fixed(double value, int digits = 3) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

// The offset of the line that holds `marker`, or npos.
std::size_t lineOf(const std::string& text, const std::string& marker, std::size_t from = 0) {
  const std::size_t at = text.find(marker, from);
  if (at == std::string::npos) return at;
  const std::size_t start = text.rfind('\n', at);
  return start == std::string::npos ? 0 : start + 1;
}

}  // namespace

std::string primeCommands(const FilamentState& state, const PrimeSettings& prime) {
  if (state.firmwareRetracted) return "G11 ; prime: the firmware pushes back what its G10 drew back\n";
  const double push = state.retractedMm + prime.restartExtraMm;
  if (push <= 1e-6) return "; prime: the filament is not drawn back\n";
  return "G92 E0\nG1 E" + fixed(push, 5) + " F" + fixed(prime.speedMmPerS * 60.0, 0) +
         " ; prime: push back the " + fixed(state.retractedMm, 3) + " mm drawn back, plus retract_restart_extra\n"
         "G92 E0\n";
}

std::string turnCommands(const PrinterProfile& profile, Dialect dialect, double degrees) {
  std::string lines = "M400 ; let the queued moves end\n";
  switch (dialect) {
    case Dialect::Klipper:
      lines += "MANUAL_STEPPER STEPPER=" + profile.klipperStepper + " MOVE=" + fixed(degrees) +
               " SPEED=" + fixed(profile.rotaryFeedDegreesPerMin / 60.0) + "\n";
      break;
    case Dialect::Marlin:
    case Dialect::RepRapFirmware:
      lines += "G1 " + profile.rotaryAxis + fixed(degrees) + " F" + fixed(profile.rotaryFeedDegreesPerMin, 0) + "\n";
      break;
  }
  lines += "M400 ; wait until the platform stands\n";
  return lines;
}

std::vector<RotaryAxisName> rotaryAxisNames(const PrinterProfile& profile) {
  if (profile.platform == PlatformDrive::FirmwareTwoAxis)
    return {{profile.twoAxis.tilt.letter, profile.twoAxis.tilt.klipperStepper},
            {profile.twoAxis.rotation.letter, profile.twoAxis.rotation.klipperStepper}};
  return {{profile.rotaryAxis, ""}};
}

std::string twoAxisTurnCommands(const PrinterProfile& profile, Dialect dialect, const TwoAxisTurn& turn) {
  std::string lines = "M400 ; let the queued moves end\n";
  for (const AxisMove& move : turn.moves) {
    const FirmwareRotaryAxis& axis =
        move.axis == AxisMove::Axis::Tilt ? profile.twoAxis.tilt : profile.twoAxis.rotation;
    const char* what = move.axis == AxisMove::Axis::Tilt ? " ; tilt" : " ; rotation";
    if (dialect == Dialect::Klipper)
      lines += "MANUAL_STEPPER STEPPER=" + axis.klipperStepper + " MOVE=" + fixed(move.toDegrees) +
               " SPEED=" + fixed(profile.rotaryFeedDegreesPerMin / 60.0) + what + "\n";
    else
      lines += "G1 " + axis.letter + fixed(move.toDegrees) + " F" + fixed(profile.rotaryFeedDegreesPerMin, 0) + what + "\n";
    lines += "M400 ; wait until the platform stands\n";
  }
  return lines;
}

std::string axisSetupCommands(const PrinterProfile& profile, Dialect dialect) {
  if (profile.platform == PlatformDrive::FirmwareTwoAxis) {
    const TwoAxisAngles rest = restAngles(profile.twoAxis);
    std::string setup = "; MultiDir: the platform's two axes, at rest (level, azimuth 0): " +
                        profile.twoAxis.tilt.letter + " " + fixed(rest.tiltDegrees) + ", " +
                        profile.twoAxis.rotation.letter + " " + fixed(rest.rotationDegrees) + " degrees\n";
    if (dialect == Dialect::Klipper)
      return setup + "MANUAL_STEPPER STEPPER=" + profile.twoAxis.tilt.klipperStepper + " ENABLE=1 SET_POSITION=" +
             fixed(rest.tiltDegrees) + "\nMANUAL_STEPPER STEPPER=" + profile.twoAxis.rotation.klipperStepper +
             " ENABLE=1 SET_POSITION=" + fixed(rest.rotationDegrees) + "\n";
    return setup + "G92 " + profile.twoAxis.tilt.letter + fixed(rest.tiltDegrees) + " " +
           profile.twoAxis.rotation.letter + fixed(rest.rotationDegrees) + "\n";
  }
  std::string setup = "; MultiDir: the platform's axis, at rest = 0 degrees\n";
  if (dialect == Dialect::Klipper)
    return setup + "MANUAL_STEPPER STEPPER=" + profile.klipperStepper + " ENABLE=1 SET_POSITION=0\n";
  return setup + "G92 " + profile.rotaryAxis + "0\n";
}

core::Result<std::string> stitchProgram(const std::vector<StepGcode>& steps, const std::vector<TurnPlan>& turns,
                                        const PrinterProfile& profile, Dialect dialect, const Estimate& total,
                                        const PrimeSettings& prime) {
  if (steps.empty()) return Error{ErrorCode::InvalidParameter, "no steps to stitch", "stitching"};
  if (turns.size() + 1 != steps.size())
    return Error{ErrorCode::InvalidParameter, "one platform turn is needed between two steps", "stitching"};
  const std::string endMarker = "; MULTIDIR END SEQUENCE";

  struct Parts {
    std::string prelude, body, end;
    Eigen::Vector2d firstXy = Eigen::Vector2d::Zero();
    FilamentState atEnd;  // how the body leaves the filament, from a primed start
  };
  std::vector<Parts> parts;
  for (const StepGcode& step : steps) {
    const std::string stepMarker = "; MULTIDIR STEP " + std::to_string(step.step);
    const std::size_t bodyAt = lineOf(step.text, stepMarker);
    const std::size_t endAt = bodyAt == std::string::npos ? bodyAt : lineOf(step.text, endMarker, bodyAt);
    if (bodyAt == std::string::npos || endAt == std::string::npos)
      return Error{ErrorCode::InvalidParameter,
                   "the G-code of step " + std::to_string(step.step) + " lacks MultiDir's markers ('" + stepMarker +
                       "', '" + endMarker + "'): was it sliced by MultiDir?",
                   "stitching"};
    Parts p{step.text.substr(0, bodyAt), step.text.substr(bodyAt, endAt - bodyAt), step.text.substr(endAt), {}, {}};
    const core::Result<GcodeProgram> body = parseGcode(p.body, rotaryAxisNames(profile), "step " + std::to_string(step.step));
    if (!body) return body.error();
    bool found = false;
    for (const GcodeMove& move : body->moves)
      if (move.movesXy()) {
        p.firstXy = move.to.head<2>();
        found = true;
        break;
      }
    if (!found)
      return Error{ErrorCode::InvalidParameter, "step " + std::to_string(step.step) + " never moves in XY", "stitching"};
    p.atEnd = filamentAtEnd(*body);
    parts.push_back(std::move(p));
  }

  // Axis set-up: the platform stands at rest while the first step prints.
  const std::string setup = axisSetupCommands(profile, dialect);

  const std::string travel = fixed(profile.travelSpeedMmPerS * 60.0, 0);
  std::string out = parts.front().prelude + setup;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    out += parts[i].body;
    if (i + 1 == parts.size()) break;
    const TurnPlan& turn = turns[i];
    const Eigen::Vector2d& next = parts[i + 1].firstXy;
    out += "; MULTIDIR TRANSITION " + std::to_string(steps[i].step) + "\n";
    if (turn.twoAxis)
      out += "; turn the platform from " + profile.twoAxis.tilt.letter + " " + fixed(turn.twoAxis->from.tiltDegrees, 2) +
             " " + profile.twoAxis.rotation.letter + " " + fixed(turn.twoAxis->from.rotationDegrees, 2) + " to " +
             profile.twoAxis.tilt.letter + " " + fixed(turn.twoAxis->to.tiltDegrees, 2) + " " +
             profile.twoAxis.rotation.letter + " " + fixed(turn.twoAxis->to.rotationDegrees, 2) +
             " degrees; the printed part and the platform sweep up to z " + fixed(turn.sweptTopZMm, 2) + " mm\n";
    else
      out += "; turn the platform from " + fixed(turn.fromDegrees, 2) + " to " + fixed(turn.toDegrees, 2) +
             " degrees; the printed part sweeps up to z " + fixed(turn.sweptTopZMm, 2) + " mm\n";
    // The slicer's end of print has drawn the filament back already (by retract_length): only what is missing.
    FilamentState filament = parts[i].atEnd;
    const double missing = prime.retractLengthMm - filament.retractedMm;
    if (!filament.firmwareRetracted && missing > 1e-6) {
      out += "G92 E0\nG1 E" + fixed(-missing, 5) + " F" + fixed(prime.speedMmPerS * 60.0, 0) +
             " ; retract to retract_length while the platform turns\n";
      filament.retractedMm += missing;
    }
    out += "G90\nG1 Z" + fixed(turn.clearanceZMm) + " F600 ; lift above the swept part\n";
    out += "G1 X" + fixed(profile.park.x()) + " Y" + fixed(profile.park.y()) + " F" + travel + " ; park\n";
    out += turn.twoAxis ? twoAxisTurnCommands(profile, dialect, *turn.twoAxis)
                        : turnCommands(profile, dialect, turn.toDegrees);
    out += "G1 X" + fixed(next.x()) + " Y" + fixed(next.y()) + " F" + travel + " ; return above step " +
           std::to_string(steps[i + 1].step) + "'s first point\n";
    out += primeCommands(filament, prime);
    out += "G92 E0 ; reset E\n";
  }
  // The last step's end sequence, without its own estimate comments: the totals follow.
  std::string end = parts.back().end;
  const std::size_t estimates = lineOf(end, "; filament used [mm]");
  if (estimates != std::string::npos) end = end.substr(0, estimates);
  out += end;
  out += "; MultiDir: " + std::to_string(steps.size()) + " steps stitched\n";
  out += "; filament used [mm] = " + fixed(total.filamentMm, 2) + "\n";
  out += "; filament used [cm3] = " + fixed(total.filamentCm3, 2) + "\n";
  out += "; total filament used [g] = " + fixed(total.filamentGrams, 2) + "\n";
  const long seconds = std::lround(total.printSeconds);
  out += "; estimated printing time (normal mode) = " + std::to_string(seconds / 86400) + "d " +
         std::to_string((seconds / 3600) % 24) + "h " + std::to_string((seconds / 60) % 60) + "m " +
         std::to_string(seconds % 60) + "s\n";
  return out;
}

}  // namespace multidir::slicing
