#pragma once
// Support structures as values: a skeleton of nodes and struts, and the closed solids printed from it.
#include <string>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::core {

enum class SupportNodeKind {
  Contact,   // touches an overhang of the model (top of a contact tip)
  Tip,       // the bottom of a contact tip, where its strut starts
  Merge,     // where two struts join (Vanek et al.)
  Plane,     // where a strut crosses its region's base plane into the sub-space below (progressive projection)
  Bend,      // where a strut meets a wall of its sub-space and slides along it
  Foot,      // the top of a foot: the tip, upside down, by which a strut ends on the model below it
  Model,     // where a foot touches the model
  Platform,  // where a strut stands on the printer's platform
  Stuck,     // where a strut had to stop inside its sub-space (could not slide along a wall)
};

// "contact", "tip", "merge", "plane", "bend", "foot", "model", "platform", "stuck" (as plan.json spells them).
const char* supportNodeKindName(SupportNodeKind kind);
bool parseSupportNodeKind(const std::string& text, SupportNodeKind& kind);

struct SupportNode {
  Vec3 position;  // mm
  SupportNodeKind kind = SupportNodeKind::Merge;
};

// A straight piece from `upper` to `lower` (node indices), a truncated cone with the given end radii: a
// strut has equal radii, a contact tip ends in the contact radius at the model.
struct SupportStrut {
  std::int32_t upper = 0;
  std::int32_t lower = 0;
  double upperRadiusMm = 0.0;
  double lowerRadiusMm = 0.0;
};

// What a region's supports hold up (issue 29: a region with 0.0 mm^2 risky area showed a support and no
// reason). J_G counts risky faces only; supports also hold up what has no area but still prints in air: a
// lowest point (a vertex below its neighbours where the surface faces down) and a downward edge (a ridge
// between two printable faces that rises less steeply than alpha_max). And struts of regions printed later
// that cross into this region's sub-space are printed with it. docs/supports.md.
struct SupportCause {
  int faceContacts = 0;            // contacts on risky faces
  int pointContacts = 0;           // contacts on lowest points
  int edgeContacts = 0;            // contacts on downward edges ...
  double edgeLengthMm = 0.0;       // ... and the length of those edges they hold up
  double carriedVolumeMm3 = 0.0;   // struts that hold up only regions printed later
};

// The supports printed together with one region (all pieces inside its sub-space Omega_k).
struct SupportSet {
  int regionIndex = 0;                // the region's position in printing order
  std::vector<SupportNode> nodes;
  std::vector<SupportStrut> struts;
  TriangleMesh mesh;                  // one closed prism (or frustum) per strut; solids may overlap at joints
  int strutSides = 8;                 // sides of the prisms in `mesh`
  double volumeMm3 = 0.0;             // signedVolume(mesh): the sum of the solids
  double contactAreaMm2 = 0.0;        // where tips touch the model (a disc of the contact radius each)
  int contacts = 0;                   // tips touching the model (on overhangs and where struts end on it)
  SupportCause cause;                 // what they hold up

  bool empty() const { return struts.empty(); }
};

// The closed solids of a skeleton: strut i becomes a prism (or frustum) with `sides` sides whose polygon
// has the area of the circle of its radius, so its volume is the cone frustum's exactly. Faces carry
// FaceOrigin::surface(i). Struts shorter than 1e-9 mm are left out.
TriangleMesh supportSolids(const std::vector<SupportNode>& nodes, const std::vector<SupportStrut>& struts, int sides);

// Volume of a truncated cone of length `length` with end radii r1, r2 (pi L (r1^2 + r1 r2 + r2^2) / 3).
double frustumVolume(double length, double r1, double r2);

}  // namespace multidir::core
