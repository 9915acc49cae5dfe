#pragma once
// Marlin's numbered line stream as the host keeps it (docs/hardware.md, "Marlin (USB serial)"): every line
// numbered since the last "N0 M110 N0", how far they were sent, and which line each ok the printer writes
// answers. Marlin answers the lines it takes in order, one ok each, so an ok answers the oldest line in flight;
// with ADVANCED_OK it names its line ("ok N12 P15 B3") and answers that line and every line before it. An ok that
// answers no line in flight (more oks than lines, a number not in flight, a bare ok from a printer whose oks carry
// numbers) acknowledges nothing: counted, it would answer a later line early, and a job's last line would read
// done with moves still in the printer's planner.
//
// Not thread-safe: the link's worker holds its lock around every call.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "printer/marlin_protocol.h"

namespace multidir::hardware::marlin {

// What a numbered line is for, so the link can act on its ok. A job ends with M400 (JobEnd: Marlin takes no
// command after it until its planner is empty) and M114 (JobEndReport: its position report, which Marlin writes
// once the M400 is done, ends the job).
// AxesReport: an M114 asked between jobs for the axes the firmware has (PrinterLink::readFirmwareAxes).
enum class LineRole {
  Reset,
  Poll,
  File,
  JobEnd,
  JobEndReport,
  CoolDown,
  CoolDownEnd,
  HeatersOff,
  HeatersOffEnd,
  AxesReport
};

struct StreamLine {
  std::string command;
  LineRole role = LineRole::Poll;
  std::size_t fileLine = 0;  // File: index in the job's lines
};

class LineLedger {
 public:
  using Acknowledge = std::function<void(const StreamLine&)>;

  LineLedger() { renumber(); }

  // The numbering starts again: line 0 is "M110 N0" (Marlin's "set the current line number"), not sent yet.
  void renumber();
  // Another printer may answer from now on (the port reopened, the printer restarted): whether its oks carry
  // numbers is not known yet. Renumbers too.
  void forgetPrinter();
  void append(StreamLine line) { m_lines.push_back(std::move(line)); }

  [[nodiscard]] std::size_t numbered() const { return m_lines.size(); }
  [[nodiscard]] long inFlight() const { return m_sentUpTo - m_ackedUpTo; }
  [[nodiscard]] bool hasUnsent() const { return m_sentUpTo + 1 < static_cast<long>(m_lines.size()); }
  // The line 0 reset was answered: the printer counts from it.
  [[nodiscard]] bool numberingReady() const { return m_ackedUpTo >= 0; }
  // Marks the next unsent line sent (hasUnsent() must hold); its number.
  long sendNext() { return ++m_sentUpTo; }
  [[nodiscard]] const StreamLine& line(long number) const { return m_lines[static_cast<std::size_t>(number)]; }
  // "line 12 is", "lines 12 to 14 are", "no line is" (in flight), for messages.
  [[nodiscard]] std::string inFlightText() const;

  struct OkOutcome {
    int acknowledged = 0;   // lines the ok answered (acknowledge was called for each, in order)
    bool barePoll = false;  // it answered an M105 without the temperatures Marlin writes on M105's ok
    std::string warning;    // why it answered no line ("" when it answered one, or followed a Resend)
  };
  OkOutcome onOk(const Reply& ok, const Acknowledge& acknowledge);
  // "Resend: n": the printer refused line n (and drops what follows it); the ok after it answers no new line.
  // After a silence the printer naming the line it wants also says which lines it had: those are acknowledged.
  // A problem in words ("" when none).
  std::string onResend(long n, const Acknowledge& acknowledge);
  // No answer for a while with lines in flight: they go again (Marlin answers a line it already had with a Resend
  // of the next one, so nothing runs twice). The first line to go again.
  long resendAfterSilence();

 private:
  void acknowledgeNext(const Acknowledge& acknowledge);

  std::vector<StreamLine> m_lines;
  long m_sentUpTo = -1;
  long m_ackedUpTo = -1;
  int m_oksToSkip = 0;
  bool m_resentAfterSilence = false;
  bool m_advancedOk = false;  // the printer's oks name their line (ADVANCED_OK)
};

}  // namespace multidir::hardware::marlin
