#pragma once
// A G-code file read as the printer simulator runs it: one entry per line with the time its move takes (path
// length over the feed rate; G4 dwells; a fixed time for homing) and the heater commands (M104/M109 extruder,
// M140/M190 bed; the 9 and 90 variants wait for the temperature). Not a checker: words it does not know are
// skipped, as a printer's firmware would report and skip them.
//
// Rotary axes (simulated_axes.h): Marlin-like firmware (Marlin, RepRapFirmware) moves them with G0/G1 words and
// sets them with G92; Klipper with MANUAL_STEPPER STEPPER=name [ENABLE=] [SET_POSITION=] [SPEED=] [MOVE=]. Time of a
// move, as both Marlin's planner and RepRapFirmware's DDA::InitStandardMove take the feed rate (NIST RS274NGC
// 2.1.2.5 rule A): when X, Y or Z move, F is the speed along the XYZ path and the rotary axes turn in the same
// time; when only rotary axes move, F (degrees per minute) is the speed of the vector of their changes; else the
// extruder's change over F. Klipper's MANUAL_STEPPER MOVE takes |change| / SPEED (degrees per second; the
// stepper's velocity, Klipper's default 5, when SPEED is absent; no acceleration, Klipper's default ACCEL=0) and
// runs after the moves before it (its default SYNC=1). Accelerations are not modelled anywhere.
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace multidir::hardware::sim {

// How the firmware reads the rotary axes, and which it has.
struct RotaryAxisSetup {
  enum class Firmware { Marlin, Klipper } firmware = Firmware::Marlin;
  // Marlin: G-code letters ("U"); Klipper: manual stepper names. At most 3 (kMaxSimulatedRotaryAxes).
  std::vector<std::string> names;
};

struct TimelineLine {
  std::size_t endByte = 0;   // file position after this line
  double moveSeconds = 0.0;  // at the simulated printer's nominal speed
  enum class Heater { None, Extruder, Bed } heater = Heater::None;
  double targetC = 0.0;                           // for heater commands
  bool waitForHeater = false;                     // M109 / M190
  bool extrudes = false;                          // moves X, Y or Z and pushes filament forward
  bool turns = false;                             // changes a rotary axis' coordinate
  std::array<double, 3> endMm = {0, 0, 0};        // X Y Z after the line
  std::array<double, 3> axisDegrees = {0, 0, 0};  // the rotary axes after the line, in the setup's order
  unsigned enabledAxes = 0;                       // Klipper: bit i set once manual stepper i was enabled (ENABLE=1)
  std::string error;  // the firmware refuses the line with these words (Klipper: an unknown manual stepper)
};

struct GcodeTimeline {
  std::vector<TimelineLine> lines;
  std::size_t bytes = 0;
  double moveSeconds = 0.0;  // sum of the moves (heating not included)
};

// Reads one line at a time, keeping the modal state (position, absolute/relative, feed rate) between lines:
// readGcodeTimeline for a whole file, the Marlin simulator for lines as they arrive over the serial link.
class GcodeTimelineReader {
 public:
  explicit GcodeTimelineReader(RotaryAxisSetup axes = {}) : m_axes(std::move(axes)) {}
  // `line` without its end of line; `endByte` is stored as the line's TimelineLine::endByte.
  TimelineLine read(const std::string& line, std::size_t endByte);
  // Where the lines read so far end: axis 0..3 is X, Y, Z, E in mm (Marlin's planned current_position).
  [[nodiscard]] double position(int axis) const { return m_position[axis]; }
  // The rotary axis `index` of the setup (degrees).
  [[nodiscard]] double axisPosition(std::size_t index) const { return m_axis[index]; }
  [[nodiscard]] const RotaryAxisSetup& axes() const { return m_axes; }

 private:
  void readManualStepper(const std::string& code, TimelineLine& line);

  RotaryAxisSetup m_axes;
  std::array<double, 3> m_axis = {0, 0, 0};
  unsigned m_enabled = 0;
  double m_position[4] = {0, 0, 0, 0};  // X Y Z E
  bool m_relative = false;
  bool m_relativeE = false;
  double m_feedMmPerMin = 1500.0;  // until the first F word
};

GcodeTimeline readGcodeTimeline(const std::string& text, const RotaryAxisSetup& axes = {});

}  // namespace multidir::hardware::sim
