#include "plan/json_field.h"

#include <cmath>

namespace multidir::core::detail {
namespace {

const char* typeName(const nlohmann::json& value) {
  if (value.is_null()) return "null";
  if (value.is_boolean()) return "true/false";
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_array()) return "an array";
  return "an object";
}

}  // namespace

void JsonField::fail(const std::string& what) const {
  throw JsonFieldError(Error{m_code, (m_path.empty() ? std::string("the document") : m_path) + " " + what, m_file});
}

void JsonField::failInside(const std::string& message, ErrorCode code) const {
  throw JsonFieldError(Error{code, (m_path.empty() ? std::string() : m_path + ": ") + message, m_file});
}

void JsonField::requireObject() const {
  if (!m_value->is_object()) fail(std::string("must be an object, not ") + typeName(*m_value));
}

JsonField JsonField::operator[](const char* key) const {
  requireObject();
  const auto it = m_value->find(key);
  if (it == m_value->end()) JsonField(*m_value, childPath(key), m_file, m_code).fail("is missing");
  return JsonField(*it, childPath(key), m_file, m_code);
}

std::optional<JsonField> JsonField::optional(const char* key) const {
  requireObject();
  const auto it = m_value->find(key);
  if (it == m_value->end() || it->is_null()) return std::nullopt;
  return JsonField(*it, childPath(key), m_file, m_code);
}

std::size_t JsonField::arraySize() const {
  if (!m_value->is_array()) fail(std::string("must be an array, not ") + typeName(*m_value));
  return m_value->size();
}

JsonField JsonField::element(std::size_t index) const {
  if (index >= arraySize()) fail("has no element " + std::to_string(index));
  return JsonField((*m_value)[index], m_path + "[" + std::to_string(index) + "]", m_file, m_code);
}

std::string JsonField::string() const {
  if (!m_value->is_string()) fail(std::string("must be a string, not ") + typeName(*m_value));
  return m_value->get<std::string>();
}

bool JsonField::boolean() const {
  if (!m_value->is_boolean()) fail(std::string("must be true or false, not ") + typeName(*m_value));
  return m_value->get<bool>();
}

double JsonField::number() const {
  if (!m_value->is_number()) fail(std::string("must be a number, not ") + typeName(*m_value));
  const double value = m_value->get<double>();
  if (!std::isfinite(value)) fail("must be a finite number");
  return value;
}

double JsonField::numberAtLeast(double minimum) const {
  const double value = number();
  if (!(value >= minimum))
    fail("must be at least " + nlohmann::json(minimum).dump() + " (it is " + m_value->dump() + ")");
  return value;
}

long long JsonField::integer(long long minimum, long long maximum) const {
  if (!m_value->is_number_integer())
    fail(std::string("must be a whole number, not ") + (m_value->is_number() ? m_value->dump() : typeName(*m_value)));
  const bool isUnsigned = m_value->is_number_unsigned();
  if (isUnsigned && m_value->get<unsigned long long>() > static_cast<unsigned long long>(maximum))
    fail("must be at most " + std::to_string(maximum) + " (it is " + m_value->dump() + ")");
  const long long value = m_value->get<long long>();
  if (value < minimum || value > maximum)
    fail("must be between " + std::to_string(minimum) + " and " + std::to_string(maximum) + " (it is " +
         std::to_string(value) + ")");
  return value;
}

Vec3 JsonField::vector() const {
  if (!m_value->is_array() || m_value->size() != 3) fail("must be an array of three numbers [x, y, z]");
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i) {
    const nlohmann::json& c = (*m_value)[i];
    if (!c.is_number() || !std::isfinite(c.get<double>())) fail("must be an array of three finite numbers [x, y, z]");
    v[static_cast<Eigen::Index>(i)] = c.get<double>();
  }
  return v;
}

Vec3 JsonField::unitVector() const {
  const Vec3 v = vector();
  if (std::abs(v.norm() - 1.0) > kUnitVectorTolerance)
    fail("is not a unit vector (its length is " + nlohmann::json(v.norm()).dump() + ")");
  return v.normalized();
}

}  // namespace multidir::core::detail
