#include "multidir/core/supports/support_set.h"

#include <array>
#include <cmath>

#include "multidir/core/common/units.h"

namespace multidir::core {
namespace {

constexpr std::array<const char*, 9> kNodeKindNames = {"contact", "tip",   "merge",    "plane", "bend",
                                                       "foot",    "model", "platform", "stuck"};

// Two unit vectors perpendicular to `axis` (unit) and to each other.
void perpendicularFrame(const Vec3& axis, Vec3& e1, Vec3& e2) {
  const Vec3 helper = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  e1 = axis.cross(helper).normalized();
  e2 = axis.cross(e1);
}

}  // namespace

const char* supportNodeKindName(SupportNodeKind kind) { return kNodeKindNames[static_cast<std::size_t>(kind)]; }

bool parseSupportNodeKind(const std::string& text, SupportNodeKind& kind) {
  for (std::size_t i = 0; i < kNodeKindNames.size(); ++i)
    if (text == kNodeKindNames[i]) {
      kind = static_cast<SupportNodeKind>(i);
      return true;
    }
  return false;
}

double frustumVolume(double length, double r1, double r2) { return kPi * length * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0; }

TriangleMesh supportSolids(const std::vector<SupportNode>& nodes, const std::vector<SupportStrut>& struts, int sides) {
  TriangleMesh mesh;
  // A regular n-gon of circumradius r has area n r^2 sin(2 pi / n) / 2: scaling by this keeps pi r^2.
  const double areaScale = std::sqrt(2.0 * kPi / (sides * std::sin(2.0 * kPi / sides)));
  // Struts in one line (through a plane or bend node) would share ring corners exactly; turning each ring by
  // the golden angle keeps the solids' corners apart, so each solid stays a closed surface of its own.
  constexpr double kGoldenAngle = 2.39996322972865332;
  for (std::size_t s = 0; s < struts.size(); ++s) {
    const Vec3& top = nodes[static_cast<std::size_t>(struts[s].upper)].position;
    const Vec3& bottom = nodes[static_cast<std::size_t>(struts[s].lower)].position;
    const Vec3 axisVector = top - bottom;
    const double length = axisVector.norm();
    if (!(length > 1e-9)) continue;
    const Vec3 axis = axisVector / length;
    Vec3 e1, e2;
    perpendicularFrame(axis, e1, e2);
    const auto first = static_cast<std::int32_t>(mesh.vertices.size());
    const double phase = kGoldenAngle * static_cast<double>(s);
    for (int ring = 0; ring < 2; ++ring) {
      const Vec3& center = ring == 0 ? bottom : top;
      const double radius = areaScale * (ring == 0 ? struts[s].lowerRadiusMm : struts[s].upperRadiusMm);
      for (int k = 0; k < sides; ++k) {
        const double angle = phase + 2.0 * kPi * k / sides;
        mesh.vertices.push_back(center + radius * (std::cos(angle) * e1 + std::sin(angle) * e2));
      }
    }
    // Rings turn counter-clockwise about the axis (bottom to top): sides face out, the bottom cap faces
    // down the axis and the top cap up it.
    auto at = [&](int ring, int k) { return first + ring * sides + (k % sides); };
    for (int k = 0; k < sides; ++k) {
      mesh.triangles.push_back({at(0, k), at(0, k + 1), at(1, k + 1)});
      mesh.triangles.push_back({at(0, k), at(1, k + 1), at(1, k)});
    }
    for (int k = 1; k + 1 < sides; ++k) {
      mesh.triangles.push_back({at(0, 0), at(0, k + 1), at(0, k)});
      mesh.triangles.push_back({at(1, 0), at(1, k), at(1, k + 1)});
    }
    mesh.origins.resize(mesh.triangles.size(), FaceOrigin::surface(static_cast<std::int32_t>(s)));
  }
  return mesh;
}

}  // namespace multidir::core
