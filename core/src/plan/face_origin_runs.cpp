#include "plan/face_origin_runs.h"

#include <cstdint>
#include <limits>

namespace multidir::core::detail {
namespace {

constexpr long long kMaxIndex = std::numeric_limits<std::int32_t>::max();

// Reads the decimal digits at text[pos...]; false if there are none or the value exceeds `maximum`.
bool readNumber(const std::string& text, std::size_t& pos, long long maximum, long long& value) {
  const std::size_t start = pos;
  value = 0;
  while (pos < text.size() && text[pos] >= '0' && text[pos] <= '9') {
    value = value * 10 + (text[pos] - '0');
    if (value > maximum) return false;
    ++pos;
  }
  return pos > start && (pos - start == 1 || text[start] != '0');  // no leading zeros: one spelling per run
}

}  // namespace

std::string encodeFaceOrigins(const std::vector<FaceOrigin>& origins) {
  std::string text;
  std::size_t i = 0;
  while (i < origins.size()) {
    const FaceOrigin first = origins[i];
    std::size_t end = i + 1;
    char form = 0;
    if (end < origins.size() && origins[end] == first) {
      form = '*';
      while (end < origins.size() && origins[end] == first) ++end;
    } else if (!first.isCap() && end < origins.size() && !origins[end].isCap() &&
               static_cast<long long>(origins[end].index) == static_cast<long long>(first.index) + 1) {
      form = '+';
      while (end < origins.size() && !origins[end].isCap() &&
             static_cast<long long>(origins[end].index) == static_cast<long long>(origins[end - 1].index) + 1)
        ++end;
    }
    if (!text.empty()) text += ' ';
    text += first.isCap() ? 'c' : 's';
    text += std::to_string(first.index);
    if (form) {
      text += form;
      text += std::to_string(end - i);
    }
    i = end;
  }
  return text;
}

Result<std::vector<FaceOrigin>> decodeFaceOrigins(const std::string& text, std::size_t maxFaces) {
  std::vector<FaceOrigin> origins;
  std::size_t pos = 0;
  int run = 0;
  while (pos < text.size()) {
    ++run;
    const std::size_t start = pos;
    const std::size_t stop = text.find(' ', pos);
    const std::string token = text.substr(start, stop == std::string::npos ? std::string::npos : stop - start);
    auto bad = [&](const std::string& why) {
      return Error{ErrorCode::MalformedFile, "run " + std::to_string(run) + " ('" + token.substr(0, 40) + "') " + why,
                   ""};
    };
    if (token.empty()) return bad("is empty: runs are separated by single spaces");
    const char kind = token[0];
    if (kind != 's' && kind != 'c') return bad("must start with s (surface face) or c (cap of a plane)");
    std::size_t p = 1;
    long long index = 0;
    if (!readNumber(token, p, kMaxIndex, index))
      return bad("needs an index from 0 to 2147483647 after '" + std::string(1, kind) + "'");
    long long count = 1;
    char form = 0;
    if (p < token.size()) {
      form = token[p++];
      if (form != '+' && form != '*')
        return bad("has '" + std::string(1, form) + "' where + (consecutive) or * (repeated) belongs");
      if (form == '+' && kind == 'c') return bad("uses + on a cap: cap faces all carry their plane's index, use *");
      if (!readNumber(token, p, static_cast<long long>(maxFaces), count) || count < 1 || p != token.size())
        return bad("needs a face count from 1 to " + std::to_string(maxFaces) + " after '" + std::string(1, form) +
                   "'");
      if (form == '+' && index + count - 1 > kMaxIndex) return bad("runs past face index 2147483647");
    }
    if (origins.size() + static_cast<std::size_t>(count) > maxFaces)
      return bad("makes more than the " + std::to_string(maxFaces) + " faces the region has");
    for (long long k = 0; k < count; ++k) {
      const auto value = static_cast<std::int32_t>(form == '+' ? index + k : index);
      origins.push_back(kind == 'c' ? FaceOrigin::cap(value) : FaceOrigin::surface(value));
    }
    pos = stop == std::string::npos ? text.size() : stop + 1;
    if (stop != std::string::npos && pos == text.size()) return bad("is followed by a trailing space");
  }
  return origins;
}

}  // namespace multidir::core::detail
