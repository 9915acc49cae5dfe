#include "multidir/core/plan/json_text.h"

#include "plan/json_file.h"

namespace multidir::core {

Status checkJsonText(const std::string& text, const std::string& name) {
  Result<nlohmann::json> parsed = detail::parseJsonText(text, name);
  if (!parsed) return parsed.error();
  return Done{};
}

}  // namespace multidir::core
