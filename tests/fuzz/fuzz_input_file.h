#pragma once
// Shared by the libFuzzer harnesses whose loader reads a file, not bytes: the input is written to a scratch
// file of this process (the process id keeps parallel fuzzers apart) and removed again after the load.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace multidir::fuzz {

// "$TMPDIR/multidir-fuzz-<pid>" (or /tmp): the stem of every scratch file this process writes.
inline const std::string& scratchStem() {
  static const std::string stem = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp && *tmp ? tmp : "/tmp") + "/multidir-fuzz-" + std::to_string(::getpid());
  }();
  return stem;
}

// Writes the input to `path`, replacing what was there.
inline void writeInput(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

// The input as text, for the promises that look at what a refusal quotes.
inline std::string inputText(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Aborts (so libFuzzer keeps the input) when `broken` names a broken promise.
inline void requirePromise(const std::string& broken, const char* loader) {
  if (broken.empty()) return;
  std::fprintf(stderr, "%s broke its promise: %s\n", loader, broken.c_str());
  std::abort();
}

}  // namespace multidir::fuzz
