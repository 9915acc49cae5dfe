#pragma once
// A printer's JSON reply parsed with a bound on its nesting. nlohmann::json parses without recursion, but
// copying, comparing and dumping a value recurse once per level: 100,000 nested objects from a hostile or
// broken server overflowed the stack. No printer reply MultiDir reads nests deeper than 5 levels; anything
// deeper than kMaxReplyJsonDepth is refused before it is parsed.
#include <nlohmann/json.hpp>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

constexpr int kMaxReplyJsonDepth = 64;

// The deepest nesting of objects and arrays in `text` (brackets inside strings do not count), scanning no
// further than the first level past `limit`.
int jsonNestingDepth(const std::string& text, int limit = kMaxReplyJsonDepth);

// The parsed reply. Errors (DeviceFault naming `printer`): "is not JSON", or "is nested deeper than 64 levels";
// `request` ("GET /api/job") and `hint` (": is this OctoPrint's address?", added to the first) complete them.
core::Result<nlohmann::json> parseReplyJson(const std::string& text, const std::string& request,
                                            const std::string& hint, const std::string& printer);

}  // namespace multidir::hardware
