#include "plan/json_file.h"

#include "detail/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace multidir::core::detail {

namespace fs = std::filesystem;

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
  const std::string content = text.str();
  if (content.empty()) return Error{ErrorCode::MalformedFile, "the file is empty (0 bytes)", name};
  try {
    return nlohmann::json::parse(content);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries nlohmann's "[json.exception.parse_error.101]" prefix; the byte offset is what helps.
    return Error{
        ErrorCode::MalformedFile,
        "not valid JSON (syntax error near byte " + std::to_string(e.byte) + "); check brackets, commas and quotes",
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
