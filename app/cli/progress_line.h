#pragma once
// A command's progress on stderr. On a terminal one status line is redrawn in place ("\r", erase to the end of
// the line); anywhere else (a file, a pipe, a CI log) no terminal escapes at all: a plain line each time the
// progress passes another tenth, so logs stay readable.
#include <mutex>
#include <ostream>
#include <string>

namespace multidir::cli {

class ProgressLine {
 public:
  // `terminal`: whether `err` is a terminal (isatty(STDERR_FILENO) for std::cerr).
  ProgressLine(std::ostream& err, bool terminal) : m_err(err), m_terminal(terminal) {}

  // Thread-safe. "[#########.....................] 30% slicing step 1 (45 %) ..." on a terminal, else
  // "30% slicing step 1 (45 %) ..." once per tenth.
  void show(double fraction, const std::string& phase);
  // Removes the drawn line (a terminal only), before the command writes its own lines.
  void clear();

 private:
  std::mutex m_mutex;
  std::ostream& m_err;
  bool m_terminal = false;
  bool m_drawn = false;
  int m_lastTenth = -1;
};

}  // namespace multidir::cli
