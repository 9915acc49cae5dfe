#include "plan/supports_json.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::core::detail {
namespace {

using nlohmann::ordered_json;

constexpr long long kMaxSkeleton = 10'000'000;

}  // namespace

std::string supportFileName(std::size_t regionIndex) {
  char name[40];
  std::snprintf(name, sizeof name, "region-%02zu-supports.stl", regionIndex + 1);
  return name;
}

ordered_json supportsToJson(const SupportSet& supports, std::size_t regionIndex) {
  ordered_json nodes = ordered_json::array();
  for (const SupportNode& node : supports.nodes)
    nodes.push_back(ordered_json::array({node.position.x(), node.position.y(), node.position.z(),
                                         supportNodeKindName(node.kind)}));
  ordered_json struts = ordered_json::array();
  for (const SupportStrut& s : supports.struts)
    struts.push_back(ordered_json::array({s.upper, s.lower, s.upperRadiusMm, s.lowerRadiusMm}));
  return {{"file", supportFileName(regionIndex)},
          {"triangles", supports.mesh.triangles.size()},
          {"volumeMm3", supports.volumeMm3},
          {"contactAreaMm2", supports.contactAreaMm2},
          {"contacts", supports.contacts},
          {"strutSides", supports.strutSides},
          {"holdsUp",
           {{"faceContacts", supports.cause.faceContacts},
            {"pointContacts", supports.cause.pointContacts},
            {"edgeContacts", supports.cause.edgeContacts},
            {"edgeLengthMm", supports.cause.edgeLengthMm},
            {"carriedVolumeMm3", supports.cause.carriedVolumeMm3}}},
          {"nodes", nodes},
          {"struts", struts}};
}

SupportsDocument supportsFromJson(const JsonField& field, std::size_t regionIndex) {
  SupportsDocument doc;
  SupportSet& set = doc.supports;
  set.regionIndex = static_cast<int>(regionIndex);
  const JsonField file = field["file"];
  doc.file = file.string();
  if (doc.file != supportFileName(regionIndex)) file.fail("must be \"" + supportFileName(regionIndex) + "\"");
  doc.triangles = static_cast<std::size_t>(field["triangles"].integer(0, 50'000'000));
  set.volumeMm3 = field["volumeMm3"].numberAtLeast(0.0);
  set.contactAreaMm2 = field["contactAreaMm2"].numberAtLeast(0.0);
  set.contacts = static_cast<int>(field["contacts"].integer(0, std::numeric_limits<int>::max()));
  const int sides = static_cast<int>(field["strutSides"].integer(3, 64));
  set.strutSides = sides;
  // Optional: plans written before issue 29 do not say what their supports hold up (then all zero).
  if (const auto holds = field.optional("holdsUp")) {
    constexpr long long kMaxContacts = std::numeric_limits<int>::max();
    set.cause.faceContacts = static_cast<int>((*holds)["faceContacts"].integer(0, kMaxContacts));
    set.cause.pointContacts = static_cast<int>((*holds)["pointContacts"].integer(0, kMaxContacts));
    set.cause.edgeContacts = static_cast<int>((*holds)["edgeContacts"].integer(0, kMaxContacts));
    set.cause.edgeLengthMm = (*holds)["edgeLengthMm"].numberAtLeast(0.0);
    set.cause.carriedVolumeMm3 = (*holds)["carriedVolumeMm3"].numberAtLeast(0.0);
  }

  const JsonField nodes = field["nodes"];
  const std::size_t nodeCount = nodes.arraySize();
  if (nodeCount > static_cast<std::size_t>(kMaxSkeleton)) nodes.fail("holds more nodes than MultiDir reads");
  for (std::size_t i = 0; i < nodeCount; ++i) {
    const JsonField node = nodes.element(i);
    if (node.arraySize() != 4) node.fail("must be [x, y, z, kind]");
    SupportNode n;
    n.position = Vec3(node.element(0).number(), node.element(1).number(), node.element(2).number());
    const JsonField kind = node.element(3);
    if (!parseSupportNodeKind(kind.string(), n.kind))
      kind.fail("is not a node kind (contact, tip, merge, plane, bend, foot, model, platform or stuck)");
    set.nodes.push_back(n);
  }
  const JsonField struts = field["struts"];
  const std::size_t strutCount = struts.arraySize();
  if (strutCount > static_cast<std::size_t>(kMaxSkeleton)) struts.fail("holds more struts than MultiDir reads");
  const auto lastNode = static_cast<long long>(nodeCount) - 1;
  for (std::size_t i = 0; i < strutCount; ++i) {
    const JsonField strut = struts.element(i);
    if (strut.arraySize() != 4) strut.fail("must be [upper node, lower node, upper radius, lower radius]");
    if (lastNode < 0) strut.fail("names a node, but there are none");
    SupportStrut s;
    s.upper = static_cast<std::int32_t>(strut.element(0).integer(0, lastNode));
    s.lower = static_cast<std::int32_t>(strut.element(1).integer(0, lastNode));
    s.upperRadiusMm = strut.element(2).number();
    s.lowerRadiusMm = strut.element(3).number();
    if (!(s.upperRadiusMm > 0 && s.lowerRadiusMm > 0 && s.upperRadiusMm < 1000 && s.lowerRadiusMm < 1000))
      strut.fail("must have radii above 0 and below 1000 mm");
    set.struts.push_back(s);
  }
  set.mesh = supportSolids(set.nodes, set.struts, sides);
  if (set.mesh.triangles.size() != doc.triangles)
    field["triangles"].fail("is " + std::to_string(doc.triangles) + ", but the struts make " +
                            std::to_string(set.mesh.triangles.size()) + " triangles");
  return doc;
}

}  // namespace multidir::core::detail
