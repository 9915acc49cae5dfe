#include "ur/urscript_program.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace multidir::hardware::ur {
namespace {

// A refusal carried out of the nested readers; caught once in parseUrScript.
struct Refusal {
  int column;
  std::string message;
};

std::string trimmed(const std::string& text, std::size_t& leading) {
  std::size_t begin = 0;
  while (begin < text.size() && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  std::size_t end = text.size();
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  leading = begin;
  return text.substr(begin, end - begin);
}

// The line without its comment: '#' outside a string literal starts one.
std::string withoutComment(const std::string& line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == '#' && !quoted) return line.substr(0, i);
  }
  return line;
}

// Reads a statement's text left to right; every refusal names the column where the reader stands.
class Reader {
 public:
  Reader(const std::string& text, int firstColumn) : m_text(text), m_first(firstColumn) {}

  [[noreturn]] void refuse(const std::string& message) const { refuseAt(m_at, message); }
  [[noreturn]] void refuseAt(std::size_t at, const std::string& message) const {
    throw Refusal{m_first + static_cast<int>(at), message};
  }
  // Where the next token starts (for a refusal naming it after it was read).
  std::size_t mark() {
    skipSpace();
    return m_at;
  }
  void skipSpace() {
    while (m_at < m_text.size() && m_text[m_at] == ' ') ++m_at;
  }
  bool done() {
    skipSpace();
    return m_at >= m_text.size();
  }
  bool accept(const std::string& token) {
    skipSpace();
    if (m_text.compare(m_at, token.size(), token) != 0) return false;
    m_at += token.size();
    return true;
  }
  void expect(const std::string& token, const std::string& what) {
    if (!accept(token)) refuse("expected '" + token + "' " + what);
  }
  std::string identifier() {
    skipSpace();
    const std::size_t begin = m_at;
    while (m_at < m_text.size() && (std::isalnum(static_cast<unsigned char>(m_text[m_at])) || m_text[m_at] == '_'))
      ++m_at;
    if (begin == m_at) refuse("expected a name");
    return m_text.substr(begin, m_at - begin);
  }
  double number(const std::string& what) {
    skipSpace();
    const char* begin = m_text.c_str() + m_at;
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || !std::isfinite(value)) refuse("expected a number for " + what);
    // strtod also reads "inf", "nan" and hexadecimal numbers, which URScript does not have.
    for (const char* c = begin; c < end; ++c)
      if (!(std::isdigit(static_cast<unsigned char>(*c)) || *c == '.' || *c == '-' || *c == '+' || *c == 'e' ||
            *c == 'E'))
        refuse("expected a number for " + what);
    m_at += static_cast<std::size_t>(end - begin);
    return value;
  }
  std::array<double, 6> list(const std::string& what) {
    std::array<double, 6> values{};
    for (int i = 0; i < 6; ++i) {
      values[static_cast<std::size_t>(i)] = number(what);
      if (i < 5) expect(",", "between the six values of " + what);
    }
    expect("]", "after the six values of " + what);
    return values;
  }
  std::string quoted() {
    skipSpace();
    if (m_at >= m_text.size() || m_text[m_at] != '"') refuse("expected a string in double quotes");
    const std::size_t close = m_text.find('"', m_at + 1);
    if (close == std::string::npos) refuse("the string is not closed");
    std::string text = m_text.substr(m_at + 1, close - m_at - 1);
    m_at = close + 1;
    return text;
  }

 private:
  const std::string& m_text;
  int m_first;
  std::size_t m_at = 0;
};

// Keyword arguments a=, v= (and r= when `blend`), each at most once, after the first argument.
void moveArguments(Reader& reader, UrStatement& statement, bool blend) {
  bool seenA = false;
  bool seenV = false;
  bool seenR = false;
  while (reader.accept(",")) {
    const std::size_t at = reader.mark();
    const std::string name = reader.identifier();
    reader.expect("=", "after " + name);
    bool* seen = name == "a" ? &seenA : name == "v" ? &seenV : (blend && name == "r") ? &seenR : nullptr;
    if (seen == nullptr)
      reader.refuseAt(at, "'" + name + "' is not an argument MultiDir's programs give " +
                              (blend ? std::string("movel (a, v, r)") : std::string("movej (a, v)")));
    if (*seen) reader.refuseAt(at, "'" + name + "' is given twice");
    *seen = true;
    const double value = reader.number(name);
    if (name == "a") statement.a = value;
    if (name == "v") statement.v = value;
    if (name == "r") statement.r = value;
  }
  reader.expect(")", "to close the call");
  if (!(statement.a > 0.0) || !(statement.v > 0.0)) reader.refuse("a and v must be above 0");
  if (statement.r < 0.0) reader.refuse("the blend radius r must not be negative");
}

UrStatement statementOf(Reader& reader, int line) {
  UrStatement s;
  s.line = line;
  const std::size_t nameAt = reader.mark();
  const std::string name = reader.identifier();
  reader.expect("(", "after " + name);
  if (name == "set_tcp") {
    s.kind = UrStatementKind::SetTcp;
    reader.expect("p[", "(set_tcp takes a pose p[x, y, z, rx, ry, rz])");
    s.pose = reader.list("the pose");
    reader.expect(")", "to close the call");
  } else if (name == "set_standard_analog_out" || name == "set_standard_digital_out") {
    const bool analog = name == "set_standard_analog_out";
    s.kind = analog ? UrStatementKind::SetAnalogOut : UrStatementKind::SetDigitalOut;
    const double index = reader.number("the output");
    const int highest = analog ? 1 : 7;
    if (index != std::floor(index) || index < 0 || index > highest)
      reader.refuse("the standard " + std::string(analog ? "analog" : "digital") + " outputs are 0 to " +
                    std::to_string(highest));
    s.index = static_cast<int>(index);
    reader.expect(",", "after the output");
    if (analog) {
      s.value = reader.number("the output's value");
      if (s.value < 0.0 || s.value > 1.0) reader.refuse("an analog output's value is between 0 and 1");
    } else if (reader.accept("True")) {
      s.flag = true;
    } else if (reader.accept("False")) {
      s.flag = false;
    } else {
      reader.refuse("expected True or False");
    }
    reader.expect(")", "to close the call");
  } else if (name == "write_output_integer_register") {
    // UR's general purpose output integer registers 0..47, which RTDE reads as output_int_register_N.
    s.kind = UrStatementKind::WriteIntRegister;
    const double index = reader.number("the register");
    if (index != std::floor(index) || index < 0 || index > 47)
      reader.refuse("the output integer registers are 0 to 47");
    s.index = static_cast<int>(index);
    reader.expect(",", "after the register");
    const double value = reader.number("the register's value");
    if (value != std::floor(value) || value < -2147483648.0 || value > 2147483647.0)
      reader.refuse("an integer register holds a whole number from -2147483648 to 2147483647");
    s.integer = static_cast<std::int32_t>(value);
    reader.expect(")", "to close the call");
  } else if (name == "movej") {
    s.kind = UrStatementKind::MoveJ;
    s.a = 1.4;
    s.v = 1.05;
    reader.expect("[", "(movej takes the joints [q1, ..., q6] in radians)");
    s.pose = reader.list("the joints");
    moveArguments(reader, s, false);
  } else if (name == "movel") {
    s.kind = UrStatementKind::MoveL;
    s.a = 1.2;
    s.v = 0.25;
    reader.expect("p[", "(movel takes a pose p[x, y, z, rx, ry, rz])");
    s.pose = reader.list("the pose");
    moveArguments(reader, s, true);
  } else if (name == "sleep") {
    s.kind = UrStatementKind::Sleep;
    s.value = reader.number("the seconds");
    if (s.value < 0.0) reader.refuse("sleep's seconds must not be negative");
    reader.expect(")", "to close the call");
  } else if (name == "textmsg") {
    s.kind = UrStatementKind::TextMsg;
    s.text = reader.quoted();
    reader.expect(")", "to close the call");
  } else {
    reader.refuseAt(nameAt,
                    "'" + name +
                        "' is not in the URScript subset MultiDir's programs use (set_tcp, "
                        "set_standard_analog_out, set_standard_digital_out, write_output_integer_register, movej, "
                        "movel, sleep, textmsg and the heat wait loop)");
  }
  if (!reader.done()) reader.refuse("unexpected text after the statement");
  return s;
}

}  // namespace

UrScriptParse parseUrScript(const std::string& text) {
  UrScriptParse result;
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(line);
    }
  }
  enum class Where { BeforeDef, InBody, InWhile, AfterWhileBody, AfterEnd };
  Where where = Where::BeforeDef;
  UrProgram program;
  UrStatement pendingWait;
  int lineNumber = 0;
  try {
    for (const std::string& raw : lines) {
      ++lineNumber;
      std::size_t leading = 0;
      const std::string line = trimmed(withoutComment(raw), leading);
      if (line.empty()) continue;
      Reader reader(line, static_cast<int>(leading) + 1);
      switch (where) {
        case Where::BeforeDef: {
          if (!reader.accept("def ")) reader.refuse("a program starts with 'def NAME():'");
          program.name = reader.identifier();
          reader.expect("():", "after the program's name (MultiDir's programs take no arguments)");
          if (!reader.done()) reader.refuse("unexpected text after 'def " + program.name + "():'");
          where = Where::InBody;
          break;
        }
        case Where::InBody: {
          if (line == "end") {
            where = Where::AfterEnd;
            break;
          }
          if (reader.accept("while ")) {
            reader.expect("get_standard_analog_in(",
                          "(the only loop is the heat wait: while "
                          "get_standard_analog_in(0) < X:)");
            const double index = reader.number("the input");
            if (index != 0.0) reader.refuse("the heat wait reads analog input 0 (the nozzle temperature)");
            reader.expect(")", "to close the call");
            reader.expect("<", "(the heat wait compares with '<')");
            pendingWait = UrStatement{};
            pendingWait.kind = UrStatementKind::WaitAnalogInBelow;
            pendingWait.line = lineNumber;
            pendingWait.index = 0;
            pendingWait.value = reader.number("the threshold");
            reader.expect(":", "at the end of the while line");
            if (!reader.done()) reader.refuse("unexpected text after the while line");
            where = Where::InWhile;
            break;
          }
          program.statements.push_back(statementOf(reader, lineNumber));
          break;
        }
        case Where::InWhile:
          if (line != "sync()") reader.refuse("the heat wait's body is 'sync()' alone");
          where = Where::AfterWhileBody;
          break;
        case Where::AfterWhileBody:
          if (line != "end") reader.refuse("the heat wait ends with 'end' after its 'sync()'");
          program.statements.push_back(pendingWait);
          where = Where::InBody;
          break;
        case Where::AfterEnd:
          reader.refuse("text after the program's 'end': one def per program");
      }
    }
  } catch (const Refusal& refusal) {
    result.error = UrScriptError{lineNumber, refusal.column, refusal.message};
    return result;
  }
  if (where == Where::BeforeDef) {
    result.error = UrScriptError{std::max(lineNumber, 1), 1, "the program is empty: expected 'def NAME():'"};
    return result;
  }
  if (where != Where::AfterEnd) {
    result.error = UrScriptError{lineNumber + 1, 1, "the program ends without its 'end'"};
    return result;
  }
  result.program = std::move(program);
  return result;
}

}  // namespace multidir::hardware::ur
