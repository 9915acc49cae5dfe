#pragma once
// Reading and writing whole JSON files, with the errors plan files and machine profiles share.
#include <nlohmann/json.hpp>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::core::detail {

// Parses a JSON file of at most kMaxJsonFileBytes. Errors: FileNotFound, TooLarge, MalformedFile (with the
// byte offset of the syntax error). `name` is the file's name in messages.
constexpr std::uintmax_t kMaxJsonFileBytes = 1u << 30;
Result<nlohmann::json> readJsonFile(const std::string& path, const std::string& name);

// Parses JSON text already in memory. Errors: MalformedFile naming the field where parsing stopped (a number
// too large to represent such as 1e999, or a token that is not JSON such as NaN) and the token.
Result<nlohmann::json> parseJsonText(const std::string& content, const std::string& name);

// Writes `text` beside `path` and renames it into place, so readers never see half a file. Errors: WriteFailed.
Status writeTextFile(const std::string& path, const std::string& text, const std::string& name);

}  // namespace multidir::core::detail
