#pragma once
// A G-code file read as the printer simulator runs it: one entry per line with the time its move takes (path
// length over the feed rate; G4 dwells; a fixed time for homing) and the heater commands (M104/M109 extruder,
// M140/M190 bed; the 9 and 90 variants wait for the temperature). Not a checker: words it does not know are
// skipped, as a printer's firmware would report and skip them.
#include <cstddef>
#include <string>
#include <vector>

namespace multidir::hardware::sim {

struct TimelineLine {
  std::size_t endByte = 0;   // file position after this line
  double moveSeconds = 0.0;  // at the simulated printer's nominal speed
  enum class Heater { None, Extruder, Bed } heater = Heater::None;
  double targetC = 0.0;        // for heater commands
  bool waitForHeater = false;  // M109 / M190
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
  // `line` without its end of line; `endByte` is stored as the line's TimelineLine::endByte.
  TimelineLine read(const std::string& line, std::size_t endByte);
  // Where the lines read so far end: axis 0..3 is X, Y, Z, E in mm (Marlin's planned current_position).
  [[nodiscard]] double position(int axis) const { return m_position[axis]; }

 private:
  double m_position[4] = {0, 0, 0, 0};  // X Y Z E
  bool m_relative = false;
  bool m_relativeE = false;
  double m_feedMmPerMin = 1500.0;  // until the first F word
};

GcodeTimeline readGcodeTimeline(const std::string& text);

}  // namespace multidir::hardware::sim
