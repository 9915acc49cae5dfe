#include "api_key.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace multidir::cli {
namespace {

std::string trimmed(const std::string& text) {
  const char* const blanks = " \t\r\n";
  const std::size_t begin = text.find_first_not_of(blanks);
  if (begin == std::string::npos) return {};
  return text.substr(begin, text.find_last_not_of(blanks) - begin + 1);
}

// The key from `source` ("the API key file 'F'", "MULTIDIR_PRINTER_API_KEY", "--api-key"), checked.
std::string checkedKey(const std::string& text, const std::string& source, const std::string& command) {
  const std::string key = trimmed(text);
  if (key.empty())
    throw UsageError("multidir " + command + ": " + source + " is empty: put the printer's API key in it. Run 'multidir help " +
                     command + "'.");
  // The key goes into a request header: a line break would end it.
  if (std::any_of(key.begin(), key.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
    throw UsageError("multidir " + command + ": " + source +
                     " holds more than the key (a line break or another control character): keep only the key, on "
                     "one line. Run 'multidir help " +
                     command + "'.");
  return key;
}

}  // namespace

std::string printerApiKey(const ParsedArgs& parsed, const std::string& command) {
  if (parsed.has("--api-key") && parsed.has("--api-key-file"))
    throw UsageError("multidir " + command +
                     ": give the API key once: --api-key-file FILE (preferred) or --api-key KEY, not both. Run "
                     "'multidir help " +
                     command + "'.");
  if (parsed.has("--api-key-file")) {
    const std::string path = parsed.value("--api-key-file", "");
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw UsageError("multidir " + command + ": cannot read the API key file '" + path +
                       "': check that it exists and that you may read it. Run 'multidir help " + command + "'.");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return checkedKey(text, "the API key file '" + path + "'", command);
  }
  if (parsed.has("--api-key")) return checkedKey(parsed.value("--api-key", ""), "--api-key", command);
  if (const char* fromEnvironment = std::getenv(kApiKeyVariable); fromEnvironment != nullptr)
    return checkedKey(fromEnvironment, kApiKeyVariable, command);
  return {};
}

}  // namespace multidir::cli
