#include "progress_line.h"

#include <algorithm>

namespace multidir::cli {

void ProgressLine::show(double fraction, const std::string& phase) {
  std::lock_guard<std::mutex> lock(m_mutex);
  fraction = std::clamp(fraction, 0.0, 1.0);
  const int percent = static_cast<int>(fraction * 100.0 + 0.5);
  if (!m_terminal) {
    const int tenth = percent / 10;
    if (tenth == m_lastTenth) return;
    m_lastTenth = tenth;
    m_err << percent << "% " << phase << "\n" << std::flush;
    return;
  }
  const int filled = static_cast<int>(fraction * 30.0 + 0.5);
  m_err << "\r\033[K[" << std::string(static_cast<std::size_t>(filled), '#')
        << std::string(static_cast<std::size_t>(30 - filled), '.') << "] " << percent << "% " << phase << std::flush;
  m_drawn = true;
}

void ProgressLine::clear() {
  std::lock_guard<std::mutex> lock(m_mutex);
  if (m_terminal && m_drawn) m_err << "\r\033[K" << std::flush;
  m_drawn = false;
}

}  // namespace multidir::cli
