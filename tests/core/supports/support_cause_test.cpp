// Why a region has supports (issue 29: bunny region 5 showed 0.0 mm^2 risky and a 20.6 mm^3 support). A support
// holds up what would print in air: a risky face (J_G's area), a lowest point or a downward edge with air below
// it. What rests on material (the bottom of a pit in an upward surface) needs none, and each region's support
// says what it holds up.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "multidir/core/search/decompose.h"
#include "multidir/core/supports/projected_supports.h"
#include "support/test_models.h"

using namespace multidir::core;

namespace {

// Whether `p` lies inside the closed `mesh`: ray parity along three skew directions, the majority (a ray through
// an edge or a vertex may count one crossing twice).
bool insideSolid(const TriangleMesh& mesh, const Vec3& p) {
  const std::array<Vec3, 3> directions = {Vec3(0.1234, 0.9876, 0.0567).normalized(),
                                          Vec3(-0.7071, 0.0312, 0.7011).normalized(),
                                          Vec3(0.5773, -0.5802, 0.5744).normalized()};
  int insideVotes = 0;
  for (const Vec3& dir : directions) {
    int crossings = 0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const Vec3 a = mesh.corner(f, 0), e1 = mesh.corner(f, 1) - a, e2 = mesh.corner(f, 2) - a;
      const Vec3 h = dir.cross(e2);
      const double det = e1.dot(h);
      if (std::abs(det) < 1e-15) continue;
      const Vec3 s = p - a;
      const double u = s.dot(h) / det;
      if (u < 0 || u > 1) continue;
      const Vec3 q = s.cross(e1);
      const double v = dir.dot(q) / det;
      if (v < 0 || u + v > 1) continue;
      if (e2.dot(q) / det > 0) ++crossings;
    }
    insideVotes += crossings % 2;
  }
  return insideVotes >= 2;
}

// The bunny's default plan in the studio (5-DOF, up +Z, the default search) and its supports.
struct BunnyPlan {
  TriangleMesh model;
  Decomposition plan;
  ProjectedSupports supports;
};

const BunnyPlan& bunnyPlan() {
  static const BunnyPlan result = [] {
    BunnyPlan b;
    b.model = multidir::test::loadSharedModel("bunny.off");
    MachineSpec machine;
    machine.up = Vec3::UnitZ();
    JobContext job;
    b.plan = decompose(b.model, machine, SearchOptions{}, job).value();
    b.supports = generateSupports(b.model, b.plan, machine, SupportOptions{}, job).value();
    return b;
  }();
  return result;
}

}  // namespace

TEST(SupportCause, NoStrutOfTheBunnyPlanRunsInsideTheModel) {
  const BunnyPlan& b = bunnyPlan();
  for (const SupportSet& set : b.supports.regions)
    for (const SupportStrut& strut : set.struts) {
      const Vec3 middle = 0.5 * (set.nodes[strut.upper].position + set.nodes[strut.lower].position);
      EXPECT_FALSE(insideSolid(b.model, middle))
          << "region " << set.regionIndex + 1 << ": a strut " << supportNodeKindName(set.nodes[strut.upper].kind)
          << " -> " << supportNodeKindName(set.nodes[strut.lower].kind) << " inside the model at (" << middle.x()
          << ", " << middle.y() << ", " << middle.z() << ")";
    }
}

TEST(SupportCause, EveryContactHasAirBelowItAlongItsRegionsDirection) {
  const BunnyPlan& b = bunnyPlan();
  for (const SupportSet& set : b.supports.regions) {
    const Vec3 d = b.plan.regions[static_cast<std::size_t>(set.regionIndex)].printingDirection;
    for (const SupportNode& node : set.nodes) {
      if (node.kind != SupportNodeKind::Contact) continue;
      EXPECT_FALSE(insideSolid(b.model, node.position - 0.05 * d))
          << "region " << set.regionIndex + 1 << ": a contact rests on material at (" << node.position.x() << ", "
          << node.position.y() << ", " << node.position.z() << ")";
    }
  }
}

TEST(SupportCause, EachRegionsSupportSaysWhatItHoldsUp) {
  const BunnyPlan& b = bunnyPlan();
  for (const SupportSet& set : b.supports.regions) {
    const Region& region = b.plan.regions[static_cast<std::size_t>(set.regionIndex)];
    const SupportCause& cause = set.cause;
    int contacts = 0;
    for (const SupportNode& node : set.nodes) contacts += node.kind == SupportNodeKind::Contact ? 1 : 0;
    EXPECT_EQ(cause.faceContacts + cause.pointContacts + cause.edgeContacts, contacts) << "region " << set.regionIndex + 1;
    EXPECT_EQ(cause.edgeContacts > 0, cause.edgeLengthMm > 0) << "region " << set.regionIndex + 1;
    EXPECT_LE(cause.carriedVolumeMm3, set.volumeMm3 * (1 + 1e-9) + 1e-9) << "region " << set.regionIndex + 1;
    // A region with no risky area has support only for a lowest point, a downward edge or a later region's struts.
    if (region.riskyAreaMm2 < 0.05 && set.volumeMm3 > 0) {
      EXPECT_TRUE(cause.pointContacts > 0 || cause.edgeContacts > 0 || cause.carriedVolumeMm3 > 0)
          << "region " << set.regionIndex + 1 << ": " << set.volumeMm3 << " mm^3 holding up nothing";
    }
    if (set.empty()) {
      EXPECT_EQ(contacts, 0);
    }
  }
}
