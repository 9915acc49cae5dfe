// Marlin over a serial device: one worker thread owns the port's reading and the line-numbered stream (it
// runs the queued commands in order between lines), one thread only writes the latched M112 (both started and
// stopped by PrinterLinkThreads; the latch is a LatchedEmergencyStop, shared with the HTTP links).
#include "multidir/hardware/marlin_link.h"

#include <poll.h>
#include <unistd.h>

#include <cctype>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <deque>
#include <sstream>
#include <map>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "printer/checked_gcode.h"
#include "printer/latched_emergency_stop.h"
#include "printer/marlin_line_ledger.h"
#include "printer/marlin_protocol.h"
#include "printer/printer_link_threads.h"
#include "printer/serial_port.h"

namespace multidir::hardware {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

// Sent when a job is cancelled: heaters and part fan off. No motion: the platform may be about to turn, and
// where the head may park is the operator's decision.
const char* const kCancelLines[] = {"M104 S0", "M140 S0", "M107"};
// switchHeatersOff(): both heaters, nothing else.
const char* const kHeatersOffLines[] = {"M104 S0", "M140 S0"};
constexpr std::size_t kRenumberAfterLines = 10000;
// Marlin answers M105 with its temperatures on the ok line: this many temperature polls answered with a bare ok
// in a row (no temperature report between them) mean the printer's state cannot be read.
constexpr int kBareTemperaturePollsLimit = 3;

core::Error invalid(const std::string& what, const std::string& where) {
  return core::Error{core::ErrorCode::InvalidParameter, what, where};
}

template <typename T>
std::future<T> readyFuture(T value) {
  std::promise<T> promise;
  promise.set_value(std::move(value));
  return promise.get_future();
}

// The axes of M114's report (report_logical_position: "X:1.00 Y:2.00 Z:3.00 U:0.00 V:0.00 E:0.00 Count X:..")
// beyond X, Y, Z and E, in its order.
FirmwareAxes axesOfPositionReport(const std::string& text) {
  FirmwareAxes axes;
  const std::string logical = text.substr(0, text.find("Count"));
  std::size_t at = 0;
  while ((at = logical.find(':', at)) != std::string::npos) {
    std::size_t begin = at;
    while (begin > 0 && std::isalpha(static_cast<unsigned char>(logical[begin - 1]))) --begin;
    const std::string letter = logical.substr(begin, at - begin);
    if (letter.size() == 1 && std::string("XYZE").find(letter) == std::string::npos) axes.letters.push_back(letter);
    ++at;
  }
  return axes;
}

class MarlinLink : public PrinterLink {
 public:
  MarlinLink(MarlinSettings settings, PrinterLinkOptions options)
      : m_settings(std::move(settings)), m_options(std::move(options)) {
    if (!m_options.steadyNow) m_options.steadyNow = [] { return Clock::now(); };
    m_name = "Marlin printer at " + m_settings.devicePath;
  }
  ~MarlinLink() override { disconnect(); }

  core::Status connect() override {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (m_threads.running()) return invalid("already connected", m_name);
      m_threads.begin();
      m_status.link = LinkState::Connecting;
      m_status.polls = 0;
    }
    return m_threads.start([this] { runWorker(); }, [this] { runStopper(); });
  }

  void disconnect() override {
    if (!m_threads.stop()) return;
    closePort();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_threads.finish();
    m_status.link = LinkState::Disconnected;
    const core::Error cancelled{core::ErrorCode::Cancelled, "the link was disconnected before the printer answered",
                                m_name};
    failQueued(cancelled);
    failJobPromises(cancelled);
    m_stop.cancelWaiters(m_name);
  }

  using PrinterLink::upload;
  std::future<core::Status> upload(const std::string& localPath, const std::string& remoteName,
                                   const std::string& checkedSha256) override {
    if (remoteName.empty() || remoteName.find('/') != std::string::npos || remoteName.find("..") != std::string::npos)
      return readyFuture<core::Status>(
          invalid("the printer's file name '" + remoteName + "' must be a plain file name", m_name));
    return submit(Command::Upload, "loading " + remoteName, true, localPath, remoteName, checkedSha256);
  }
  std::future<core::Status> startPrint(const std::string& remoteName) override {
    return submit(Command::Start, "starting " + remoteName, true, {}, remoteName);
  }
  std::future<core::Status> pausePrint() override { return submit(Command::Pause, "pausing the print", false); }
  std::future<core::Status> resumePrint() override { return submit(Command::Resume, "resuming the print", true); }
  std::future<core::Status> cancelPrint() override { return submit(Command::Cancel, "cancelling the print", false); }
  std::future<core::Status> switchHeatersOff() override {
    return submit(Command::HeatersOff, "switching the heaters off", false);
  }

  // M114 between jobs: its report lists every axis Marlin has ("X:.. Y:.. Z:.. U:.. V:.. E:.. Count ..."). Refused
  // while a job streams (its lines hold the numbering) or while another such question waits.
  std::future<core::Result<FirmwareAxes>> readFirmwareAxes() override {
    std::promise<core::Result<FirmwareAxes>> promise;
    std::future<core::Result<FirmwareAxes>> future = promise.get_future();
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_threads.running() || m_job || m_axesPromise) {
        promise.set_value(invalid(!m_threads.running() ? "not connected: M114 was not sent"
                                                       : "the printer is busy with a job or another M114: ask again later",
                                  m_name));
        return future;
      }
      m_axesPromise = std::move(promise);
      m_axesQueried = false;
    }
    m_threads.workerWake().notify_all();
    return future;
  }

  std::future<core::Status> emergencyStop() override {
    std::future<core::Status> future;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      future = m_stop.latch();
      m_haltedBeforeStop = m_status.firmwareState == "halted";
      failQueued(core::Error{core::ErrorCode::Cancelled, "cancelled by the emergency stop", m_name});
      m_dropJob = true;  // the worker stops streaming at once
    }
    m_threads.stopWake().notify_all();
    m_threads.workerWake().notify_all();
    return future;
  }

  core::Status clearStop() override {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_stop.clear(m_name);
  }

  PrinterStatus status() const override {
    std::lock_guard<std::mutex> lock(m_mutex);
    PrinterStatus s = m_status;
    s.stop = m_stop.state();
    s.linkLost = s.polls == 0 || m_options.steadyNow() - s.lastReply >= m_options.linkLostAfter ||
                 m_bareTemperaturePolls >= kBareTemperaturePollsLimit;
    if (s.linkLost && s.polls > 0)
      if (std::string why = notAnsweringReason(); !why.empty()) s.lastError = std::move(why);
    return s;
  }

  std::string name() const override { return m_name; }

 private:
  enum class Command { Upload, Start, Pause, Resume, Cancel, HeatersOff };
  struct Pending {
    Command command = Command::Upload;
    std::string what;
    std::string localPath;
    std::string remoteName;
    std::string checkedSha256;  // upload: the SHA-256 the file had when it was checked ("": none)
    std::promise<core::Status> promise;
  };
  using Role = marlin::LineRole;
  using Line = marlin::StreamLine;
  struct Job {
    std::string name;
    std::vector<std::string> lines;
    std::size_t nextFileLine = 0;  // the next file line to number and send
    std::size_t acknowledged = 0;  // file lines the printer took
    bool endQueued = false;        // M400 numbered
    bool reportQueued = false;     // M114 numbered
    bool reportSent = false;       // ... and written: its position report ends the job
    bool cancelling = false;
    std::size_t coolDownQueued = 0;
  };

  std::future<core::Status> submit(Command command, const std::string& what, bool refusedWhileStopped,
                                   std::string localPath = {}, std::string remoteName = {},
                                   std::string checkedSha256 = {}) {
    std::promise<core::Status> promise;
    std::future<core::Status> future = promise.get_future();
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_threads.running()) {
        promise.set_value(invalid("not connected: " + what + " was not sent", m_name));
        return future;
      }
      if (refusedWhileStopped && m_stop.latched()) {
        promise.set_value(invalid(
            "the emergency stop is latched: " + what + " was not sent; clear the stop (and reset the printer) first",
            m_name));
        return future;
      }
      m_queue.push_back(Pending{command, what, std::move(localPath), std::move(remoteName), std::move(checkedSha256),
                                std::move(promise)});
    }
    m_threads.workerWake().notify_all();
    return future;
  }

  // Requires m_mutex.
  void failQueued(const core::Error& error) {
    for (Pending& pending : m_queue) pending.promise.set_value(error);
    m_queue.clear();
  }
  // Requires m_mutex.
  void failJobPromises(const core::Error& error) {
    if (m_startPromise) m_startPromise->set_value(error);
    if (m_cancelPromise) m_cancelPromise->set_value(error);
    if (m_heatersOffPromise) m_heatersOffPromise->set_value(error);
    m_startPromise.reset();
    m_cancelPromise.reset();
    m_heatersOffPromise.reset();
    m_heatersOffQueued = 0;
    if (m_axesPromise) m_axesPromise->set_value(error);
    m_axesPromise.reset();
  }

  // --- the port -------------------------------------------------------------------------------------------

  void closePort() {
    std::lock_guard<std::mutex> writeLock(m_writeMutex);
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
  }

  // Worker: opens the device, or notes why not. True once open.
  bool openPort() {
    core::Result<int> opened = serial::openRaw(m_settings.devicePath, m_settings.baud);
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!opened) {
      m_status.link = m_status.polls == 0 ? LinkState::Connecting : LinkState::Reconnecting;
      m_status.lastError = opened.error().describe();
      m_threads.reportFirst(opened.error());
      return false;
    }
    {
      std::lock_guard<std::mutex> writeLock(m_writeMutex);
      m_fd = *opened;
    }
    m_openedAt = Clock::now();
    m_rx.clear();
    m_unknownSinceRead = 0;
    m_oksSinceRead = 0;
    m_bareTemperaturePolls = 0;
    m_ledger.forgetPrinter();
    // A stop latched before (or while) the port was closed is written again first: the printer may have
    // restarted meanwhile.
    if (m_stop.latched()) {
      m_stop.markDue();
      m_threads.stopWake().notify_all();
    }
    return true;
  }

  // Never called with m_mutex held (the lock order is m_mutex, then m_writeMutex).
  core::Status sendRaw(const std::string& text) {
    std::lock_guard<std::mutex> writeLock(m_writeMutex);
    if (m_fd < 0)
      return core::Error{core::ErrorCode::DeviceUnreachable, "the serial port is not open (reconnecting)", m_name};
    return serial::writeAll(m_fd, text, m_options.requestTimeout);
  }

  // --- the worker -----------------------------------------------------------------------------------------

  void runWorker() {
    auto nextOpen = Clock::now();
    const auto reopenEvery = std::max<std::chrono::milliseconds>(m_options.pollInterval, 50ms);
    while (true) {
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_threads.quitting()) return;
      }
      int fd = -1;
      {
        std::lock_guard<std::mutex> writeLock(m_writeMutex);
        fd = m_fd;
      }
      if (fd < 0) {
        if (Clock::now() < nextOpen) {
          std::unique_lock<std::mutex> lock(m_mutex);
          m_threads.workerWake().wait_until(lock, nextOpen, [this] { return m_threads.quitting(); });
          continue;
        }
        nextOpen = Clock::now() + reopenEvery;
        if (!openPort()) continue;
        std::lock_guard<std::mutex> writeLock(m_writeMutex);
        fd = m_fd;
      }
      pollfd p{fd, POLLIN, 0};
      const int ready = ::poll(&p, 1, 2);
      if (ready > 0 && (p.revents & POLLIN) != 0) {
        if (!readAvailable(fd)) {
          lose("the serial device stopped answering reads");
          continue;
        }
      } else if (ready > 0 && (p.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0) {
        lose("the serial device went away (unplugged or switched off?)");
        continue;
      }
      runCommands();
      checkSilence();
      pump();
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_threads.firstReported() && Clock::now() - m_openedAt > 2 * m_options.linkLostAfter) {
        const std::string seen = m_unknownSinceRead > 0
                                     ? " (only lines that are not Marlin's protocol came back, the last " +
                                           marlin::quoted(m_lastUnknown) + ")"
                                 : m_oksSinceRead > 0 ? " (it answered ok, but never with its temperatures)"
                                                      : std::string();
        m_threads.reportFirst(core::Error{
            core::ErrorCode::DeviceUnreachable,
            "no answer from the printer within " + std::to_string(2 * m_options.linkLostAfter.count()) +
                " ms of opening " + m_settings.devicePath + " at " + std::to_string(m_settings.baud) + " baud" + seen +
                ": check the baud rate (Marlin's BAUDRATE, often 115200 or 250000), that "
                "the printer is on, and that no other program uses the port",
            m_name});
      }
    }
  }

  void lose(const std::string& why) {
    closePort();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_status.link = LinkState::Reconnecting;
    m_status.lastError = why + ": " + m_settings.devicePath;
    if (m_job) {
      // The stream is cut: Marlin empties its buffer and stops; most boards restart when the port reopens.
      m_status.state = PrinterJobState::Error;
      m_status.message = "the serial link was lost while " + m_job->name + " streamed (" + why +
                         "): the printer stopped after the lines it had";
      m_job.reset();
      failJobPromises(core::Error{core::ErrorCode::DeviceUnreachable, m_status.message, m_name});
    }
    m_threads.reportFirst(core::Error{core::ErrorCode::DeviceUnreachable, m_status.lastError, m_name});
  }

  // False on a read error (the device is gone).
  bool readAvailable(int fd) {
    char buffer[512];
    while (true) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n > 0) {
        m_rx.append(buffer, static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) break;
      return false;  // 0 (hang-up) or an error such as EIO
    }
    std::size_t end = 0;
    while ((end = m_rx.find_first_of("\r\n")) != std::string::npos) {
      const std::string line = m_rx.substr(0, end);
      m_rx.erase(0, end + 1);
      if (!line.empty()) onLine(line);
    }
    if (m_rx.size() > 4096) m_rx.clear();  // noise without line ends (a wrong baud rate)
    return true;
  }

  // Liveness: only lines of Marlin's protocol say the printer answers (noise says nothing), and only status
  // reads (temperatures, M114's position, busy) keep status().linkLost false: oks alone tell nothing of its state.
  void onLine(const std::string& text) {
    const marlin::Reply reply = marlin::parseReply(text);
    std::lock_guard<std::mutex> lock(m_mutex);
    if (reply.kind == marlin::Reply::Kind::Unknown) {
      ++m_unknownSinceRead;
      m_lastUnknown = text;
      warn("the printer sent a line that is not Marlin's protocol: " + marlin::quoted(text) +
           " (not taken as an answer)");
      return;
    }
    m_lastProtocolLine = Clock::now();
    m_status.link = LinkState::Connected;
    if (reply.extruder || reply.bed) {
      if (reply.extruder) m_status.extruder = *reply.extruder;
      if (reply.bed) m_status.bed = *reply.bed;
      m_lastTemperature = Clock::now();
      m_bareTemperaturePolls = 0;
      noteStatusRead();
      if (m_status.firmwareState.empty()) m_status.firmwareState = "ready";
      if (m_status.state == PrinterJobState::Unknown) m_status.state = PrinterJobState::Standby;
      m_status.lastError.clear();
      m_threads.reportFirst(core::Done{});
    }
    switch (reply.kind) {
      case marlin::Reply::Kind::Ok:
        onOk(reply);
        break;
      case marlin::Reply::Kind::Position:
        onPosition(text);
        break;
      case marlin::Reply::Kind::Resend:
        onResend(reply.resendLine);
        break;
      case marlin::Reply::Kind::LineError:
        m_status.lastError = "the printer asked for a line again: " + reply.text;
        ++m_resends;
        break;
      case marlin::Reply::Kind::Fault:
        onFault(reply.text, reply.killed);
        break;
      case marlin::Reply::Kind::Action:
        onAction(reply.text);
        break;
      case marlin::Reply::Kind::Busy:
        // Marlin's keepalive while a command blocks (M109, G28, M400, a move waiting for room in the planner):
        // the printer is working on what it was sent. A status read once its state was read at all.
        if (m_status.polls > 0) noteStatusRead();
        break;
      case marlin::Reply::Kind::Info:
        if (text == "start" && m_ledger.numberingReady()) onRestart();
        break;
      case marlin::Reply::Kind::Unknown:
        break;
    }
  }

  // m_mutex held: a line that tells the printer's state arrived.
  void noteStatusRead() {
    m_status.lastReply = m_options.steadyNow();
    ++m_status.polls;
    m_unknownSinceRead = 0;
    m_oksSinceRead = 0;
  }

  // m_mutex held: a line the link cannot account for; it goes on without it.
  void warn(const std::string& what) {
    ++m_status.protocolWarnings;
    m_status.lastWarning = what;
  }

  // m_mutex held: why status().linkLost, when the printer still sends lines ("" when it sends none).
  std::string notAnsweringReason() const {
    if (m_bareTemperaturePolls >= kBareTemperaturePollsLimit)
      return "the printer answered its last " + std::to_string(m_bareTemperaturePolls) +
             " temperature polls (M105) with a bare ok and no temperature report: its state cannot be read, so it "
             "counts as not answering; check that the device is a Marlin printer and that nothing else answers on "
             "its port";
    const std::string since = " for " + std::to_string(m_options.linkLostAfter.count()) + " ms";
    if (m_unknownSinceRead > 0)
      return "the printer is not answering: " + std::to_string(m_unknownSinceRead) +
             " lines that are not Marlin's protocol came" + since + " and nothing else (the last " +
             marlin::quoted(m_lastUnknown) +
             "): check the baud rate (Marlin's BAUDRATE, often 115200 or 250000) and the cable";
    if (m_oksSinceRead > 0)
      return "the printer is not answering: it sent oks but no temperature, position or busy report" + since +
             ", so its state cannot be read";
    return {};
  }

  // m_mutex held: the ledger says which line in flight the ok answers (marlin_line_ledger.h); an ok that
  // answers none is a protocol warning and counts for nothing.
  void onOk(const marlin::Reply& reply) {
    if (!reply.extruder && !reply.bed) ++m_oksSinceRead;
    const marlin::LineLedger::OkOutcome outcome = m_ledger.onOk(reply, [this](const Line& line) { acknowledge(line); });
    if (outcome.barePoll) ++m_bareTemperaturePolls;
    if (!outcome.warning.empty()) warn(outcome.warning);
  }

  // m_mutex held: M114's position report. After the job's M114 was written it ends the job: Marlin ran the M400
  // before it, so the planner was empty and every move of the step done.
  void onPosition(const std::string& text) {
    noteStatusRead();
    if (m_axesPromise && m_axesQueried && !m_job) {
      m_axesPromise->set_value(axesOfPositionReport(text));
      m_axesPromise.reset();
      return;
    }
    if (!m_job || !m_job->reportSent || m_job->cancelling) return;
    m_status.state = PrinterJobState::Complete;
    m_status.progress = 1.0;
    m_job.reset();
  }

  // m_mutex held: the printer took `line` (the oldest in flight).
  void acknowledge(const Line& line) {
    switch (line.role) {
      case Role::Reset:
        if (m_job && m_startPromise) {
          m_status.state = PrinterJobState::Printing;
          m_status.currentFile = m_job->name;
          m_status.progress = 0.0;
          m_status.message.clear();
          noteStatusRead();  // the start's answer is a status read of its own
          m_startPromise->set_value(core::Done{});
          m_startPromise.reset();
        }
        break;
      case Role::Poll:
        break;
      case Role::File:
        if (m_job) {
          m_job->acknowledged = std::max(m_job->acknowledged, line.fileLine + 1);
          m_status.progress = m_job->lines.empty()
                                  ? 1.0
                                  : static_cast<double>(m_job->acknowledged) / static_cast<double>(m_job->lines.size());
        }
        break;
      case Role::JobEnd:  // the job ends with M114's report (onPosition)
      case Role::JobEndReport:
        break;
      case Role::CoolDown:
        break;
      case Role::HeatersOff:
      case Role::AxesReport:  // answered by its report (onPosition)
        break;
      case Role::HeatersOffEnd:
        m_heatersOffQueued = 0;
        if (m_heatersOffPromise) m_heatersOffPromise->set_value(core::Done{});
        m_heatersOffPromise.reset();
        break;
      case Role::CoolDownEnd:
        m_status.state = PrinterJobState::Cancelled;
        noteStatusRead();
        m_job.reset();
        if (m_cancelPromise) m_cancelPromise->set_value(core::Done{});
        m_cancelPromise.reset();
        break;
    }
  }

  // m_mutex held: the printer refused line n (bad checksum, wrong number) and every line after it.
  void onResend(long n) {
    if (std::string problem = m_ledger.onResend(n, [this](const Line& line) { acknowledge(line); }); !problem.empty())
      m_status.lastError = std::move(problem);
  }

  // m_mutex held: Marlin stopped (its own words), or halted after an M112.
  void onFault(const std::string& text, bool killed) {
    if (m_status.firmwareState != "halted") {
      m_status.firmwareState = "halted";
      m_status.message = text;
    } else if (m_status.message.find(text) == std::string::npos) {
      m_status.message += "; " + text;
    }
    m_status.state = PrinterJobState::Error;
    m_status.lastError = "the printer reports: " + text;
    m_job.reset();
    failJobPromises(core::Error{core::ErrorCode::DeviceFault, "the printer stopped: " + m_status.message, m_name});
    if (killed && m_stop.latched() && !m_stop.state().confirmed) confirmStop(m_stop.generation());
  }

  // m_mutex held: host action commands Marlin sends when the job is handled at the printer.
  void onAction(const std::string& action) {
    if (action == "cancel" && m_job) {
      m_job.reset();
      m_status.state = PrinterJobState::Cancelled;
      failJobPromises(core::Error{core::ErrorCode::DeviceFault, "the job was cancelled at the printer", m_name});
    } else if (action == "pause" && m_status.state == PrinterJobState::Printing) {
      m_status.state = PrinterJobState::Paused;
    } else if (action == "resume" && m_status.state == PrinterJobState::Paused && m_job) {
      m_status.state = PrinterJobState::Printing;
    }
  }

  // m_mutex held: the printer printed "start" again: it restarted (reset button, power, watchdog).
  void onRestart() {
    if (m_job) {
      m_status.state = PrinterJobState::Error;
      m_status.message = "the printer restarted while " + m_job->name + " streamed";
      m_job.reset();
      failJobPromises(core::Error{core::ErrorCode::DeviceFault, m_status.message, m_name});
    } else if (m_status.firmwareState == "halted") {
      m_status.firmwareState = "ready";
      m_status.state = PrinterJobState::Standby;
      m_status.message.clear();
    }
    m_bareTemperaturePolls = 0;
    m_ledger.forgetPrinter();  // the firmware may be another one now
  }

  // m_mutex held: the printer's halt confirms the stop sent as `generation`.
  void confirmStop(std::uint64_t generation) {
    m_stop.confirm(generation);
    m_threads.stopWake().notify_all();
  }

  // The queued commands, in order; start and cancel finish later, when the printer answered their lines.
  void runCommands() {
    std::unique_lock<std::mutex> lock(m_mutex);
    if (m_dropJob) {
      m_dropJob = false;
      m_job.reset();
      failJobPromises(core::Error{core::ErrorCode::Cancelled, "cancelled by the emergency stop", m_name});
    }
    while (!m_queue.empty()) {
      // A start, cancel or heaters-off in progress holds later commands back.
      if (m_startPromise || m_cancelPromise || m_heatersOffPromise) return;
      Pending pending = std::move(m_queue.front());
      m_queue.pop_front();
      if (pending.command == Command::Upload) {
        lock.unlock();  // reading a large file does not hold the status
        core::Result<std::vector<std::string>> lines = readJobFile(pending.localPath, pending.checkedSha256);
        lock.lock();
        if (!lines) {
          pending.promise.set_value(lines.error());
          continue;
        }
        m_files[pending.remoteName] = std::move(*lines);
        pending.promise.set_value(core::Done{});
        continue;
      }
      const core::Status refusal = refusalOf(pending);
      if (!refusal.ok()) {
        m_status.lastError = refusal.error().describe();
        pending.promise.set_value(refusal);
        continue;
      }
      switch (pending.command) {
        case Command::Start: {
          Job job;
          job.name = pending.remoteName;
          job.lines = m_files[pending.remoteName];
          m_job = std::move(job);
          m_startPromise = std::move(pending.promise);
          m_resetDue = true;  // number the job from N0 once the window is empty
          break;
        }
        case Command::Pause:
          m_status.state = PrinterJobState::Paused;
          pending.promise.set_value(core::Done{});
          break;
        case Command::Resume:
          m_status.state = PrinterJobState::Printing;
          pending.promise.set_value(core::Done{});
          break;
        case Command::Cancel:
          m_job->cancelling = true;
          m_cancelPromise = std::move(pending.promise);
          break;
        case Command::HeatersOff:
          m_heatersOffQueued = 0;
          m_heatersOffPromise = std::move(pending.promise);
          break;
        case Command::Upload:
          break;
      }
    }
  }

  // m_mutex held: why the printer cannot take the command now ("" status: it can).
  core::Status refusalOf(const Pending& pending) const {
    const bool halted = m_status.firmwareState == "halted";
    if (halted && pending.command != Command::Cancel && pending.command != Command::Pause)
      return core::Error{core::ErrorCode::DeviceFault,
                         "the printer is halted (" + m_status.message +
                             "): reset it (its reset button, or switch it off and on) and reconnect",
                         m_name};
    const bool busy = m_status.state == PrinterJobState::Printing || m_status.state == PrinterJobState::Paused;
    switch (pending.command) {
      case Command::Start:
        if (m_files.count(pending.remoteName) == 0)
          return invalid("no G-code named " + pending.remoteName + " was loaded: upload it first", m_name);
        if (busy || m_job)
          return invalid("the printer is busy with " + m_status.currentFile + ": " + pending.what + " was refused",
                         m_name);
        if (m_status.polls == 0)
          return core::Error{core::ErrorCode::DeviceUnreachable,
                             "the printer has not answered yet: " + pending.what + " was not sent", m_name};
        return core::Done{};
      case Command::Pause:
        if (!m_job || m_status.state != PrinterJobState::Printing)
          return invalid("no job is printing: nothing to pause", m_name);
        return core::Done{};
      case Command::Resume:
        if (!m_job || m_status.state != PrinterJobState::Paused)
          return invalid("no job is paused: nothing to resume", m_name);
        return core::Done{};
      case Command::Cancel:
        if (!m_job || m_job->cancelling) return invalid("no job is printing: nothing to cancel", m_name);
        return core::Done{};
      case Command::HeatersOff:
        // Streamed between the job's lines they would be overridden by the job's own heater commands.
        if (m_job)
          return invalid(
              "a job is streaming (" + m_job->name + "): cancel it first (the cancel switches the heaters off too)",
              m_name);
        return core::Done{};
      case Command::Upload:
        return core::Done{};
    }
    return core::Done{};
  }

  // The file is read once (readGcodeToSend checks it is what was checked); its lines are what is streamed.
  core::Result<std::vector<std::string>> readJobFile(const std::string& path, const std::string& checkedSha256) const {
    const core::Result<std::string> content = readGcodeToSend(path, checkedSha256, "stream");
    if (!content) return content.error();
    std::istringstream in(*content);
    std::vector<std::string> lines;
    std::string raw;
    while (std::getline(in, raw)) {
      std::string command = marlin::commandOf(raw);
      if (command.empty()) continue;
      // A '*' inside a command would be taken for the checksum; Marlin reads up to the last '*'.
      if (command.find('*') != std::string::npos)
        return core::Error{core::ErrorCode::InvalidParameter,
                           "line '" + raw + "' contains '*', which Marlin's line checksum forbids: remove it", path};
      lines.push_back(std::move(command));
    }
    return lines;
  }

  // No line in Marlin's protocol for linkLostAfter while lines are in flight (noise does not count): their oks
  // (or the lines) were lost: send them again. Marlin answers a line it had with "Resend: <next>", so nothing is
  // done twice.
  void checkSilence() {
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto now = Clock::now();
    if (m_ledger.inFlight() <= 0) return;
    const auto since = std::max(m_lastProtocolLine, std::max(m_lastSend, m_lastSilenceResend));
    if (now - since < m_options.linkLostAfter) return;
    m_lastSilenceResend = now;
    const long again = m_ledger.resendAfterSilence();
    m_status.lastError = "no answer from the printer for " + std::to_string(m_options.linkLostAfter.count()) +
                         " ms: sending line " + std::to_string(again) + " again";
  }

  // Sends what the window allows: lines to resend, then the job's next line or a temperature poll.
  void pump() {
    while (true) {
      std::string text;
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_status.firmwareState == "halted") return;
        if (m_ledger.inFlight() >= m_settings.maxUnacknowledgedLines) return;
        if (!m_ledger.hasUnsent() && !appendNextLine()) return;
        const long number = m_ledger.sendNext();
        const Line& line = m_ledger.line(number);
        if (line.role == Role::JobEndReport && m_job) m_job->reportSent = true;
        text = marlinNumberedLine(number, line.command) + "\n";
        m_lastSend = Clock::now();
      }
      if (const core::Status sent = sendRaw(text); !sent.ok()) {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_status.lastError = sent.error().describe();
        return;
      }
    }
  }

  // m_mutex held: numbers the next line to send, if any is due. Never while the job's reset waits.
  bool appendNextLine() {
    if (!m_ledger.numberingReady()) return false;  // N0 M110 is in flight: wait for its ok
    // Idle polls number lines too: start again from N0 now and then, so the history kept for resends stays small.
    if (!m_job && m_ledger.numbered() > kRenumberAfterLines) m_resetDue = true;
    if (m_resetDue) {
      if (m_ledger.inFlight() != 0) return false;
      m_resetDue = false;
      m_ledger.renumber();  // the next line is N0 M110 N0
      return true;
    }
    const auto now = Clock::now();
    const bool pollDue =
        now - m_lastTemperature >= m_options.pollInterval && now - m_lastPollSent >= m_options.pollInterval;
    if (m_job && m_status.state == PrinterJobState::Printing && !m_stop.latched()) {
      // At most one poll between two job lines: when a round trip takes longer than pollInterval (a loaded
      // machine, a slow printer) a poll is always due, and polls alone would hold the job (and a cancel) up.
      if (pollDue && !m_pollSentLast) return appendPoll(now);
      m_pollSentLast = false;
      Job& job = *m_job;
      if (job.cancelling) {
        const std::size_t count = sizeof kCancelLines / sizeof kCancelLines[0];
        if (job.coolDownQueued >= count) return false;
        const Role role = job.coolDownQueued + 1 == count ? Role::CoolDownEnd : Role::CoolDown;
        m_ledger.append(Line{kCancelLines[job.coolDownQueued++], role, 0});
        return true;
      }
      if (job.nextFileLine < job.lines.size()) {
        m_ledger.append(Line{job.lines[job.nextFileLine], Role::File, job.nextFileLine});
        ++job.nextFileLine;
        return true;
      }
      if (!job.endQueued) {
        job.endQueued = true;
        m_ledger.append(Line{"M400", Role::JobEnd, 0});  // Marlin takes the next command once every move is done
        return true;
      }
      if (!job.reportQueued) {
        job.reportQueued = true;
        m_ledger.append(Line{"M114", Role::JobEndReport, 0});  // its report: the M400 before it is done
        return true;
      }
      return false;
    }
    if (m_job && m_job->cancelling) {
      // Cancelling a paused job: the cool-down lines go out although no file line does.
      const std::size_t count = sizeof kCancelLines / sizeof kCancelLines[0];
      if (m_job->coolDownQueued < count) {
        const Role role = m_job->coolDownQueued + 1 == count ? Role::CoolDownEnd : Role::CoolDown;
        m_ledger.append(Line{kCancelLines[m_job->coolDownQueued++], role, 0});
        return true;
      }
    }
    if (!m_job && m_axesPromise && !m_axesQueried) {
      m_axesQueried = true;
      m_ledger.append(Line{"M114", Role::AxesReport, 0});
      return true;
    }
    if (!m_job && m_heatersOffPromise) {
      const std::size_t count = sizeof kHeatersOffLines / sizeof kHeatersOffLines[0];
      if (m_heatersOffQueued < count) {
        const Role role = m_heatersOffQueued + 1 == count ? Role::HeatersOffEnd : Role::HeatersOff;
        m_ledger.append(Line{kHeatersOffLines[m_heatersOffQueued++], role, 0});
        return true;
      }
    }
    if (pollDue) return appendPoll(now);
    return false;
  }

  bool appendPoll(Clock::time_point now) {
    m_lastPollSent = now;
    m_pollSentLast = true;
    m_ledger.append(Line{"M105", Role::Poll, 0});
    return true;
  }

  // --- the stop thread ------------------------------------------------------------------------------------

  void runStopper() {
    while (true) {
      std::uint64_t generation = 0;
      bool haltedBefore = false;
      {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_threads.stopWake().wait(lock, [this] { return m_threads.quitting() || m_stop.due(); });
        if (m_threads.quitting()) return;
        generation = m_stop.take();
        haltedBefore = m_haltedBeforeStop;
      }
      // Outside the numbering: Marlin's emergency parser acts on M112 as it arrives, even with a full buffer.
      // The leading line end ends a line a failed write may have cut short (the parser skips to the next line).
      const core::Status sent = sendRaw("\nM112\n");
      std::unique_lock<std::mutex> lock(m_mutex);
      if (!sent.ok()) {
        m_stop.setProblem("M112 not written: " + sent.error().message);
      } else if (haltedBefore) {
        // Marlin was already halted (a kill before this stop) and answers nothing more: the state shows it.
        confirmStop(generation);
      } else if (!m_stop.state().confirmed) {
        m_stop.setProblem("M112 sent; waiting for the printer to report its halt");
      }
      const bool answered = m_threads.stopWake().wait_for(lock, m_options.stopRetryInterval, [&] {
        return m_threads.quitting() || (m_stop.state().confirmed && generation == m_stop.generation()) ||
               generation != m_stop.generation();
      });
      if (m_threads.quitting()) return;
      (void)answered;
      if (m_stop.latched() && !m_stop.state().confirmed) m_stop.markDue();  // resend until the printer answers
    }
  }

  MarlinSettings m_settings;
  PrinterLinkOptions m_options;
  std::string m_name;

  mutable std::mutex m_mutex;  // everything below but the port
  PrinterLinkThreads m_threads{m_mutex};
  std::deque<Pending> m_queue;
  PrinterStatus m_status;  // but its stop, which is m_stop's
  LatchedEmergencyStop m_stop;
  bool m_haltedBeforeStop = false;
  bool m_dropJob = false;

  // The stream (worker, under m_mutex): every line numbered since the last M110, for resends.
  marlin::LineLedger m_ledger;
  bool m_resetDue = false;
  std::uint64_t m_resends = 0;
  // Since the last status read (temperatures, position, busy): lines that were not the protocol, and oks.
  std::uint64_t m_unknownSinceRead = 0;
  std::uint64_t m_oksSinceRead = 0;
  std::string m_lastUnknown;
  int m_bareTemperaturePolls = 0;  // M105s answered with a bare ok since the last temperature report
  std::map<std::string, std::vector<std::string>> m_files;
  std::optional<Job> m_job;
  std::optional<std::promise<core::Status>> m_startPromise;
  std::optional<std::promise<core::Status>> m_cancelPromise;
  std::optional<std::promise<core::Status>> m_heatersOffPromise;
  std::optional<std::promise<core::Result<FirmwareAxes>>> m_axesPromise;  // readFirmwareAxes(), until M114's report
  bool m_axesQueried = false;                                             // ... and its M114 is numbered
  std::size_t m_heatersOffQueued = 0;  // of kHeatersOffLines numbered so far
  Clock::time_point m_openedAt{};
  Clock::time_point m_lastProtocolLine{};  // the last line in Marlin's protocol (worker clock)
  Clock::time_point m_lastSend{};
  Clock::time_point m_lastSilenceResend{};
  Clock::time_point m_lastTemperature{};
  Clock::time_point m_lastPollSent{};
  bool m_pollSentLast = false;  // the last line appended while printing was a poll
  std::string m_rx;             // worker only: bytes after the last line end

  std::mutex m_writeMutex;  // the descriptor and every write: whole lines never interleave
  int m_fd = -1;
};

}  // namespace

core::Result<std::unique_ptr<PrinterLink>> makeMarlinLink(const MarlinSettings& settings,
                                                          const PrinterLinkOptions& options) {
  if (settings.devicePath.empty()) return invalid("the printer's serial device path is empty", "printer");
  if (!serial::supportedRate(settings.baud))
    return invalid(std::to_string(settings.baud) + " baud is not a rate the serial port can be set to", "printer");
  if (settings.maxUnacknowledgedLines < 1 || settings.maxUnacknowledgedLines > 4)
    return invalid("the window of unacknowledged lines must be 1 to 4 (Marlin's command buffer)", "printer");
  if (core::Status valid = validate(options); !valid) return valid.error();
  return std::unique_ptr<PrinterLink>(std::make_unique<MarlinLink>(settings, options));
}

}  // namespace multidir::hardware
