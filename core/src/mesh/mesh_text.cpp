#include <cerrno>
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

bool parseDouble(const std::string& token, double& value) {
  if (token.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  // ERANGE on underflow still gives a usable (tiny) value; on overflow it gives inf, caught by finiteness checks.
  return end == token.c_str() + token.size();
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

Status checkTriangleCount(std::size_t triangles, const LoadOptions& options, const std::string& name) {
  if (triangles <= options.maxTriangles) return Done{};
  return Error{ErrorCode::TooLarge,
               "the faces make more than " + withThousands(options.maxTriangles) +
                   " triangles; simplify the model first",
               name};
}

}  // namespace multidir::core::detail
