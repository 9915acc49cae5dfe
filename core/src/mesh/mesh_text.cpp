#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <sstream>

#include "mesh/mesh_formats.h"

namespace multidir::core::detail {

bool LineReader::next(std::string& line) {
  line.clear();
  std::streambuf* buffer = m_in.rdbuf();
  if (buffer == nullptr) return false;
  bool any = false;
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) break;
    any = true;
    if (c == '\n') break;
    if (c == '\r') continue;
    const auto byte = static_cast<unsigned char>(c);
    // Text mesh formats hold printable ASCII (and UTF-8 in comments), tabs and form feeds.
    if (byte < 0x20 && byte != '\t' && byte != '\f' && byte != '\v') m_binary = true;
    if (line.size() >= kMaxLineLength) {
      m_tooLong = true;
      continue;  // keep consuming so the line count stays right; the caller stops at tooLong()
    }
    line.push_back(static_cast<char>(c));
  }
  if (any) ++m_lineNumber;
  return any;
}

std::size_t splitTokens(const std::string& line, std::vector<std::string>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && (line[i] == ' ' || line[i] == '\t' || line[i] == '\f' || line[i] == '\v')) ++i;
    const std::size_t start = i;
    while (i < n && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\f' || line[i] == '\v')) ++i;
    if (i > start) tokens.emplace_back(line, start, i - start);
  }
  return tokens.size();
}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Plain decimal notation only: [+-] digits [. digits] [(e|E) [+-] digits], with a digit before or after the
// point. Hexadecimal ("0x10"), "nan", "inf" and C's other spellings are not mesh data.
bool isPlainDecimal(const std::string& token) {
  std::size_t i = 0;
  const std::size_t n = token.size();
  if (i < n && (token[i] == '+' || token[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < n && isDigit(token[i])) ++i, ++digits;
  if (i < n && token[i] == '.') {
    ++i;
    while (i < n && isDigit(token[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < n && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < n && (token[i] == '+' || token[i] == '-')) ++i;
    std::size_t exponentDigits = 0;
    while (i < n && isDigit(token[i])) ++i, ++exponentDigits;
    if (exponentDigits == 0) return false;
  }
  return i == n;
}

bool spellsNonFinite(const std::string& token) {
  std::string word;
  for (char c : token)
    if (c != '+' && c != '-') word.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return word == "nan" || word == "inf" || word == "infinity" || word.rfind("nan(", 0) == 0;
}

}  // namespace

NumberStatus parseCoordinate(const std::string& token, double& value) {
  value = 0.0;
  if (spellsNonFinite(token)) return NumberStatus::NotFinite;
  if (!isPlainDecimal(token)) return NumberStatus::NotANumber;
  // from_chars ignores the locale (strtod would read "1,5" in a German one) and takes no leading '+'.
  const char* first = token.data() + (token[0] == '+' ? 1 : 0);
  const char* last = token.data() + token.size();
  const auto [end, error] = std::from_chars(first, last, value);
  if (end != last) return NumberStatus::NotANumber;
  if (error == std::errc::result_out_of_range) {
    // Too small to represent is zero; too large is refused. A negative exponent means too small.
    const std::size_t e = token.find_first_of("eE");
    if (e != std::string::npos && e + 1 < token.size() && token[e + 1] == '-') {
      value = token[0] == '-' ? -0.0 : 0.0;
      return NumberStatus::Ok;
    }
    return NumberStatus::NotFinite;
  }
  if (error != std::errc()) return NumberStatus::NotANumber;
  return isFiniteAsFloat(value) ? NumberStatus::Ok : NumberStatus::NotFinite;
}

bool isFiniteAsFloat(double value) {
  return std::isfinite(value) && std::fabs(value) <= static_cast<double>(std::numeric_limits<float>::max());
}

bool parseDouble(const std::string& token, double& value) {
  return parseCoordinate(token, value) == NumberStatus::Ok;
}

Error coordinateError(const std::string& name, std::size_t line, std::size_t vertex, const std::string& token,
                      NumberStatus status) {
  const std::string where = (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + "vertex " +
                            std::to_string(vertex) + " has the coordinate '" + token.substr(0, 40) + "'";
  if (status == NumberStatus::NotFinite)
    return Error{ErrorCode::NonFiniteVertex,
                 where + ", which is not a finite number within the range of a mesh file (at most 3.4e38 in "
                         "size); fix or remove it in a mesh editor",
                 name};
  return malformed(name, where + ", which is not a plain decimal number (hexadecimal and other forms are not "
                                 "read); export the model again");
}

bool parseInteger(const std::string& token, long long& value) {
  if (token.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return errno == 0 && end == token.c_str() + token.size();
}

std::string joinIndices(const std::vector<std::int64_t>& indices) {
  std::ostringstream out;
  for (std::size_t i = 0; i < indices.size(); ++i) out << (i ? ", " : "") << indices[i];
  return out.str();
}

std::string withThousands(std::size_t n) {
  std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out.push_back(',');
    out.push_back(digits[i]);
  }
  return out;
}

Error malformed(const std::string& name, const std::string& message) {
  return Error{ErrorCode::MalformedFile, message, name};
}

Status addPolygon(RawSoup& soup, const std::vector<std::int32_t>& corners, const LoadOptions& options,
                  const std::string& name) {
  if (corners.size() < 3) {
    ++soup.droppedByReader;
    return Done{};
  }
  if (soup.triangles.size() + (corners.size() - 2) > options.maxTriangles)
    return checkTriangleCount(soup.triangles.size() + (corners.size() - 2), options, name);
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) soup.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  return Done{};
}

Status checkTriangleCount(std::size_t triangles, const LoadOptions& options, const std::string& name) {
  if (triangles <= options.maxTriangles) return Done{};
  return Error{ErrorCode::TooLarge,
               "the faces make more than " + withThousands(options.maxTriangles) +
                   " triangles; simplify the model first",
               name};
}

}  // namespace multidir::core::detail
