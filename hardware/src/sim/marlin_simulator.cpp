// Marlin's host protocol on the master side of a pseudo-terminal, in front of SimulatedPrinter (streaming).
#include "multidir/hardware/marlin_simulator.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <mutex>
#include <thread>

#include "multidir/hardware/marlin_link.h"
#include "printer/marlin_protocol.h"
#include "sim/gcode_timeline.h"
#include "sim/simulated_printer.h"

namespace multidir::hardware {
namespace {

using Clock = std::chrono::steady_clock;
using Outcome = MarlinLineRecord::Outcome;

constexpr std::chrono::milliseconds kLoopInterval{1};
constexpr std::chrono::milliseconds kNoiseInterval{20};
constexpr int kCommandBuffer = 4;                      // Marlin's BUFSIZE, for ADVANCED_OK's B
const double kStepsPerMm[3] = {80.0, 80.0, 400.0};     // Marlin's DEFAULT_AXIS_STEPS_PER_UNIT, for M114's Count
constexpr double kStepsPerDegree = 80.0;               // a rotary axis' steps per degree (the simulator's choice)
const char* const kNoise = "\xf8\x1f~#x%\x7f&q?\xe0";  // what 115200 baud read at 250000 looks like
const char* const kKilled = "Printer halted. kill() called!";
const char* const kThermalRunaway = "Thermal Runaway, system stopped! Heater_ID: 0";

std::string temperatureText(const HeaterReading& e, const HeaterReading& b) {
  char text[128];
  std::snprintf(text, sizeof text, "T:%.2f /%.2f B:%.2f /%.2f @:0 B@:0", e.actualC, e.targetC, b.actualC, b.targetC);
  return text;
}

// The G or M code of a command ("G1 X5" -> 'G', 1); false for anything else.
bool codeOf(const std::string& command, char& letter, int& number) {
  if (command.size() < 2) return false;
  letter = static_cast<char>(std::toupper(static_cast<unsigned char>(command[0])));
  if (letter != 'G' && letter != 'M') return false;
  char* end = nullptr;
  const long parsed = std::strtol(command.c_str() + 1, &end, 10);
  if (end == command.c_str() + 1) return false;
  number = static_cast<int>(parsed);
  return true;
}

// The value of parameter `letter` in `command`, or `fallback`.
double parameter(const std::string& command, char letter, double fallback) {
  for (std::size_t i = 1; i < command.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(command[i])) != letter || command[i - 1] != ' ') continue;
    char* end = nullptr;
    const double value = std::strtod(command.c_str() + i + 1, &end);
    if (end != command.c_str() + i + 1) return value;
  }
  return fallback;
}

}  // namespace

class MarlinSimulator::Impl {
 public:
  explicit Impl(MarlinSimulatorOptions options) : m_options(std::move(options)) {
    if (!m_options.steadyNow) m_options.steadyNow = [] { return Clock::now(); };
  }
  ~Impl() { stop(); }

  core::Status start() {
    if (!(m_options.speed > 0.0) || m_options.speed > 100000.0)
      return core::Error{core::ErrorCode::InvalidParameter, "the speed must be above 0 and at most 100000", "--speed"};
    if (m_options.plannerMoves < 1 || m_options.plannerMoves > 256)
      return core::Error{core::ErrorCode::InvalidParameter, "the planner must hold 1 to 256 moves", "plannerMoves"};
    if (m_options.fault != PrinterFault::None && m_options.fault != PrinterFault::ThermalRunaway &&
        m_options.fault != PrinterFault::CancelledOnPrinter)
      return core::Error{core::ErrorCode::InvalidParameter,
                         std::string("the Marlin simulator injects thermal-runaway and cancelled-on-printer itself, "
                                     "not ") +
                             printerFaultName(m_options.fault),
                         "fault"};
    if (core::Status axes = validate(m_options.rotaryAxes, "--rotary-axes"); !axes) return axes;
    if (!m_options.rotaryAxes.manualSteppers.empty())
      return core::Error{core::ErrorCode::InvalidParameter,
                         "Marlin has rotary axes as G-code letters, not Klipper's manual steppers: give --rotary-axes",
                         "--manual-stepper"};
    if (m_options.faultAtMove < 1)
      return core::Error{core::ErrorCode::InvalidParameter, "the fault's move must be 1 or later", "faultAtMove"};
    if (m_options.busyInterval.count() < 1 || m_options.temperatureInterval.count() < 1)
      return core::Error{core::ErrorCode::InvalidParameter, "the busy and temperature intervals must be at least 1 ms",
                         "busyInterval"};
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_thread.joinable()) return core::Done{};
    int master = -1;
    int slave = -1;
    if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0)
      return core::Error{
          core::ErrorCode::DeviceUnreachable,
          "cannot open a pseudo-terminal (" + std::string(std::strerror(errno)) + "): is /dev/pts mounted?",
          "printer simulator"};
    // The printer's side is raw from the start, so nothing is echoed or translated before the link opens it.
    termios tio{};
    tcgetattr(slave, &tio);
    cfmakeraw(&tio);
    tcsetattr(slave, TCSANOW, &tio);
    fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
    fcntl(master, F_SETFD, FD_CLOEXEC);
    fcntl(slave, F_SETFD, FD_CLOEXEC);
    char* name = ttyname(slave);
    m_path = name != nullptr ? name : "";
    m_master = master;
    m_slave = slave;  // kept open: reads on the master would fail while no one holds the printer's side
    m_quit = false;
    m_lastAdvance = m_options.steadyNow();
    bootPrinter();
    m_thread = std::thread([this] { loop(); });
    return core::Done{};
  }

  void stop() {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_quit = true;
    }
    if (m_thread.joinable()) m_thread.join();
    std::lock_guard<std::mutex> lock(m_mutex);
    closeFds();
  }

  std::string devicePath() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_path;
  }

  void injectThermalRunaway() {
    std::lock_guard<std::mutex> lock(m_mutex);
    advanceLocked();
    m_printer.thermalRunaway();
  }
  void cancelJobOnPrinter() {
    std::lock_guard<std::mutex> lock(m_mutex);
    advanceLocked();
    cancelLocked();
  }
  void dropLink() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_silent = true;
    m_outbox.clear();
  }
  void restoreLink() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_silent = false;
  }
  void closePort() {
    std::lock_guard<std::mutex> lock(m_mutex);
    closeFds();
  }
  void setReplyDelay(std::chrono::milliseconds delay) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_replyDelay = delay;
  }
  void corruptNextLines(int count) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_corruptions = std::max(0, count);
  }
  void resetPrinter() {
    std::lock_guard<std::mutex> lock(m_mutex);
    bootPrinter();
  }
  void sendStrayOks(int count) {
    std::lock_guard<std::mutex> lock(m_mutex);
    for (int i = 0; i < count; ++i) send("ok");
  }
  void sendStrayOkOnReceiving(const std::string& command) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_strayOkOn = command;
  }
  void garbleOutput(bool garbled) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_garbled = garbled;
  }
  void reportTemperatures(bool report) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_reportTemperatures = report;
  }

  std::vector<MarlinLineRecord> received() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_received;
  }
  std::vector<MarlinExecutedRecord> executed() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_executed;
  }
  SimulatedAxisLog axisLog() {
    std::lock_guard<std::mutex> lock(m_mutex);
    advanceLocked();
    return m_printer.axisLog();
  }
  MarlinSimulatorState state() {
    std::lock_guard<std::mutex> lock(m_mutex);
    advanceLocked();
    MarlinSimulatorState s;
    s.halted = m_halted;
    s.haltReason = m_haltReason;
    s.extruder = m_printer.extruder();
    s.bed = m_printer.bed();
    s.lastLineNumber = m_lastLine;
    s.queuedMoves = m_printer.linesQueued();
    return s;
  }

 private:
  struct Queued {
    long lineNumber = -1;
    std::string command;
  };
  struct Execution {
    std::size_t printerLine = 0;  // SimulatedPrinter's line index: done once linesDone() passes it
    long lineNumber = -1;
    std::string command;
  };
  struct Outgoing {
    Clock::time_point releaseAt;
    std::string text;
  };

  // m_mutex held.
  void closeFds() {
    if (m_master >= 0) ::close(m_master);
    if (m_slave >= 0) ::close(m_slave);
    m_master = -1;
    m_slave = -1;
  }

  // m_mutex held: power on (or the reset button): a fresh printer at line 0, greeting the host as Marlin does.
  void bootPrinter() {
    sim::SimulatedPrinterSettings settings;
    settings.axes = axisSetup();
    m_printer = sim::SimulatedPrinter{settings};
    m_printer.startStream("serial");
    m_reader = sim::GcodeTimelineReader{axisSetup()};
    m_halted = false;
    m_haltReason.clear();
    m_lastLine = 0;
    m_inbox.clear();
    m_blocked = false;
    m_waitingForRoom = false;
    m_pendingExecution.clear();
    m_autoReport = std::chrono::milliseconds{0};
    send("start");
    send("echo:Marlin 2.1.2 (MultiDir simulator)");
  }

  sim::RotaryAxisSetup axisSetup() const {
    return {sim::RotaryAxisSetup::Firmware::Marlin, m_options.rotaryAxes.letters};
  }

  // m_mutex held.
  void send(const std::string& line) {
    if (m_silent) return;
    m_outbox.push_back(Outgoing{Clock::now() + m_replyDelay, (m_garbled ? std::string(kNoise) : line) + "\n"});
  }

  // m_mutex held: a garbled line keeps writing noise of its own, as a wrong baud rate turns any byte into some.
  void noise() {
    if (!m_garbled) return;
    const auto now = Clock::now();
    if (now - m_lastNoise < kNoiseInterval) return;
    m_lastNoise = now;
    send(kNoise);
  }

  // m_mutex held: the ok of a numbered or unnumbered command, with ADVANCED_OK's numbers when built with it.
  std::string okFor(const Queued& q) const {
    if (!m_options.advancedOk || q.lineNumber < 0) return "ok";
    const std::size_t queued = m_printer.linesQueued();
    const long plannerFree = queued >= static_cast<std::size_t>(m_options.plannerMoves)
                                 ? 0
                                 : m_options.plannerMoves - static_cast<long>(queued);
    const long bufferFree = std::max<long>(0, kCommandBuffer - static_cast<long>(m_inbox.size()));
    return "ok N" + std::to_string(q.lineNumber) + " P" + std::to_string(plannerFree) + " B" +
           std::to_string(bufferFree);
  }

  // m_mutex held: Marlin's M114 (report_current_position_projected): the planned position, logical and in steps.
  // report_logical_position lists X Y Z, then the extra axes in Marlin's order (I J K U V W, named by
  // AXIS4_NAME..; here the options' order), then E; the stepper counts follow for the axes, not E.
  std::string positionText() const {
    char number[64];
    std::string logical;
    std::string counts = " Count";
    const auto axis = [&](const std::string& letter, double value, double stepsPerUnit) {
      std::snprintf(number, sizeof number, "%s%s:%.2f", logical.empty() ? "" : " ", letter.c_str(), value);
      logical += number;
      std::snprintf(number, sizeof number, " %s:%ld", letter.c_str(), std::lround(value * stepsPerUnit));
      counts += number;
    };
    axis("X", m_reader.position(0), kStepsPerMm[0]);
    axis("Y", m_reader.position(1), kStepsPerMm[1]);
    axis("Z", m_reader.position(2), kStepsPerMm[2]);
    for (std::size_t i = 0; i < m_options.rotaryAxes.letters.size(); ++i)
      axis(m_options.rotaryAxes.letters[i], m_reader.axisPosition(i), kStepsPerDegree);
    std::snprintf(number, sizeof number, " E:%.2f", m_reader.position(3));
    return logical + number + counts;
  }

  // m_mutex held: M115's first line (GcodeSuite::M115): AXIS_COUNT only when the axes are not X, Y, Z alone.
  std::string capabilityText() const {
    std::string text =
        "FIRMWARE_NAME:Marlin 2.1.2 (MultiDir simulator) SOURCE_CODE_URL:github.com/MarlinFirmware/Marlin "
        "PROTOCOL_VERSION:1.0 MACHINE_TYPE:MultiDir simulator EXTRUDER_COUNT:1";
    if (!m_options.rotaryAxes.letters.empty())
      text += " AXIS_COUNT:" + std::to_string(3 + m_options.rotaryAxes.letters.size());
    return text;
  }

  // m_mutex held: runs the printer up to now.
  void advanceLocked() {
    const auto now = m_options.steadyNow();
    const double seconds = std::chrono::duration<double>(now - m_lastAdvance).count() * m_options.speed;
    m_lastAdvance = now;
    if (seconds > 0.0) m_printer.advance(seconds);
    while (!m_pendingExecution.empty() && m_printer.linesDone() > m_pendingExecution.front().printerLine) {
      const Execution& e = m_pendingExecution.front();
      m_executed.push_back(MarlinExecutedRecord{now, e.lineNumber, e.command});
      m_pendingExecution.pop_front();
    }
    // The heater ran away past its limit: Marlin's thermal protection halts the printer.
    if (!m_halted && m_printer.firmwareState() == "shutdown") kill(kThermalRunaway);
  }

  // m_mutex held: the LCD's "Stop print".
  void cancelLocked() {
    m_printer.dropQueued();
    m_pendingExecution.clear();
    send("//action:cancel");
  }

  // m_mutex held: options.fault, once its move was taken.
  void injectFaultLocked() {
    if (m_options.fault == PrinterFault::ThermalRunaway) m_printer.thermalRunaway();
    if (m_options.fault == PrinterFault::CancelledOnPrinter) cancelLocked();
  }

  // m_mutex held.
  void kill(const std::string& reason) {
    if (reason != kKilled) send(std::string("Error:") + reason);
    send(std::string("Error:") + kKilled);
    m_halted = true;
    m_haltReason = reason;
    m_inbox.clear();
    m_blocked = false;
    if (m_printer.firmwareState() != "shutdown") m_printer.emergencyStop();
  }

  // m_mutex held: a line as Marlin's serial reader takes it (checks at once; execution later, in order).
  void onLine(std::string text) {
    if (m_silent) return;  // the printer hears nothing
    MarlinLineRecord record;
    record.at = m_options.steadyNow();
    if (m_corruptions > 0 && !text.empty() && text[0] == 'N' && text.size() > 4) {
      --m_corruptions;
      text[text.size() / 2] = static_cast<char>(text[text.size() / 2] ^ 0x01);  // one bit flipped in transit
    }
    record.text = text;
    if (m_halted) {
      record.outcome = Outcome::Ignored;
      m_received.push_back(record);
      return;
    }
    std::string command = text;
    const std::size_t star = text.rfind('*');
    if (!text.empty() && text[0] == 'N') {
      char* end = nullptr;
      record.lineNumber = std::strtol(text.c_str() + 1, &end, 10);
      const std::size_t after = static_cast<std::size_t>(end - text.c_str());
      command = marlin::commandOf(star == std::string::npos || star < after ? text.substr(after)
                                                                            : text.substr(after, star - after));
      record.command = command;
      if (command == "M112") return emergency(record);
      if (star == std::string::npos) return refuse(record, Outcome::NoChecksum, "No Checksum with line number");
      const int given = std::atoi(text.c_str() + star + 1);
      if (marlinChecksum(text.substr(0, star)) != given)
        return refuse(record, Outcome::ChecksumMismatch, "checksum mismatch");
      const bool m110 = command.rfind("M110", 0) == 0;
      if (!m110 && record.lineNumber != m_lastLine + 1)
        return refuse(record, Outcome::WrongLineNumber, "Line Number is not Last Line Number+1");
      m_lastLine =
          m110 ? static_cast<long>(parameter(command, 'N', static_cast<double>(record.lineNumber))) : record.lineNumber;
    } else {
      command = marlin::commandOf(star == std::string::npos ? text : text.substr(0, star));
      record.command = command;
      if (command == "M112") return emergency(record);
      if (star != std::string::npos) return refuse(record, Outcome::NoChecksum, "No Line Number with checksum");
      if (command.rfind("M110", 0) == 0) m_lastLine = static_cast<long>(parameter(command, 'N', 0.0));
    }
    record.outcome = Outcome::Accepted;
    m_received.push_back(record);
    if (!command.empty()) m_inbox.push_back(Queued{record.lineNumber, command});
    if (!m_strayOkOn.empty() && command == m_strayOkOn) send("ok");  // test hook: an ok that answers no line
  }

  // m_mutex held: Marlin's gcode_line_error and flush_and_request_resend.
  void refuse(MarlinLineRecord& record, Outcome outcome, const std::string& message) {
    record.outcome = outcome;
    m_received.push_back(record);
    send("Error:" + message + ", Last Line: " + std::to_string(m_lastLine));
    send("Resend: " + std::to_string(m_lastLine + 1));
    send("ok");
    m_flushInput = true;  // Marlin drops what else is in its serial buffer
  }

  // m_mutex held: M112, taken by the emergency parser as it arrives.
  void emergency(MarlinLineRecord& record) {
    record.outcome = Outcome::EmergencyStop;
    m_received.push_back(record);
    m_executed.push_back(MarlinExecutedRecord{record.at, record.lineNumber, "M112"});
    kill(kKilled);
  }

  // m_mutex held: executes queued commands in order, as far as the planner and blocking commands allow.
  void process() {
    const auto now = m_options.steadyNow();
    const auto realNow = Clock::now();  // keepalive and temperature lines are real-time, like Marlin's timers
    while (!m_inbox.empty() && !m_halted) {
      const Queued& q = m_inbox.front();
      if (m_blocked) {
        if (m_printer.linesQueued() > 0) {
          if (realNow - m_lastBusy >= m_options.busyInterval) {
            m_lastBusy = realNow;
            send("echo:busy: processing");
          }
          if (m_reportTemperatures && m_printer.waitingForHeater() &&
              realNow - m_lastTemperatureLine >= m_options.temperatureInterval) {
            m_lastTemperatureLine = realNow;
            send(temperatureText(m_printer.extruder(), m_printer.bed()) + " W:?");
          }
          return;
        }
        m_blocked = false;
        if (m_blockedOutsidePrinter) m_executed.push_back(MarlinExecutedRecord{now, q.lineNumber, q.command});  // M400
        finish(q);
        continue;
      }
      char letter = 0;
      int number = 0;
      const bool known = codeOf(q.command, letter, number);
      const bool toPrinter =
          known && ((letter == 'G' && (number <= 4 || number == 28 || number == 90 || number == 91 || number == 92)) ||
                    (letter == 'M' && (number == 82 || number == 83 || number == 104 || number == 109 ||
                                       number == 140 || number == 190)));
      const bool blocking = known && ((letter == 'G' && (number == 4 || number == 28)) ||
                                      (letter == 'M' && (number == 109 || number == 190 || number == 400)));
      const bool move = known && letter == 'G' && number <= 1;
      if (toPrinter) {
        if (!blocking && m_printer.linesQueued() >= static_cast<std::size_t>(m_options.plannerMoves)) {
          // The move waits for room in the planner inside its handler: Marlin's host keepalive says so.
          if (!m_waitingForRoom) m_lastBusy = realNow;
          m_waitingForRoom = true;
          if (realNow - m_lastBusy >= m_options.busyInterval) {
            m_lastBusy = realNow;
            send("echo:busy: processing");
          }
          return;
        }
        m_waitingForRoom = false;
        m_pendingExecution.push_back(
            Execution{m_printer.linesDone() + m_printer.linesQueued(), q.lineNumber, q.command});
        m_printer.enqueue(m_reader.read(q.command, 0));
      } else if (!blocking) {
        m_executed.push_back(MarlinExecutedRecord{now, q.lineNumber, q.command});
      }
      if (blocking) {
        m_blocked = true;
        m_blockedOutsidePrinter = !toPrinter;
        m_lastBusy = realNow;
        m_lastTemperatureLine = realNow;
        continue;  // answered once the printer has done it
      }
      finish(q);
      if (move && ++m_movesTaken == m_options.faultAtMove) injectFaultLocked();
    }
  }

  // m_mutex held: answers a command that is done (or in the planner) and takes it off the queue.
  void finish(const Queued& q) {
    char letter = 0;
    int number = 0;
    const bool known = codeOf(q.command, letter, number);
    if (known && letter == 'M' && number == 105) {
      // Marlin answers M105 on its ok line, without ADVANCED_OK's numbers.
      send(m_reportTemperatures ? "ok " + temperatureText(m_printer.extruder(), m_printer.bed()) : "ok");
    } else if (known && letter == 'M' && number == 114) {
      send(positionText());
      send(okFor(q));
    } else if (known && letter == 'M' && number == 115) {
      send(capabilityText());
      send(okFor(q));
    } else if (known && letter == 'M' && number == 27) {
      send("Not SD printing");  // the job is streamed by the host, not read from the SD card
      send(okFor(q));
    } else if (known && letter == 'M' && number == 155) {
      m_autoReport = std::chrono::milliseconds(static_cast<long>(parameter(q.command, 'S', 0.0) * 1000.0));
      send(okFor(q));
    } else {
      send(okFor(q));
    }
    m_inbox.pop_front();
  }

  void autoReport() {
    if (m_autoReport.count() <= 0 || m_halted || !m_reportTemperatures) return;
    const auto now = Clock::now();
    if (now - m_lastAutoReport < m_autoReport) return;
    m_lastAutoReport = now;
    send(" " + temperatureText(m_printer.extruder(), m_printer.bed()));
  }

  // m_mutex held: writes what is due (the reply delay holds lines back).
  void flush() {
    const auto now = Clock::now();
    while (!m_outbox.empty() && m_master >= 0 && m_outbox.front().releaseAt <= now) {
      const std::string& text = m_outbox.front().text;
      const ssize_t n = ::write(m_master, text.data(), text.size());
      if (n < 0) return;  // the link does not read: keep it for later
      if (static_cast<std::size_t>(n) < text.size()) {
        m_outbox.front().text.erase(0, static_cast<std::size_t>(n));
        return;
      }
      m_outbox.pop_front();
    }
  }

  void loop() {
    std::string rx;
    while (true) {
      int master = -1;
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_quit) return;
        master = m_master;
      }
      if (master < 0) {
        std::this_thread::sleep_for(kLoopInterval);
      } else {
        pollfd p{master, POLLIN, 0};
        ::poll(&p, 1, static_cast<int>(kLoopInterval.count()));
        if ((p.revents & POLLIN) != 0) {
          char buffer[1024];
          const ssize_t n = ::read(master, buffer, sizeof buffer);
          if (n > 0) rx.append(buffer, static_cast<std::size_t>(n));
        }
      }
      std::lock_guard<std::mutex> lock(m_mutex);
      advanceLocked();
      std::size_t end = 0;
      while ((end = rx.find_first_of("\r\n")) != std::string::npos) {
        std::string line = rx.substr(0, end);
        rx.erase(0, end + 1);
        if (line.empty()) continue;
        onLine(std::move(line));
        if (m_flushInput) {
          m_flushInput = false;
          rx.clear();
          break;
        }
      }
      if (m_silent) rx.clear();
      process();
      autoReport();
      noise();
      flush();
    }
  }

  MarlinSimulatorOptions m_options;
  mutable std::mutex m_mutex;
  bool m_quit = false;
  std::thread m_thread;
  int m_master = -1;
  int m_slave = -1;
  std::string m_path;

  sim::SimulatedPrinter m_printer;
  sim::GcodeTimelineReader m_reader;
  Clock::time_point m_lastAdvance{};
  bool m_halted = false;
  std::string m_haltReason;
  long m_lastLine = 0;
  std::deque<Queued> m_inbox;            // Marlin's command queue
  bool m_blocked = false;                // the front command waits for the printer
  bool m_blockedOutsidePrinter = false;  // ... and is not one of its lines (M400): recorded when it ends
  std::deque<Execution> m_pendingExecution;
  Clock::time_point m_lastBusy{};
  Clock::time_point m_lastTemperatureLine{};
  std::chrono::milliseconds m_autoReport{0};
  Clock::time_point m_lastAutoReport{};
  bool m_flushInput = false;

  bool m_waitingForRoom = false;  // the front move waits for room in the planner

  bool m_silent = false;
  bool m_garbled = false;
  Clock::time_point m_lastNoise{};
  bool m_reportTemperatures = true;
  std::string m_strayOkOn;  // a stray ok follows each received line of this command ("" none)
  int m_corruptions = 0;
  long m_movesTaken = 0;  // G0/G1 taken into the planner since start(), for options.faultAtMove
  std::chrono::milliseconds m_replyDelay{0};
  std::deque<Outgoing> m_outbox;

  std::vector<MarlinLineRecord> m_received;
  std::vector<MarlinExecutedRecord> m_executed;
};

MarlinSimulator::MarlinSimulator(MarlinSimulatorOptions options) : m_impl(std::make_unique<Impl>(std::move(options))) {}
MarlinSimulator::~MarlinSimulator() = default;
core::Status MarlinSimulator::start() { return m_impl->start(); }
void MarlinSimulator::stop() { m_impl->stop(); }
std::string MarlinSimulator::devicePath() const { return m_impl->devicePath(); }
void MarlinSimulator::injectThermalRunaway() { m_impl->injectThermalRunaway(); }
void MarlinSimulator::cancelJobOnPrinter() { m_impl->cancelJobOnPrinter(); }
void MarlinSimulator::dropLink() { m_impl->dropLink(); }
void MarlinSimulator::restoreLink() { m_impl->restoreLink(); }
void MarlinSimulator::closePort() { m_impl->closePort(); }
void MarlinSimulator::setReplyDelay(std::chrono::milliseconds delay) { m_impl->setReplyDelay(delay); }
void MarlinSimulator::corruptNextLines(int count) { m_impl->corruptNextLines(count); }
void MarlinSimulator::resetPrinter() { m_impl->resetPrinter(); }
void MarlinSimulator::sendStrayOks(int count) { m_impl->sendStrayOks(count); }
void MarlinSimulator::sendStrayOkOnReceiving(const std::string& command) { m_impl->sendStrayOkOnReceiving(command); }
void MarlinSimulator::garbleOutput(bool garbled) { m_impl->garbleOutput(garbled); }
void MarlinSimulator::reportTemperatures(bool report) { m_impl->reportTemperatures(report); }
std::vector<MarlinLineRecord> MarlinSimulator::received() const { return m_impl->received(); }
std::vector<MarlinExecutedRecord> MarlinSimulator::executed() const { return m_impl->executed(); }
MarlinSimulatorState MarlinSimulator::state() const { return m_impl->state(); }
SimulatedAxisLog MarlinSimulator::axisLog() const { return m_impl->axisLog(); }

}  // namespace multidir::hardware
