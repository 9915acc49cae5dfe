#pragma once
// How a solid stands on a flat bed (docs/search.md, "The pose search"): the patch of its convex hull that
// touches the bed when a given direction points up, and how far inside that patch its centre of mass falls.
#include <vector>

#include "multidir/core/search/convex_hull.h"

namespace multidir::core {

// Hull corners this close to the bed count as touching it: the first layer, squashed onto the bed, fills a gap
// of half its height under the part, and it is 0.2 mm or more in every printer profile MultiDir ships
// (resources/printers; docs/search.md).
constexpr double kContactToleranceMm = 0.1;

struct ContactPatch {
  Vec3 up = Vec3::UnitZ();  // unit: the direction that points away from the bed
  // The touching corners' convex outline on the bed plane, counter-clockwise seen from above; one corner is a
  // point contact, two an edge.
  std::vector<Vec3> outline;
  double areaMm2 = 0.0;
  // Signed distance from the centre of mass's projection on the bed to the outline's boundary: > 0 inside,
  // <= 0 on or outside it (the solid tips over). A point or an edge contact is never > 0.
  double stabilityMarginMm = 0.0;
  bool stands() const { return areaMm2 > 0.0 && stabilityMarginMm > 0.0; }
};

// Centre of mass of a closed solid of uniform density, from its volume (signed tetrahedra from the origin).
Vec3 solidCentreOfMass(const TriangleMesh& solid);

// The patch the hull stands on with `up` (any non-zero length) pointing up: every hull corner within
// kContactToleranceMm of the lowest along up.
ContactPatch contactPatch(const ConvexHull& hull, const Vec3& up, const Vec3& centreOfMass);

// Every pose in which the hull stands: the planes of its faces whose patch holds the centre of mass, largest
// area first (ties: larger margin). Patches whose ups lie within `mergeDegrees` of a larger one's are that
// pose again and left out.
std::vector<ContactPatch> standingPatches(const ConvexHull& hull, const Vec3& centreOfMass, double mergeDegrees);

}  // namespace multidir::core
