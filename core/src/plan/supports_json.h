#pragma once
// A region's supports in plan.json (docs/plan-format.md, regions[i].supports): the skeleton, its totals and
// the STL that holds its solids. The solids are rebuilt from the skeleton on load.
#include <nlohmann/json.hpp>
#include <string>

#include "multidir/core/supports/support_set.h"
#include "plan/json_field.h"

namespace multidir::core::detail {

// "region-01-supports.stl" for the region at printing position 0.
std::string supportFileName(std::size_t regionIndex);

nlohmann::ordered_json supportsToJson(const SupportSet& supports, std::size_t regionIndex);

struct SupportsDocument {
  SupportSet supports;   // mesh rebuilt from the skeleton
  std::string file;
  std::size_t triangles = 0;
};

// Checks every field (throws JsonFieldError on the first violation) and rebuilds the solids.
SupportsDocument supportsFromJson(const JsonField& field, std::size_t regionIndex);

}  // namespace multidir::core::detail
