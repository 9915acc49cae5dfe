#include "printer/reply_json.h"

#include <algorithm>

namespace multidir::hardware {

int jsonNestingDepth(const std::string& text, int limit) {
  int depth = 0;
  int deepest = 0;
  bool inString = false;
  bool escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        inString = false;
      }
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) return deepest;
    } else if ((c == '}' || c == ']') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

core::Result<nlohmann::json> parseReplyJson(const std::string& text, const std::string& request,
                                            const std::string& hint, const std::string& printer) {
  if (jsonNestingDepth(text) > kMaxReplyJsonDepth)
    return core::Error{core::ErrorCode::DeviceFault,
                       "the reply to " + request + " is nested deeper than " + std::to_string(kMaxReplyJsonDepth) +
                           " levels (no printer reply MultiDir reads is): refused; check what answers at this address",
                       printer};
  nlohmann::json body = nlohmann::json::parse(text, nullptr, false);
  if (body.is_discarded())
    return core::Error{core::ErrorCode::DeviceFault, "the reply to " + request + " is not JSON" + hint, printer};
  return body;
}

}  // namespace multidir::hardware
