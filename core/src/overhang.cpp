#include "multidir/core/analysis/overhang.h"

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
  if (!(options.platformToleranceMm >= 0.0 && std::isfinite(options.platformToleranceMm)))
    return Error{ErrorCode::InvalidParameter, "the platform tolerance must be a finite length >= 0 mm",
                 "platform tolerance"};
  return Done{};
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
  double lowest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t) lowest = std::min(lowest, d.dot(mesh.vertices[v]));
  out.platformHeightMm = mesh.triangles.empty() ? 0.0 : lowest;

  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Vec3 areaNormal = mesh.areaNormal(f);
    const double doubleArea = areaNormal.norm();
    if (doubleArea <= 0.0) continue;
    if (areaNormal.dot(d) / doubleArea + sinAlpha >= 0.0) continue;
    bool onPlatform = true;
    for (int k = 0; k < 3 && onPlatform; ++k)
      onPlatform = d.dot(mesh.corner(f, k)) - lowest <= options.platformToleranceMm;
    if (onPlatform) continue;
    out.risky[f] = 1;
    ++out.riskyFaces;
    out.riskyAreaMm2 += 0.5 * doubleArea;
  }
  return out;
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
