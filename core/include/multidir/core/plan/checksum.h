#pragma once
// Checksums that tie a plan to the exact model file it was computed for.
//
// FNV-1a 64 (Fowler, Noll, Vo): not cryptographic, but it notices any edit, truncation or swap of a model
// file, which is all a plan needs, and it is small enough to carry without a dependency.
#include <cstddef>
#include <cstdint>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::core {

constexpr std::uint64_t kFnv1a64Offset = 14695981039346656037ull;
constexpr std::uint64_t kFnv1a64Prime = 1099511628211ull;

// FNV-1a 64 of `size` bytes. Pass a previous result as `state` to continue over data given in pieces.
std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t state = kFnv1a64Offset);

// "fnv1a64:" followed by 16 lower-case hex digits, the form plan files store.
std::string checksumText(std::uint64_t fnv1a64Value);

// The checksum text of a file's bytes, read in blocks (constant memory). Errors: FileNotFound.
Result<std::string> fileChecksum(const std::string& path);

// Whether `text` has the form checksumText produces.
bool isChecksumText(const std::string& text);

}  // namespace multidir::core
