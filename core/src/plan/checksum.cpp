#include "multidir/core/plan/checksum.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace multidir::core {
namespace {

constexpr const char* kPrefix = "fnv1a64:";
constexpr std::size_t kPrefixLength = 8;
constexpr std::size_t kHexDigits = 16;

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t state) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) state = (state ^ bytes[i]) * kFnv1a64Prime;
  return state;
}

std::string checksumText(std::uint64_t value) {
  char hex[kHexDigits + 1];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(value));
  return std::string(kPrefix) + hex;
}

Result<std::string> fileChecksum(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return Error{ErrorCode::FileNotFound, "this is a folder, not a file: " + path, name};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::FileNotFound, "the file cannot be opened for its checksum: " + path, name};
  std::array<char, 1 << 16> block{};
  std::uint64_t state = kFnv1a64Offset;
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    state = fnv1a64(block.data(), static_cast<std::size_t>(in.gcount()), state);
  }
  if (in.bad()) return Error{ErrorCode::FileNotFound, "reading the file failed part way: " + path, name};
  return checksumText(state);
}

bool isChecksumText(const std::string& text) {
  if (text.size() != kPrefixLength + kHexDigits || text.compare(0, kPrefixLength, kPrefix) != 0) return false;
  for (std::size_t i = kPrefixLength; i < text.size(); ++i) {
    const char c = text[i];
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

}  // namespace multidir::core
