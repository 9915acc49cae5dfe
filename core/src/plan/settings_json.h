#pragma once
// MachineSpec and SearchOptions as JSON objects, shared by plan files and machine profiles.
#include <nlohmann/json.hpp>

#include "multidir/core/search/machine.h"
#include "multidir/core/search/search_options.h"
#include "plan/json_field.h"

namespace multidir::core::detail {

nlohmann::ordered_json machineToJson(const MachineSpec& machine);
nlohmann::ordered_json searchOptionsToJson(const SearchOptions& options);

// Fields left out take MachineSpec's defaults when `allRequired` is false (hand-written profiles), else
// every field must be there (plan files, which savePlan writes in full). Types and unit vectors are checked
// here (MalformedFile); ranges by validate(MachineSpec) / validate(SearchOptions) (InvalidParameter, the
// message prefixed with the field's path).
MachineSpec machineFromJson(const JsonField& field, bool allRequired);
SearchOptions searchOptionsFromJson(const JsonField& field);

}  // namespace multidir::core::detail
