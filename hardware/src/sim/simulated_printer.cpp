#include "sim/simulated_printer.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace multidir::hardware::sim {
namespace {

constexpr double kReachedWithinC = 1.0;  // M109/M190 end within this of the target

double toward(double value, double target, double step) {
  if (value < target) return std::min(target, value + step);
  return std::max(target, value - step);
}

}  // namespace

SimulatedPrinter::SimulatedPrinter(SimulatedPrinterSettings settings)
    : m_settings(settings), m_extruder(settings.ambientC), m_bed(settings.ambientC) {}

void SimulatedPrinter::storeFile(const std::string& name, std::string content) { m_files[name] = std::move(content); }

std::size_t SimulatedPrinter::fileSize(const std::string& name) const {
  const auto it = m_files.find(name);
  return it == m_files.end() ? 0 : it->second.size();
}

std::vector<std::string> SimulatedPrinter::fileNames() const {
  std::vector<std::string> names;
  for (const auto& entry : m_files) names.push_back(entry.first);
  return names;
}

double SimulatedPrinter::progress() const {
  if (m_timeline.bytes == 0) return m_state == "complete" ? 1.0 : 0.0;
  return static_cast<double>(m_bytesDone) / static_cast<double>(m_timeline.bytes);
}

std::string SimulatedPrinter::start(const std::string& name) {
  if (m_firmwareState != "ready") return "Printer is not ready: " + m_firmwareMessage;
  if (m_state == "printing" || m_state == "paused") return "SD busy";
  const auto it = m_files.find(name);
  if (it == m_files.end()) return "Unable to open file";
  m_file = name;
  m_timeline = readGcodeTimeline(it->second, m_settings.axes);
  resetJob();
  return {};
}

void SimulatedPrinter::resetJob() {
  m_line = 0;
  m_lineElapsed = 0.0;
  m_lineHeaterApplied = false;
  m_bytesDone = 0;
  m_printSeconds = 0.0;
  m_message.clear();
  m_state = "printing";
  m_axisLog = SimulatedAxisLog{};
}

void SimulatedPrinter::lineDone(const TimelineLine& line) {
  m_axisNow = line.axisDegrees;
  m_axisEnabled = line.enabledAxes;
  m_axisLog.printSeconds = m_printSeconds;
  if (!line.extrudes && !line.turns) return;
  SimulatedMove move;
  move.sequence = m_line;
  move.endSeconds = m_printSeconds;
  move.startSeconds = m_printSeconds - line.moveSeconds;
  move.xMm = line.endMm[0];
  move.yMm = line.endMm[1];
  move.zMm = line.endMm[2];
  move.axisDegrees.assign(line.axisDegrees.begin(),
                          line.axisDegrees.begin() + static_cast<long>(m_settings.axes.names.size()));
  (line.extrudes ? m_axisLog.extrusions : m_axisLog.turns).push_back(move);
  if (line.extrudes && line.turns) m_axisLog.turns.push_back(move);
}

void SimulatedPrinter::startStream(const std::string& name) {
  m_streaming = true;
  m_file = name;
  m_timeline = GcodeTimeline{};
  resetJob();
}

void SimulatedPrinter::enqueue(const TimelineLine& line) {
  m_timeline.lines.push_back(line);
  m_timeline.bytes = line.endByte;
  m_timeline.moveSeconds += line.moveSeconds;
}

bool SimulatedPrinter::waitingForHeater() const {
  return m_state == "printing" && m_line < m_timeline.lines.size() && m_timeline.lines[m_line].waitForHeater &&
         secondsToReach(m_timeline.lines[m_line]) > 0.0;
}

void SimulatedPrinter::dropQueued() {
  m_timeline.lines.resize(m_line);
  m_lineElapsed = 0.0;
  m_lineHeaterApplied = false;
  m_extruderTarget = 0.0;
  m_bedTarget = 0.0;
}

std::string SimulatedPrinter::pause() {
  if (m_state == "paused") return "Print already paused";
  if (m_state != "printing") return "Print is not in progress";
  m_state = "paused";
  return {};
}

std::string SimulatedPrinter::resume() {
  if (m_state != "paused") return "Print is not paused, resume aborted";
  m_state = "printing";
  return {};
}

std::string SimulatedPrinter::cancel() {
  if (m_state != "printing" && m_state != "paused") return "Print is not in progress";
  m_state = "cancelled";
  m_extruderTarget = 0.0;
  m_bedTarget = 0.0;
  return {};
}

void SimulatedPrinter::setTarget(TimelineLine::Heater heater, double targetC) {
  if (heater == TimelineLine::Heater::Extruder) m_extruderTarget = targetC;
  if (heater == TimelineLine::Heater::Bed) m_bedTarget = targetC;
}

void SimulatedPrinter::firmwareRestart() {
  m_firmwareState = "ready";
  m_firmwareMessage = "Printer is ready";
  m_state = "standby";
  m_message.clear();
  m_file.clear();
  m_timeline = GcodeTimeline{};
  m_bytesDone = 0;
  m_runaway = false;
}

void SimulatedPrinter::shutdown(const std::string& why) {
  m_firmwareState = "shutdown";
  m_shutdownReason = why;
  m_firmwareMessage = why +
                      "\nOnce the underlying issue is corrected, use the \"FIRMWARE_RESTART\" command to reset "
                      "the firmware, reload the config, and restart the host software.";
  if (m_state == "printing" || m_state == "paused") {
    m_state = "error";
    m_message = why;
  }
  m_extruderTarget = 0.0;
  m_bedTarget = 0.0;
  m_runaway = false;  // the firmware's shutdown switches the heater pins off
}

void SimulatedPrinter::heat(double seconds) {
  if (m_runaway)
    m_extruder += m_settings.runawayRateCPerSecond * seconds;
  else
    m_extruder = toward(m_extruder, std::max(m_extruderTarget, m_settings.ambientC),
                        m_settings.extruderRateCPerSecond * seconds);
  m_bed = toward(m_bed, std::max(m_bedTarget, m_settings.ambientC), m_settings.bedRateCPerSecond * seconds);
  if (m_extruder > m_settings.extruderMaxC) shutdown(m_settings.overTemperatureShutdown);
}

double SimulatedPrinter::secondsToReach(const TimelineLine& line) const {
  const bool extruder = line.heater == TimelineLine::Heater::Extruder;
  const double actual = extruder ? m_extruder : m_bed;
  const double gap = std::abs(line.targetC - actual) - kReachedWithinC;
  if (gap <= 0) return 0.0;
  if (extruder && m_runaway) return 1e9;  // never settles
  return gap / (extruder ? m_settings.extruderRateCPerSecond : m_settings.bedRateCPerSecond);
}

void SimulatedPrinter::advance(double seconds) {
  while (seconds > 0.0 && m_state == "printing") {
    if (m_line >= m_timeline.lines.size()) break;
    const TimelineLine& line = m_timeline.lines[m_line];
    if (!line.error.empty()) {
      // Klipper's virtual_sdcard: a command's error ends the job (print_stats "error", its message).
      m_state = "error";
      m_message = line.error;
      m_bytesDone = line.endByte;
      break;
    }
    if (line.heater != TimelineLine::Heater::None && !m_lineHeaterApplied) {
      (line.heater == TimelineLine::Heater::Extruder ? m_extruderTarget : m_bedTarget) = line.targetC;
      m_lineHeaterApplied = true;
    }
    const double need = line.waitForHeater ? secondsToReach(line) : std::max(0.0, line.moveSeconds - m_lineElapsed);
    const double step = std::min(seconds, need);
    heat(step);
    if (m_state != "printing") return;  // shut down while heating
    m_printSeconds += step;
    m_lineElapsed += step;
    seconds -= step;
    if (step >= need) {
      lineDone(line);
      m_bytesDone = line.endByte;
      ++m_line;
      m_lineElapsed = 0.0;
      m_lineHeaterApplied = false;
    }
  }
  if (m_state == "printing" && m_line >= m_timeline.lines.size() && !m_streaming) {
    m_state = "complete";
    m_bytesDone = m_timeline.bytes;
  }
  if (seconds > 0.0) heat(seconds);
}

}  // namespace multidir::hardware::sim
