#include "program_parts.h"

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "multidir/robot/robot_program.h"

namespace multidir::robot::detail {
namespace {

constexpr int kMaxParts = 999;  // the file names' three digits
// What ends every part but the last: the extruder stopped while the next part is sent and compiled.
const std::string kPartClosing = "  set_standard_analog_out(0, 0.000000)\nend\n";

std::string trimmed(const std::string& s) {
  const std::size_t first = s.find_first_not_of(' ');
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The number after `prefix` in a trimmed line that starts with it.
double numberAfter(const std::string& line, const std::string& prefix) {
  return std::strtod(line.c_str() + prefix.size(), nullptr);
}

// The statements from one move (exclusive) to the next (inclusive): what a part is made of.
struct Group {
  std::size_t begin = 0, end = 0;  // line indices [begin, end)
  std::size_t bytes = 0;
  bool idleStart = false;  // a part may start here: a travel movel or a re-orientation, the extruder stopped
  // ... and the move before was idle too (a travel's lift, or its move across): the part before ends with the
  // nozzle off the printed surface, where it waits, hot, while the next part is sent and compiled.
  bool offPartStart = false;
  int movel = 0;           // the register's number of its movel (0: a movej)
  // The step's state where the group begins (trimmed lines, "" when not set yet).
  std::string tcp, setPoint, fan;
};

struct Parsed {
  std::vector<std::string> lines;
  std::size_t headerEnd = 0, footerBegin = 0;
  std::vector<Group> groups;
};

std::size_t bytesOf(const std::vector<std::string>& lines, std::size_t begin, std::size_t end) {
  std::size_t bytes = 0;
  for (std::size_t i = begin; i < end; ++i) bytes += lines[i].size() + 1;
  return bytes;
}

core::Result<Parsed> parse(const std::string& script, int step) {
  Parsed p;
  std::istringstream in(script);
  for (std::string line; std::getline(in, line);) p.lines.push_back(line);
  const auto malformed = [&](const std::string& why) {
    return core::Error{core::ErrorCode::InvalidParameter,
                       "step " + std::to_string(step) + "'s program cannot be split: " + why +
                           " (not a program `multidir robot-program` writes)",
                       {}};
  };
  const std::string registerPrefix = "write_output_integer_register(" + std::to_string(kMovelRegister) + ", ";
  std::size_t firstMovel = p.lines.size(), lastMovel = 0;
  for (std::size_t i = 0; i < p.lines.size(); ++i)
    if (startsWith(trimmed(p.lines[i]), "movel(")) {
      firstMovel = std::min(firstMovel, i);
      lastMovel = i;
    }
  if (firstMovel == p.lines.size()) return malformed("it has no movel");
  for (std::size_t i = 0; i < firstMovel; ++i)
    if (startsWith(trimmed(p.lines[i]), "movej(")) p.headerEnd = i + 1;
  for (std::size_t i = lastMovel; i < p.lines.size(); ++i)
    if (trimmed(p.lines[i]) == registerPrefix + "0)") p.footerBegin = i;
  if (p.headerEnd == 0 || p.footerBegin == 0) return malformed("no joint move before its first movel or no end after its last");

  std::string tcp, setPoint, fan;
  double rate = 0.0;
  double previousBlend = 0.0;  // the blend radius of the move before
  double previousRate = -1.0;  // the extruder's rate through the move before (-1: no move before)
  const auto track = [&](const std::string& t) {
    if (startsWith(t, "set_tcp(")) tcp = t;
    if (startsWith(t, "set_standard_analog_out(1,")) setPoint = t;
    if (startsWith(t, "set_standard_digital_out(0,")) fan = t;
    if (startsWith(t, "set_standard_analog_out(0,")) rate = numberAfter(t, "set_standard_analog_out(0,");
  };
  for (std::size_t i = 0; i < p.headerEnd; ++i) track(trimmed(p.lines[i]));
  Group group;
  group.begin = p.headerEnd;
  group.tcp = tcp, group.setPoint = setPoint, group.fan = fan;
  for (std::size_t i = p.headerEnd; i < p.footerBegin; ++i) {
    const std::string t = trimmed(p.lines[i]);
    track(t);
    if (startsWith(t, registerPrefix)) group.movel = static_cast<int>(numberAfter(t, registerPrefix));
    const bool movel = startsWith(t, "movel("), movej = startsWith(t, "movej(");
    if (!movel && !movej) continue;
    if (movej) group.movel = 0;
    // Idle: the extruder stopped through this move, and the move before ends at rest (no blend into this one).
    group.idleStart = !p.groups.empty() && rate == 0.0 && previousBlend == 0.0;
    group.offPartStart = group.idleStart && previousRate == 0.0;
    previousRate = rate;
    const std::size_t r = t.find(", r=");
    previousBlend = movel && r != std::string::npos ? numberAfter(t.substr(r), ", r=") : 0.0;
    group.end = i + 1;
    group.bytes = bytesOf(p.lines, group.begin, group.end);
    p.groups.push_back(group);
    group = Group{};
    group.begin = i + 1;
    group.tcp = tcp, group.setPoint = setPoint, group.fan = fan;
  }
  if (p.groups.empty()) return malformed("no move between its start and its end");
  // Statements after the last move (none in what convertStep writes) stay with it.
  p.groups.back().end = p.footerBegin;
  p.groups.back().bytes = bytesOf(p.lines, p.groups.back().begin, p.footerBegin);
  return p;
}

// The start of a part after the first: the step's def, what part it is, and the step's state where it starts.
std::string continuation(const Parsed& p, const Group& first, int step, int part, int parts) {
  char label[96];
  std::snprintf(label, sizeof label, "step %02d, part %03d of %03d", step, part, parts);
  std::string text = p.lines.front() + "\n";
  text += "  # MultiDir robot program: " + std::string(label) +
          "; it goes on where the part before ended (the arm at rest at its last movel's end, the extruder "
          "stopped)\n";
  if (!first.tcp.empty()) text += "  " + first.tcp + "\n";
  text += "  set_standard_analog_out(0, 0.000000)\n";
  if (!first.setPoint.empty()) text += "  " + first.setPoint + "\n";  // the nozzle holds it already: no wait
  if (!first.fan.empty()) text += "  " + first.fan + "\n";
  return text;
}

}  // namespace

core::Result<std::vector<ProgramPart>> splitStepProgram(const std::string& script, int step, std::size_t maxBytes) {
  auto parsed = parse(script, step);
  if (!parsed) return parsed.error();
  const Parsed& p = parsed.value();
  const std::size_t budget = maxBytes > kResumeReserveBytes ? maxBytes - kResumeReserveBytes : 0;
  const auto movelsIn = [&](std::size_t from, std::size_t to, int& first) {
    int count = 0;
    first = 0;
    for (std::size_t g = from; g < to; ++g)
      if (p.groups[g].movel > 0) {
        if (count++ == 0) first = p.groups[g].movel;
      }
    return count;
  };
  if (script.size() <= budget) {
    ProgramPart whole;
    whole.text = script;
    whole.movels = movelsIn(0, p.groups.size(), whole.firstMovel);
    return std::vector<ProgramPart>{whole};
  }
  const std::size_t headerBytes = bytesOf(p.lines, 0, p.headerEnd);
  const std::size_t footerBytes = bytesOf(p.lines, p.footerBegin, p.lines.size());
  // Greedy: each part takes as many groups as fit and ends before the last idle group that still fits; before
  // the last one that leaves the nozzle off the part (after a travel's lift) if that keeps the part at least
  // half full, so that the parts do not grow in number for it.
  std::vector<std::size_t> starts{0};
  for (std::size_t s = 0;;) {
    std::size_t size = s == 0 ? headerBytes : continuation(p, p.groups[s], step, 1, 1).size();
    std::optional<std::size_t> cut, offPartCut;
    bool finished = false;
    std::size_t g = s;
    for (; g < p.groups.size(); ++g) {
      size += p.groups[g].bytes;
      if (g + 1 == p.groups.size()) {
        finished = size + footerBytes <= budget;
        break;
      }
      if (size + kPartClosing.size() > budget) break;
      if (p.groups[g + 1].idleStart) cut = g + 1;
      if (p.groups[g + 1].offPartStart && 2 * size >= budget) offPartCut = g + 1;
    }
    if (finished) break;
    if (offPartCut) cut = offPartCut;
    if (!cut) {
      int first = 0;
      movelsIn(s, s + 1, first);
      return core::Error{core::ErrorCode::CheckFailed,
                         "step " + std::to_string(step) + ": from movel " + std::to_string(first) +
                             " on, the program extrudes without a travel move for more than a part of " +
                             std::to_string(maxBytes) +
                             " bytes (the cell's maxProgramBytes) can hold, and a part may only end where the "
                             "extruder is idle: raise maxProgramBytes in the cell file",
                         {}};
    }
    s = *cut;
    starts.push_back(s);
    if (starts.size() > static_cast<std::size_t>(kMaxParts))
      return core::Error{core::ErrorCode::CheckFailed,
                         "step " + std::to_string(step) + " needs more than " + std::to_string(kMaxParts) +
                             " programs of at most " + std::to_string(maxBytes) +
                             " bytes: raise maxProgramBytes in the cell file",
                         {}};
  }
  std::vector<ProgramPart> parts;
  const int count = static_cast<int>(starts.size());
  for (int k = 0; k < count; ++k) {
    const std::size_t from = starts[static_cast<std::size_t>(k)];
    const std::size_t to = k + 1 < count ? starts[static_cast<std::size_t>(k + 1)] : p.groups.size();
    ProgramPart part;
    if (k == 0)
      for (std::size_t i = 0; i < p.headerEnd; ++i) part.text += p.lines[i] + "\n";
    else
      part.text = continuation(p, p.groups[from], step, k + 1, count);
    for (std::size_t i = p.groups[from].begin; i < p.groups[to - 1].end; ++i) part.text += p.lines[i] + "\n";
    if (k + 1 < count)
      part.text += kPartClosing;
    else
      for (std::size_t i = p.footerBegin; i < p.lines.size(); ++i) part.text += p.lines[i] + "\n";
    part.movels = movelsIn(from, to, part.firstMovel);
    parts.push_back(std::move(part));
  }
  return parts;
}

std::string partFileName(int step, int part, int parts) {
  char name[48];
  if (parts <= 1)
    std::snprintf(name, sizeof name, "step-%02d.script", step);
  else
    std::snprintf(name, sizeof name, "step-%02d-part-%03d.script", step, part);
  return name;
}

}  // namespace multidir::robot::detail
