#include "printer/marlin_line_ledger.h"

#include <algorithm>

namespace multidir::hardware::marlin {

void LineLedger::renumber() {
  m_lines.clear();
  m_lines.push_back(StreamLine{"M110 N0", LineRole::Reset, 0});
  m_sentUpTo = -1;
  m_ackedUpTo = -1;
  m_oksToSkip = 0;
  m_resentAfterSilence = false;
}

void LineLedger::forgetPrinter() {
  m_advancedOk = false;
  renumber();
}

std::string LineLedger::inFlightText() const {
  if (m_sentUpTo <= m_ackedUpTo) return "no line is";
  if (m_sentUpTo == m_ackedUpTo + 1) return "line " + std::to_string(m_sentUpTo) + " is";
  return "lines " + std::to_string(m_ackedUpTo + 1) + " to " + std::to_string(m_sentUpTo) + " are";
}

void LineLedger::acknowledgeNext(const Acknowledge& acknowledge) {
  ++m_ackedUpTo;
  acknowledge(line(m_ackedUpTo));
}

LineLedger::OkOutcome LineLedger::onOk(const Reply& ok, const Acknowledge& acknowledge) {
  OkOutcome outcome;
  if (m_oksToSkip > 0) {  // the ok that follows a Resend answers the refused line, not a new one
    --m_oksToSkip;
    return outcome;
  }
  m_resentAfterSilence = false;
  if (ok.okLine >= 0) {
    m_advancedOk = true;
    if (ok.okLine <= m_ackedUpTo || ok.okLine > m_sentUpTo) {
      outcome.warning = "the printer sent an ok for line " + std::to_string(ok.okLine) +
                        ", which answers no line in flight (" + inFlightText() + "): not counted";
      return outcome;
    }
    while (m_ackedUpTo < ok.okLine) {
      acknowledgeNext(acknowledge);
      ++outcome.acknowledged;
    }
    return outcome;
  }
  if (m_ackedUpTo >= m_sentUpTo) {
    outcome.warning = "the printer sent an ok that answers no line in flight (" + inFlightText() + "): not counted";
    return outcome;
  }
  const bool temperatures = ok.extruder || ok.bed;
  const bool poll = line(m_ackedUpTo + 1).role == LineRole::Poll;
  // Marlin answers M105 itself, without ADVANCED_OK's number; any other ok without a number from a printer whose
  // oks carry one answers no line.
  if (m_advancedOk && !temperatures && !poll) {
    outcome.warning =
        "the printer sent an ok without the line number its oks carry (ADVANCED_OK), which answers "
        "no line in flight (" +
        inFlightText() + "): not counted";
    return outcome;
  }
  outcome.barePoll = poll && !temperatures;
  acknowledgeNext(acknowledge);
  outcome.acknowledged = 1;
  return outcome;
}

std::string LineLedger::onResend(long n, const Acknowledge& acknowledge) {
  ++m_oksToSkip;
  // A damaged "N0 M110 N0" never reset the printer's numbering, so it asks for the next line of the old one:
  // the reset goes again (Marlin takes an M110 whatever its number).
  if (m_ackedUpTo < m_sentUpTo && line(m_ackedUpTo + 1).role == LineRole::Reset) {
    m_sentUpTo = m_ackedUpTo;
    return {};
  }
  if (n < 0 || n > static_cast<long>(m_lines.size()) || n <= m_ackedUpTo)
    return "the printer asked for line " + std::to_string(n) + ", which this link did not send";
  // After a silence the oks of the lines in flight may be lost, not the lines: the printer naming the line it
  // wants says which it had.
  if (m_resentAfterSilence)
    while (m_ackedUpTo < n - 1 && m_ackedUpTo + 1 < static_cast<long>(m_lines.size())) acknowledgeNext(acknowledge);
  m_resentAfterSilence = false;
  m_sentUpTo = std::max(m_ackedUpTo, std::min(m_sentUpTo, n - 1));
  return {};
}

long LineLedger::resendAfterSilence() {
  m_resentAfterSilence = true;
  m_sentUpTo = m_ackedUpTo;
  return m_ackedUpTo + 1;
}

}  // namespace multidir::hardware::marlin
