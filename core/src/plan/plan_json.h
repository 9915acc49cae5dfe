#pragma once
// plan.json <-> Decomposition + PlanMetadata (docs/plan-format.md). The region meshes live in STL files;
// this layer only names them and carries what STL cannot: triangle counts and face origins.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "multidir/core/plan/plan_file.h"

namespace multidir::core::detail {

// What plan.json says; the regions' meshes are still empty.
struct PlanDocument {
  LoadedPlan plan;
  std::vector<std::string> regionFiles;  // plain file names in the plan's folder
  std::vector<std::size_t> regionTriangles;
  std::vector<std::vector<FaceOrigin>> regionOrigins;
  std::vector<std::string> supportFiles;  // per region; empty where the region has no supports
  std::vector<std::size_t> supportTriangles;
};

// "region-01.stl" for the region at printing position 0.
std::string regionFileName(std::size_t index);

// `supports`: none, or one per region (a region whose set is empty gets no `supports` field).
nlohmann::ordered_json planToJson(const Decomposition& plan, const PlanMetadata& metadata,
                                  const std::vector<SupportSet>& supports = {});

// Checks every field (throws JsonFieldError naming `fileName` and the field on the first violation).
PlanDocument planFromJson(const nlohmann::json& document, const std::string& fileName);

}  // namespace multidir::core::detail
