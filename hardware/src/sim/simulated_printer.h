#pragma once
// The printer behind the printer simulators: Klipper's print_stats states, a virtual SD card that runs a
// G-code file line by line (moves timed by their feed rates, heater waits by the heating rate), two heaters,
// and Klipper's shutdown (emergency stop, or a heater beyond its maximal temperature). Time only moves in
// advance(); not thread-safe (the simulator holds its lock around every call).
#include <array>
#include <map>
#include <string>

#include "multidir/hardware/printer_link.h"
#include "multidir/hardware/simulated_axes.h"
#include "sim/gcode_timeline.h"

namespace multidir::hardware::sim {

struct SimulatedPrinterSettings {
  double ambientC = 22.0;
  double extruderRateCPerSecond = 10.0;  // heating and cooling
  double bedRateCPerSecond = 2.0;
  double runawayRateCPerSecond = 20.0;  // a stuck-on extruder heater climbs this fast
  double extruderMaxC = 280.0;          // Klipper's max_temp: beyond it the firmware shuts down
  // The firmware's words when a heater passes its maximum (Klipper's; Marlin says "MAXTEMP triggered").
  std::string overTemperatureShutdown = "MCU 'mcu' shutdown: ADC out of range";
  RotaryAxisSetup axes;  // the rotary axes the firmware has (none unless configured)
};

class SimulatedPrinter {
 public:
  explicit SimulatedPrinter(SimulatedPrinterSettings settings = {});

  void advance(double seconds);

  void storeFile(const std::string& name, std::string content);
  [[nodiscard]] bool hasFile(const std::string& name) const { return m_files.count(name) > 0; }
  [[nodiscard]] std::size_t fileSize(const std::string& name) const;
  [[nodiscard]] std::vector<std::string> fileNames() const;

  // Klipper's commands; each returns "" when done, else Klipper's error text.
  std::string start(const std::string& name);
  std::string pause();
  std::string resume();
  std::string cancel();
  void emergencyStop() { shutdown("Shutdown due to webhooks request"); }
  // A heater's target set from the console (M104/M140 outside a job, Klipper's TURN_OFF_HEATERS): at once.
  void setTarget(TimelineLine::Heater heater, double targetC);
  void firmwareRestart();

  // Faults.
  void thermalRunaway() { m_runaway = true; }

  // Streaming (a host sends the file line by line, as to Marlin over USB): the job stays "printing" with lines
  // appended as they arrive; running out of lines means waiting for the host, not complete.
  void startStream(const std::string& name);
  void enqueue(const TimelineLine& line);
  [[nodiscard]] std::size_t linesQueued() const { return m_timeline.lines.size() - m_line; }  // not finished yet
  [[nodiscard]] std::size_t linesDone() const { return m_line; }
  [[nodiscard]] bool waitingForHeater() const;  // the current line is an M109/M190 not reached yet
  // Drops the lines not finished yet and switches the heaters off (a print stopped at the printer).
  void dropQueued();

  [[nodiscard]] const std::string& jobState() const { return m_state; }  // print_stats.state
  [[nodiscard]] const std::string& jobMessage() const { return m_message; }
  [[nodiscard]] const std::string& firmwareState() const { return m_firmwareState; }  // webhooks.state
  [[nodiscard]] const std::string& firmwareMessage() const { return m_firmwareMessage; }
  // Why the firmware last shut down, without Klipper's advice on restarting ("" when it never did).
  [[nodiscard]] const std::string& shutdownReason() const { return m_shutdownReason; }
  [[nodiscard]] const std::string& currentFile() const { return m_file; }
  [[nodiscard]] double progress() const;
  [[nodiscard]] std::size_t filePosition() const { return m_bytesDone; }
  [[nodiscard]] double printSeconds() const { return m_printSeconds; }
  [[nodiscard]] HeaterReading extruder() const { return {m_extruder, m_extruderTarget}; }
  [[nodiscard]] HeaterReading bed() const { return {m_bed, m_bedTarget}; }
  [[nodiscard]] const RotaryAxisSetup& axes() const { return m_settings.axes; }
  // The rotary axes after the last line done (degrees, the setup's order), and which Klipper has enabled.
  [[nodiscard]] double axisPosition(std::size_t index) const { return m_axisNow[index]; }
  [[nodiscard]] bool axisEnabled(std::size_t index) const { return (m_axisEnabled & (1u << index)) != 0; }
  // The extrusions and turns of the current job, each recorded when it ended.
  [[nodiscard]] const SimulatedAxisLog& axisLog() const { return m_axisLog; }

 private:
  void heat(double seconds);
  void shutdown(const std::string& why);
  double secondsToReach(const TimelineLine& line) const;
  void lineDone(const TimelineLine& line);
  void resetJob();

  SimulatedPrinterSettings m_settings;
  std::map<std::string, std::string> m_files;
  std::string m_state = "standby";
  std::string m_message;
  std::string m_firmwareState = "ready";
  std::string m_firmwareMessage = "Printer is ready";
  std::string m_shutdownReason;
  std::string m_file;
  GcodeTimeline m_timeline;
  std::size_t m_line = 0;
  double m_lineElapsed = 0.0;
  bool m_lineHeaterApplied = false;
  std::size_t m_bytesDone = 0;
  double m_printSeconds = 0.0;
  double m_extruder;
  double m_bed;
  double m_extruderTarget = 0.0;
  double m_bedTarget = 0.0;
  bool m_runaway = false;
  bool m_streaming = false;
  std::array<double, 3> m_axisNow = {0, 0, 0};
  unsigned m_axisEnabled = 0;
  SimulatedAxisLog m_axisLog;
};

}  // namespace multidir::hardware::sim
