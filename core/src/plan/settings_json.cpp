#include "plan/settings_json.h"

#include <limits>

namespace multidir::core::detail {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// A member's field, or nothing when it may be left out and is.
std::optional<JsonField> member(const JsonField& object, const char* key, bool required) {
  if (required) return object[key];
  return object.optional(key);
}

int smallInteger(const JsonField& field) {
  return static_cast<int>(field.integer(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

}  // namespace

ordered_json machineToJson(const MachineSpec& m) {
  ordered_json cones = ordered_json::array();
  for (const ForbiddenCone& cone : m.forbiddenCones)
    cones.push_back({{"axis", toJson(cone.axis)}, {"halfAngleDegrees", cone.halfAngleDegrees}});
  return {{"kind", machineKindName(m.kind)},        {"up", toJson(m.up)},
          {"platformRadiusMm", m.platformRadiusMm}, {"platformMarginMm", m.platformMarginMm},
          {"rotationAxis", toJson(m.rotationAxis)}, {"minAngleDegrees", m.minAngleDegrees},
          {"maxAngleDegrees", m.maxAngleDegrees},   {"angleStepDegrees", m.angleStepDegrees},
          {"maxTiltDegrees", m.maxTiltDegrees},     {"forbiddenCones", cones}};
}

ordered_json searchOptionsToJson(const SearchOptions& o) {
  return {{"scheme", schemeName(o.scheme)},
          {"beamWidth", o.beamWidth},
          {"alphaMaxDegrees", o.alphaMaxDegrees},
          {"normalSamples", o.candidates.normalSamples},
          {"offsetStepMm", o.candidates.offsetStepMm},
          {"platformClearanceMm", o.candidates.platformClearanceMm},
          {"minVolumeDivisor", o.minVolumeDivisor},
          {"volumeScales", o.volumeScales},
          {"initialDeltaMm2", o.initialDeltaMm2},
          {"deltaGrowth", o.deltaGrowth},
          {"diversityCosine", o.diversityCosine},
          {"diversityOffsetMm", o.diversityOffsetMm},
          {"refinementRounds", o.refinementRounds},
          {"supportedBandMm", o.supportedBandMm},
          {"minRegionHeightMm", o.minRegionHeightMm},
          {"minPlaneGainPercent", o.minPlaneGainPercent},
          {"minPlaneGainMm2", o.minPlaneGainMm2},
          {"partCostMm2", o.partCostMm2},
          {"cutFaceCost", o.cutFaceCost},
          {"proxyFaces", o.proxyFaces},
          {"polish", o.polish},
          {"polishEffort", o.polishEffort},
          {"polishFinalists", o.polishFinalists},
          {"searchTails", o.searchTails},
          {"platformToleranceMm", o.platformToleranceMm},
          {"threads", o.threads}};
}

MachineSpec machineFromJson(const JsonField& field, bool allRequired) {
  MachineSpec m;
  const JsonField kind = field["kind"];
  const Result<MachineKind> parsed = parseMachineKind(kind.string());
  if (!parsed) kind.fail("must be \"3dof\", \"4dof\", \"5dof\" or \"apart\"");
  m.kind = *parsed;
  if (auto f = member(field, "up", allRequired)) m.up = f->unitVector();
  if (auto f = member(field, "platformRadiusMm", allRequired)) m.platformRadiusMm = f->number();
  if (auto f = member(field, "platformMarginMm", allRequired)) m.platformMarginMm = f->number();
  if (auto f = member(field, "rotationAxis", allRequired)) m.rotationAxis = f->unitVector();
  if (auto f = member(field, "minAngleDegrees", allRequired)) m.minAngleDegrees = f->number();
  if (auto f = member(field, "maxAngleDegrees", allRequired)) m.maxAngleDegrees = f->number();
  if (auto f = member(field, "angleStepDegrees", allRequired)) m.angleStepDegrees = f->number();
  if (auto f = member(field, "maxTiltDegrees", allRequired)) m.maxTiltDegrees = f->number();
  if (auto cones = member(field, "forbiddenCones", allRequired)) {
    const std::size_t count = cones->arraySize();
    if (count > 1000) cones->fail("lists " + std::to_string(count) + " cones; at most 1000 are accepted");
    for (std::size_t i = 0; i < count; ++i) {
      const JsonField cone = cones->element(i);
      m.forbiddenCones.push_back({cone["axis"].unitVector(), cone["halfAngleDegrees"].number()});
    }
  }
  if (m.kind != MachineKind::RotaryPlatform && !member(field, "rotationAxis", allRequired))
    m.rotationAxis = platformFrameX(m.up);  // unused by the machine, but keep it consistent with up
  if (Status valid = validate(m); !valid) field.failInside(valid.error().message, ErrorCode::InvalidParameter);
  return m;
}

SearchOptions searchOptionsFromJson(const JsonField& field) {
  SearchOptions o;
  const JsonField scheme = field["scheme"];
  const Result<SearchScheme> parsed = parseScheme(scheme.string());
  if (!parsed) scheme.fail("must be \"beam\", \"greedy\" or \"cgreedy\"");
  o.scheme = *parsed;
  o.beamWidth = smallInteger(field["beamWidth"]);
  o.alphaMaxDegrees = field["alphaMaxDegrees"].number();
  o.candidates.normalSamples = smallInteger(field["normalSamples"]);
  o.candidates.offsetStepMm = field["offsetStepMm"].number();
  o.candidates.platformClearanceMm = field["platformClearanceMm"].number();
  o.minVolumeDivisor = field["minVolumeDivisor"].number();
  // Plans written before the beam ran at several scales ran it at w alone.
  const auto scales = field.optional("volumeScales");
  o.volumeScales = scales ? smallInteger(*scales) : 1;
  o.initialDeltaMm2 = field["initialDeltaMm2"].number();
  o.deltaGrowth = field["deltaGrowth"].number();
  o.diversityCosine = field["diversityCosine"].number();
  o.diversityOffsetMm = field["diversityOffsetMm"].number();
  // Plans written before refinement existed were searched without it.
  const auto refinement = field.optional("refinementRounds");
  o.refinementRounds = refinement ? smallInteger(*refinement) : 0;
  // Plans written before these existed: the band was the default, and there were no printability limits.
  const auto band = field.optional("supportedBandMm");
  o.supportedBandMm = band ? band->number() : kDefaultSupportedBandMm;
  const auto minHeight = field.optional("minRegionHeightMm");
  o.minRegionHeightMm = minHeight ? minHeight->number() : 0.0;
  const auto gainPercent = field.optional("minPlaneGainPercent");
  o.minPlaneGainPercent = gainPercent ? gainPercent->number() : 0.0;
  const auto gainArea = field.optional("minPlaneGainMm2");
  o.minPlaneGainMm2 = gainArea ? gainArea->number() : 0.0;
  // Plans saved before the apart machine existed: no part was ever cost.
  const auto partCost = field.optional("partCostMm2");
  o.partCostMm2 = partCost ? partCost->number() : kDefaultPartCostMm2;
  // Plans saved before the cut face was priced: a part had its fixed price only.
  const auto cutFaceCost = field.optional("cutFaceCost");
  o.cutFaceCost = cutFaceCost ? cutFaceCost->number() : 0.0;
  // Plans saved before the proxy search ran on the full mesh.
  const auto proxy = field.optional("proxyFaces");
  o.proxyFaces = proxy ? static_cast<int>(proxy->integer(0, 10000000)) : 0;
  // Plans saved before polishing existed were not polished.
  const auto polish = field.optional("polish");
  o.polish = polish ? polish->boolean() : false;
  if (const auto effort = field.optional("polishEffort")) o.polishEffort = smallInteger(*effort);
  // Plans saved before this option polished the search's own plan only.
  const auto finalists = field.optional("polishFinalists");
  o.polishFinalists = finalists ? finalists->boolean() : false;
  // Plans saved before this option did not search the tails again.
  const auto tails = field.optional("searchTails");
  o.searchTails = tails ? tails->boolean() : false;
  o.platformToleranceMm = field["platformToleranceMm"].number();
  o.threads = smallInteger(field["threads"]);
  if (Status valid = validate(o); !valid) field.failInside(valid.error().message, ErrorCode::InvalidParameter);
  return o;
}

}  // namespace multidir::core::detail
