#pragma once
// Reading checked values out of a parsed JSON document. Every accessor knows its field's path
// ("regions[2].printingDirection") and throws JsonFieldError naming the file and that path on the first
// violation; the public functions of plan_file.h catch it and return it as an Error.
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core::detail {

class JsonFieldError : public std::runtime_error {
 public:
  explicit JsonFieldError(Error error) : std::runtime_error(error.describe()), m_error(std::move(error)) {}
  const Error& error() const { return m_error; }

 private:
  Error m_error;
};

// Hand-edited files often carry vectors with 6 or 7 digits; those still count as unit and are renormalised.
constexpr double kUnitVectorTolerance = 1e-6;

class JsonField {
 public:
  // `file` names the document in errors ("plan.json"); `code` is the ErrorCode thrown.
  JsonField(const nlohmann::json& value, std::string path, std::string file, ErrorCode code = ErrorCode::MalformedFile)
      : m_value(&value), m_path(std::move(path)), m_file(std::move(file)), m_code(code) {}

  const std::string& path() const { return m_path; }
  const nlohmann::json& json() const { return *m_value; }
  bool isNull() const { return m_value->is_null(); }

  // A member that must be present (the field must be an object).
  JsonField operator[](const char* key) const;
  // A member that may be missing; null counts as missing.
  std::optional<JsonField> optional(const char* key) const;
  // The field must be an array; element i of it.
  std::size_t arraySize() const;
  JsonField element(std::size_t index) const;

  std::string string() const;
  bool boolean() const;
  double number() const;  // finite
  double numberAtLeast(double minimum) const;
  long long integer(long long minimum, long long maximum) const;
  Vec3 vector() const;      // three finite numbers
  Vec3 unitVector() const;  // within kUnitVectorTolerance of length 1, returned normalised

  // Throws "<file>: <path> <what>".
  [[noreturn]] void fail(const std::string& what) const;
  // Throws "<file>: <path>: <message>", for a message that names its own subject (from validate()).
  [[noreturn]] void failInside(const std::string& message) const { failInside(message, m_code); }
  [[noreturn]] void failInside(const std::string& message, ErrorCode code) const;

 private:
  void requireObject() const;
  std::string childPath(const std::string& key) const { return m_path.empty() ? key : m_path + "." + key; }

  const nlohmann::json* m_value;
  std::string m_path;
  std::string m_file;
  ErrorCode m_code;
};

// Files are written with their keys in a fixed, readable order (ordered_json) and read as plain json.
inline nlohmann::ordered_json toJson(const Vec3& v) { return nlohmann::ordered_json::array({v.x(), v.y(), v.z()}); }

}  // namespace multidir::core::detail
