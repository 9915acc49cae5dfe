#include "plan/json_file.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "multidir/core/common/atomic_file.h"

namespace multidir::core::detail {

namespace fs = std::filesystem;

namespace {

// Walks a document with nlohmann's SAX interface only to learn where a value it cannot hold sits
// ("regions[0].volumeMm3"): the DOM parser reports a number such as 1e999 without saying where.
class FieldLocator : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string failedPath;
  std::string failedToken;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    m_stack.push_back({false, 0, ""});
    return true;
  }
  bool key(string_t& name) override {
    m_stack.back().key = name;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    m_stack.push_back({true, 0, ""});
    return true;
  }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string& lastToken, const nlohmann::detail::exception&) override {
    failedPath = path();
    failedToken = lastToken;
    return false;
  }

 private:
  struct Level {
    bool array;
    std::size_t index;
    std::string key;
  };
  // A value completes one element of the enclosing array.
  bool value() {
    if (!m_stack.empty() && m_stack.back().array) ++m_stack.back().index;
    return true;
  }
  bool close() {
    m_stack.pop_back();
    return value();
  }
  std::string path() const {
    std::string out;
    for (const Level& level : m_stack) {
      if (level.array) out += "[" + std::to_string(level.index) + "]";
      else out += (out.empty() ? "" : ".") + level.key;
    }
    return out;
  }
  std::vector<Level> m_stack;
};

// The token around byte `byte` (1-based, where nlohmann stopped) of `content`: "NaN", not only its first letter.
std::string tokenAt(const std::string& content, std::size_t byte) {
  const auto delimiter = [](char c) { return std::isspace(static_cast<unsigned char>(c)) || std::strchr(":,[]{}", c); };
  std::size_t start = std::min(std::max<std::size_t>(byte, 1), content.size()) - 1;
  while (start > 0 && !delimiter(content[start - 1])) --start;
  std::size_t end = start;
  while (end < content.size() && end - start < 40 && !delimiter(content[end])) ++end;
  return content.substr(start, end - start);
}

}  // namespace

Result<nlohmann::json> readJsonFile(const std::string& path, const std::string& name) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return Error{ErrorCode::FileNotFound, "no such file: " + path, name};
  if (fs::is_directory(status)) return Error{ErrorCode::FileNotFound, "this is a folder, not a file: " + path, name};
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return Error{ErrorCode::FileNotFound, "the file size cannot be read: " + path, name};
  if (size > kMaxJsonFileBytes)
    return Error{ErrorCode::TooLarge, "the file has " + std::to_string(size) + " bytes, more than the 1 GiB accepted",
                 name};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::FileNotFound, "the file cannot be opened (check its permissions): " + path, name};
  std::ostringstream text;
  text << in.rdbuf();
  return parseJsonText(text.str(), name);
}

Result<nlohmann::json> parseJsonText(const std::string& content, const std::string& name) {
  if (content.empty()) return Error{ErrorCode::MalformedFile, "the file is empty (0 bytes)", name};
  try {
    return nlohmann::json::parse(content);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries nlohmann's "[json.exception.parse_error.101]" prefix; the byte offset and the field
    // where parsing stopped (NaN, Infinity: not JSON) are what help.
    FieldLocator locator;
    nlohmann::json::sax_parse(content, &locator);
    const std::string where = locator.failedPath.empty()
                                  ? std::string()
                                  : " at " + locator.failedPath + " ('" + tokenAt(content, e.byte) + "')";
    return Error{ErrorCode::MalformedFile,
                 "not valid JSON (syntax error near byte " + std::to_string(e.byte) + where +
                     "); check brackets, commas and quotes, and that every number is finite",
                 name};
  } catch (const nlohmann::json::out_of_range&) {
    // A number beyond double's range (1e999): valid JSON text, but no value MultiDir can hold.
    FieldLocator locator;
    nlohmann::json::sax_parse(content, &locator);
    return Error{ErrorCode::MalformedFile,
                 (locator.failedPath.empty() ? std::string("a value") : locator.failedPath) + " is '" +
                     locator.failedToken.substr(0, 40) +
                     "', a number too large to represent (not finite); correct that field",
                 name};
  }
}

Status writeTextFile(const std::string& path, const std::string& text, const std::string& name) {
  return writeFileAtomically(path, name, [&](std::ostream& out) -> Status {
    out << text;
    return Done{};
  });
}

}  // namespace multidir::core::detail
