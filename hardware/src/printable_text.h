#pragma once
// Text from outside MultiDir (a printer's words, a file name from a job) made safe to log, show and put into
// a request: every control character (C0 and DEL) is written as an escape ("\r", "\n", "\t", "\x1b"), so that
// no name or reply can add a line to the log, a header to a request, or colour, move or clear a terminal.
#include <string>

namespace multidir::hardware {

[[nodiscard]] std::string escapeControls(const std::string& text);
[[nodiscard]] bool hasControls(const std::string& text);

}  // namespace multidir::hardware
