#include "printer/marlin_protocol.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "multidir/hardware/marlin_link.h"
#include "printer/plausible_reading.h"

namespace multidir::hardware {

int marlinChecksum(const std::string& text) {
  unsigned char sum = 0;
  for (const char c : text) sum ^= static_cast<unsigned char>(c);
  return sum;
}

std::string marlinNumberedLine(long number, const std::string& command) {
  const std::string body = "N" + std::to_string(number) + " " + command;
  return body + "*" + std::to_string(marlinChecksum(body));
}

namespace marlin {
namespace {


bool startsWith(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// "T:210.0 /215.0" at `key` ("T:" or "B:") as a word of its own (not "T0:" nor "B@:").
std::optional<HeaterReading> heater(const std::string& line, const char* key) {
  std::size_t at = 0;
  while ((at = line.find(key, at)) != std::string::npos) {
    if (at == 0 || line[at - 1] == ' ') break;
    ++at;
  }
  if (at == std::string::npos) return std::nullopt;
  const char* start = line.c_str() + at + std::strlen(key);
  char* end = nullptr;
  const double actual = std::strtod(start, &end);
  // Line noise like "T:nan" or "T:1e308" is no reading (plausible_reading.h).
  if (end == start || !plausibleCelsius(actual)) return std::nullopt;
  HeaterReading reading;
  reading.actualC = actual;
  const char* slash = end;
  while (*slash == ' ') ++slash;
  if (*slash == '/') {
    const double target = std::strtod(slash + 1, &end);
    if (end != slash + 1) {
      if (!plausibleCelsius(target)) return std::nullopt;
      reading.targetC = target;
    }
  }
  return reading;
}

}  // namespace

std::string commandOf(const std::string& fileLine) {
  std::string code = fileLine;
  if (const std::size_t semicolon = code.find(';'); semicolon != std::string::npos) code.resize(semicolon);
  const std::size_t first = code.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const std::size_t last = code.find_last_not_of(" \t\r");
  return code.substr(first, last - first + 1);
}

Reply parseReply(const std::string& rawLine) {
  std::string line = rawLine;
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  Reply reply;
  reply.extruder = heater(line, "T:");
  reply.bed = heater(line, "B:");
  reply.killed = line.find("kill() called") != std::string::npos || line.find("Printer halted") != std::string::npos;
  std::size_t first = line.find_first_not_of(' ');
  if (first == std::string::npos) first = line.size();
  const std::string trimmed = line.substr(first);
  if (line == "ok" || startsWith(line, "ok ")) {
    reply.kind = Reply::Kind::Ok;
    // ADVANCED_OK: "ok N<line> P<planner free> B<buffer free>"; Marlin echoes the N of the line it executed.
    if (startsWith(line, "ok N")) {
      char* end = nullptr;
      const long number = std::strtol(line.c_str() + 4, &end, 10);
      if (end != line.c_str() + 4 && (*end == ' ' || *end == '\0') && number >= 0) reply.okLine = number;
    }
  } else if (startsWith(line, "Resend:") || startsWith(line, "rs ")) {
    reply.kind = Reply::Kind::Resend;
    const char* start = line.c_str() + (line[0] == 'R' ? 7 : 3);
    while (*start == ' ' || *start == 'N') ++start;
    char* end = nullptr;
    errno = 0;
    const long number = std::strtol(start, &end, 10);
    // -1 (no line this link sent) for a missing, negative or overflowing number: the link refuses it by name.
    reply.resendLine = end == start || errno == ERANGE || number < 0 ? -1 : number;
  } else if (startsWith(line, "Error:") || startsWith(line, "!!")) {
    reply.text = line.substr(line[0] == 'E' ? 6 : 2);
    while (!reply.text.empty() && reply.text.front() == ' ') reply.text.erase(0, 1);
    // Transmission errors: Marlin asks for the line again (a Resend and an ok follow).
    const bool lineError = reply.text.find("Last Line") != std::string::npos ||
                           startsWith(reply.text, "checksum mismatch") || startsWith(reply.text, "No Checksum") ||
                           startsWith(reply.text, "No Line Number") || startsWith(reply.text, "Line Number");
    reply.kind = lineError ? Reply::Kind::LineError : Reply::Kind::Fault;
  } else if (line.find("busy:") != std::string::npos) {
    reply.kind = Reply::Kind::Busy;
  } else if (startsWith(line, "//action:")) {
    reply.kind = Reply::Kind::Action;
    reply.text = line.substr(9);
    if (const std::size_t space = reply.text.find(' '); space != std::string::npos) reply.text.resize(space);
  } else if (startsWith(trimmed, "X:") && trimmed.find(" Y:") != std::string::npos &&
             trimmed.find(" Z:") != std::string::npos) {
    reply.kind = Reply::Kind::Position;
  } else if (startsWith(line, "echo:") || startsWith(line, "//") || line == "start" || line == "wait" ||
             startsWith(line, "Not SD printing") || startsWith(line, "FIRMWARE_NAME:") || startsWith(line, "Cap:") ||
             ((startsWith(trimmed, "T:") || startsWith(trimmed, "B:")) && (reply.extruder || reply.bed))) {
    reply.kind = Reply::Kind::Info;
  }
  // A reading inside a line that is not the protocol's is noise that happens to contain "T:".
  if (reply.kind == Reply::Kind::Unknown) {
    reply.extruder.reset();
    reply.bed.reset();
  }
  return reply;
}

std::string quoted(const std::string& line) {
  constexpr std::size_t kLongest = 60;
  std::string out;
  for (const char c : line.substr(0, kLongest)) out += c >= ' ' && c <= '~' ? c : '?';
  return "'" + out + (line.size() > kLongest ? "...'" : "'");
}

}  // namespace marlin
}  // namespace multidir::hardware
