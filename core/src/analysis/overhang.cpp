#include "multidir/core/analysis/overhang.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace multidir::core {

Status validate(const OverhangOptions& options) {
  if (!(options.alphaMaxDegrees >= 0.0 && options.alphaMaxDegrees < 90.0))
    return Error{ErrorCode::InvalidParameter,
                 "the maximal self-supporting angle must be at least 0 and below 90 degrees (got " +
                     std::to_string(options.alphaMaxDegrees) + "); 45 suits most FDM printers",
                 "alpha"};
  if (!(options.supportedBandMm >= 0.0 && options.supportedBandMm <= 100.0))
    return Error{ErrorCode::InvalidParameter,
                 "the supported band above the platform must be between 0 and 100 mm (got " +
                     std::to_string(options.supportedBandMm) + ")",
                 "supported band"};
  return Done{};
}

double triangleAreaAbove(std::array<double, 3> heights, double area, double level) {
  std::sort(heights.begin(), heights.end());
  const double ha = heights[0], hb = heights[1], hc = heights[2];
  if (level <= ha) return area;
  if (level >= hc) return 0.0;
  // The area below a level grows quadratically from the lowest corner and shrinks quadratically to the top.
  if (level < hb) return area - area * (level - ha) * (level - ha) / ((hb - ha) * (hc - ha));
  return area * (hc - level) * (hc - level) / ((hc - ha) * (hc - hb));
}

double inPlaneToleranceMm(const TriangleMesh& mesh) {
  double largest = 1.0;
  for (const Vec3& v : mesh.vertices) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  return 1e-6 * largest;
}

Result<OverhangAnalysis> analyzeOverhang(const TriangleMesh& mesh, const Vec3& printingDirection,
                                         const OverhangOptions& options) {
  if (Status s = validate(options); !s) return s.error();
  const double length = printingDirection.norm();
  if (!std::isfinite(length) || length < 1e-12)
    return Error{ErrorCode::InvalidParameter, "the printing direction must be a finite, non-zero vector",
                 "direction"};
  const Vec3 d = printingDirection / length;
  const double sinAlpha = std::sin(degToRad(options.alphaMaxDegrees));

  OverhangAnalysis out;
  out.risky.assign(mesh.triangles.size(), 0);
  out.riskyFaceAreaMm2.assign(mesh.triangles.size(), 0.0);
  double lowest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t) lowest = std::min(lowest, d.dot(mesh.vertices[v]));
  out.platformHeightMm = mesh.triangles.empty() ? 0.0 : lowest;

  const bool onPlatform = options.base == RegionBase::Platform;
  const double inPlane = onPlatform ? 0.0 : inPlaneToleranceMm(mesh);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Vec3 areaNormal = mesh.areaNormal(f);
    const double doubleArea = areaNormal.norm();
    if (doubleArea <= 0.0) continue;
    if (areaNormal.dot(d) / doubleArea + sinAlpha >= 0.0) continue;
    const std::array<double, 3> heights = {d.dot(mesh.corner(f, 0)), d.dot(mesh.corner(f, 1)), d.dot(mesh.corner(f, 2))};
    double counted = 0.0;
    if (onPlatform) {
      counted = triangleAreaAbove(heights, 0.5 * doubleArea, lowest + options.supportedBandMm);
    } else {
      // The cap rests on the cap of the material below; nothing else above a cut plane is held up.
      const bool inBasePlane = *std::max_element(heights.begin(), heights.end()) - lowest <= inPlane;
      counted = inBasePlane ? 0.0 : 0.5 * doubleArea;
    }
    if (counted <= 0.0) continue;
    out.risky[f] = 1;
    out.riskyFaceAreaMm2[f] = counted;
    ++out.riskyFaces;
    out.riskyAreaMm2 += counted;
  }
  return out;
}

Result<double> riskyAreaOnPlatform(const TriangleMesh& solid, const Vec3& direction, double alphaMaxDegrees,
                                   double supportedBandMm) {
  OverhangOptions options;
  options.alphaMaxDegrees = alphaMaxDegrees;
  options.supportedBandMm = supportedBandMm;
  options.base = RegionBase::Platform;
  auto analysis = analyzeOverhang(solid, direction, options);
  if (!analysis.ok()) return analysis.error();
  return analysis->riskyAreaMm2;
}

Result<Vec3> parseDirection(const std::string& text) {
  std::string s = text;
  double sign = 1.0;
  if (!s.empty() && (s[0] == '-' || s[0] == '+') && s.size() == 2) {
    sign = s[0] == '-' ? -1.0 : 1.0;
    s = s.substr(1);
  }
  if (s == "x" || s == "X") return Vec3(sign, 0, 0);
  if (s == "y" || s == "Y") return Vec3(0, sign, 0);
  if (s == "z" || s == "Z") return Vec3(0, 0, sign);

  std::istringstream in(text);
  Vec3 v;
  char comma1 = 0, comma2 = 0;
  if (in >> v.x() >> comma1 >> v.y() >> comma2 >> v.z() && comma1 == ',' && comma2 == ',') {
    std::string rest;
    if (!(in >> rest) && v.allFinite() && v.norm() > 1e-12) return Vec3(v.normalized());
  }
  return Error{ErrorCode::InvalidParameter,
               "'" + text + "' is not a direction: use x, y, z, -x, -y, -z or three numbers like 0,1,0",
               "up"};
}

}  // namespace multidir::core
