#pragma once
// What every loader of a user's file promises when it refuses (header-only: shared by the corpus replay tests
// and the libFuzzer harnesses in tests/fuzz/): a refusal that says what is wrong and where, never Internal and
// never "please report it". Returns an empty string when the promise holds, else what broke it. `input` is the
// text the loader read, when the caller has it: a refusal that quotes it may repeat its words, so "please
// report" counts only when the input does not hold it.
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::test {

inline std::string brokenRefusalPromise(const core::Error& e, const std::string& input = {}) {
  if (e.code == core::ErrorCode::Internal) return "refused as an internal error: " + e.describe();
  if (e.message.empty()) return "refused without a message";
  if (e.where.empty()) return "refused without saying where: " + e.message;
  if (e.message.find("please report") != std::string::npos && input.find("please report") == std::string::npos)
    return "refused as a bug: " + e.describe();
  return {};
}

template <typename T>
std::string brokenRefusalPromise(const core::Result<T>& loaded, const std::string& input = {}) {
  return loaded ? std::string() : brokenRefusalPromise(loaded.error(), input);
}

}  // namespace multidir::test
