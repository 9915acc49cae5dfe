#include "search/unavoidable_risky_area.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "multidir/core/common/units.h"
#include "search/floating_pieces.h"

namespace multidir::core::detail {

namespace {

// The margin that keeps a face risky by rounding alone out of the bound, and a face the machine reaches within
// isRealizable's tolerance (1e-6 rad) in: a saved face is never counted. The heights' margin is how far
// clipping may move a point (clipMarginMm: snapping a corner near the plane onto it).
constexpr double kDotMargin = 1e-6;

// Every direction the machine prints along: up (the platform's region) and up turned by each whole stepper
// step of the range, min + i step (isRealizable's angles).
std::vector<Vec3> realizableDirections(const MachineSpec& machine) {
  std::vector<Vec3> directions{machine.up.normalized()};
  const int steps =
      static_cast<int>(std::floor((machine.maxAngleDegrees - machine.minAngleDegrees) / machine.angleStepDegrees + 1e-9));
  for (int i = 0; i <= steps; ++i) {
    const double angle = machine.minAngleDegrees + i * machine.angleStepDegrees;
    if (std::abs(angle) > 1e-9) directions.push_back(rotaryDirection(machine, angle).normalized());
  }
  return directions;
}

// P's highest point along `d` (as planeClearsPlatform measures it).
double platformTopAlong(const Vec3& d, const PlatformRegion& platform, const Vec3& up) {
  return d.dot(platform.center) + platform.radiusMm * (d - d.dot(up) * up).norm();
}

// A face of the model as the bound sees it.
struct BoundFace {
  Vec3 normal;                   // unit
  std::array<Vec3, 3> corners;
  double area = 0.0;
};

// The faces the bound may count: risky along up (up prints the platform's region, which holds anything, so a
// face up saves is saved) and with no corner in the bed's band.
std::vector<BoundFace> facesRiskyAlongUp(const TriangleMesh& model, const Vec3& up, double sinAlpha,
                                         double supportedBandMm) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& v : model.vertices) lowest = std::min(lowest, up.dot(v));
  const double bandTop = lowest + supportedBandMm;
  std::vector<BoundFace> faces;
  for (std::size_t f = 0; f < model.faceCount(); ++f) {
    const Vec3 areaNormal = model.areaNormal(f);
    const double length = areaNormal.norm();
    if (!(length > 0)) continue;
    BoundFace face{areaNormal / length, {model.corner(f, 0), model.corner(f, 1), model.corner(f, 2)}, 0.5 * length};
    if (face.normal.dot(up) + sinAlpha >= -kDotMargin) continue;
    if (std::min({up.dot(face.corners[0]), up.dot(face.corners[1]), up.dot(face.corners[2])}) <= bandTop) continue;
    faces.push_back(face);
  }
  return faces;
}

// Whether a region printed along `d` could hold a piece of `face` and save it.
bool savesAlong(const BoundFace& face, const Vec3& d, double top, double sinAlpha, double heightMarginMm) {
  if (face.normal.dot(d) + sinAlpha < -kDotMargin) return false;  // risky along d
  return std::max({d.dot(face.corners[0]), d.dot(face.corners[1]), d.dot(face.corners[2])}) > top - heightMarginMm;
}

// The faces in the order the bound visits them: as the mesh lists them for the whole sum (so that it is the same
// sum, bit for bit, whoever asks); largest first when the sum may stop above `stopAboveMm2`, so that it gets
// there after as few of the costly faces no direction saves as it can.
std::vector<BoundFace> facesToVisit(const TriangleMesh& model, const Vec3& up, double sinAlpha, double supportedBandMm,
                                    double stopAboveMm2) {
  std::vector<BoundFace> faces = facesRiskyAlongUp(model, up, sinAlpha, supportedBandMm);
  if (std::isfinite(stopAboveMm2))
    std::stable_sort(faces.begin(), faces.end(),
                     [](const BoundFace& a, const BoundFace& b) { return a.area > b.area; });
  return faces;
}

double rotaryBound(const TriangleMesh& model, const MachineSpec& machine, const PlatformRegion& platform,
                   double sinAlpha, double supportedBandMm, double stopAboveMm2) {
  const Vec3 up = machine.up.normalized();
  std::vector<Vec3> directions = realizableDirections(machine);
  directions.erase(directions.begin());  // up: facesRiskyAlongUp left out what it saves
  std::vector<double> tops(directions.size());
  for (std::size_t k = 0; k < directions.size(); ++k) tops[k] = platformTopAlong(directions[k], platform, up);
  const double heightMarginMm = clipMarginMm(model);
  double area = 0.0;
  for (const BoundFace& face : facesToVisit(model, up, sinAlpha, supportedBandMm, stopAboveMm2)) {
    bool saved = false;
    for (std::size_t k = 0; k < directions.size() && !saved; ++k)
      saved = savesAlong(face, directions[k], tops[k], sinAlpha, heightMarginMm);
    if (!saved) area += face.area;
    if (area > stopAboveMm2) break;
  }
  return area;
}

// A cell of the cube map of directions: on the cube face `axis` (0-2: x, y, z) `sign`, the square [u0, u1] x
// [v0, v1] of that face's plane (coordinates in [-1, 1]); its directions are the square's points normalized.
struct DirectionCell {
  int axis = 0;
  double sign = 1.0;
  double u0 = -1, u1 = 1, v0 = -1, v1 = 1;

  Vec3 direction(double u, double v) const {
    Vec3 d;
    d[axis] = sign;
    d[(axis + 1) % 3] = u;
    d[(axis + 2) % 3] = v;
    return d.normalized();
  }
  Vec3 centre() const { return direction((u0 + u1) / 2, (v0 + v1) / 2); }
  // The largest angle from the centre to a direction of the cell: at a corner (a cell lies within a
  // hemisphere and is geodesically convex, and the angle to a point is quasi-convex there).
  double radius(const Vec3& centre) const {
    double smallestCos = 1.0;
    for (const Vec3& corner : {direction(u0, v0), direction(u0, v1), direction(u1, v0), direction(u1, v1)})
      smallestCos = std::min(smallestCos, centre.dot(corner));
    return std::acos(std::clamp(smallestCos, -1.0, 1.0));
  }
  std::array<DirectionCell, 4> quarters() const {
    const double um = (u0 + u1) / 2, vm = (v0 + v1) / 2;
    return {DirectionCell{axis, sign, u0, um, v0, vm}, DirectionCell{axis, sign, um, u1, v0, vm},
            DirectionCell{axis, sign, u0, um, vm, v1}, DirectionCell{axis, sign, um, u1, vm, v1}};
  }
};

// The cells are split down to about a hundredth of a degree (a cube face's 90 degrees over 8 x 2^10).
constexpr int kRootCellsPerSide = 8;
constexpr int kDeepestSplit = 10;

class TiltBound {
 public:
  TiltBound(const MachineSpec& machine, const PlatformRegion& platform, double sinAlpha, double heightMarginMm)
      : m_machine(machine), m_up(machine.up.normalized()), m_platform(platform), m_sinAlpha(sinAlpha),
        m_heightMarginMm(heightMarginMm), m_maxTilt(degToRad(machine.maxTiltDegrees)) {
    for (int axis = 0; axis < 3; ++axis)
      for (const double sign : {1.0, -1.0})
        for (int i = 0; i < kRootCellsPerSide; ++i)
          for (int j = 0; j < kRootCellsPerSide; ++j) {
            const double step = 2.0 / kRootCellsPerSide;
            m_roots.push_back({axis, sign, -1 + i * step, -1 + (i + 1) * step, -1 + j * step, -1 + (j + 1) * step});
          }
    for (const DirectionCell& root : m_roots) {
      m_rootCentres.push_back(root.centre());
      m_rootTops.push_back(platformTopAlong(m_rootCentres.back(), m_platform, m_up));
      m_rootRealizable.push_back(isRealizable(m_machine, m_rootCentres.back()));
    }
  }

  // Whether some realizable direction may save the face (false only when none can).
  bool maySave(const BoundFace& face) const {
    // How far a corner's height above P's top can change per radian of d: d.(x - P's centre) and
    // P's radius x |d off up| change by at most |x - centre| and the radius.
    double slope = 0.0;
    for (const Vec3& corner : face.corners) slope = std::max(slope, (corner - m_platform.center).norm());
    slope += m_platform.radiusMm;
    // Most faces that can be saved are saved along some cell's centre: tried first, before any split.
    for (std::size_t k = 0; k < m_roots.size(); ++k)
      if (m_rootRealizable[k] && savesAlong(face, m_rootCentres[k], m_rootTops[k], m_sinAlpha, m_heightMarginMm))
        return true;
    for (const DirectionCell& root : m_roots)
      if (maySaveIn(face, root, slope, 0)) return true;
    return false;
  }

 private:
  bool maySaveIn(const BoundFace& face, const DirectionCell& cell, double slope, int depth) const {
    const Vec3 d = cell.centre();
    const double rho = cell.radius(d);  // every direction of the cell lies within rho (a chord of at most rho)
    // No direction of the cell is within the tilt limit (forbidden cones only shrink the set: left out here).
    if (std::acos(std::clamp(d.dot(m_up), -1.0, 1.0)) > m_maxTilt + rho + kDotMargin) return false;
    if (face.normal.dot(d) + m_sinAlpha < -rho - kDotMargin) return false;  // risky along all of them
    const double top = platformTopAlong(d, m_platform, m_up);
    const double above =
        std::max({d.dot(face.corners[0]), d.dot(face.corners[1]), d.dot(face.corners[2])}) - (top - m_heightMarginMm);
    if (above + rho * slope <= 0) return false;  // below P's top along all of them
    if (isRealizable(m_machine, d) && savesAlong(face, d, top, m_sinAlpha, m_heightMarginMm)) return true;
    if (depth == kDeepestSplit) return true;  // undecided: counted as saving, so the bound stays one
    for (const DirectionCell& quarter : cell.quarters())
      if (maySaveIn(face, quarter, slope, depth + 1)) return true;
    return false;
  }

  const MachineSpec& m_machine;
  Vec3 m_up;
  const PlatformRegion& m_platform;
  double m_sinAlpha;
  double m_heightMarginMm;
  double m_maxTilt;
  std::vector<DirectionCell> m_roots;
  std::vector<Vec3> m_rootCentres;
  std::vector<double> m_rootTops;
  std::vector<bool> m_rootRealizable;
};

double tiltBound(const TriangleMesh& model, const MachineSpec& machine, const PlatformRegion& platform,
                 double sinAlpha, double supportedBandMm, double stopAboveMm2) {
  const TiltBound bound(machine, platform, sinAlpha, clipMarginMm(model));
  double area = 0.0;
  for (const BoundFace& face : facesToVisit(model, machine.up.normalized(), sinAlpha, supportedBandMm, stopAboveMm2)) {
    if (!bound.maySave(face)) area += face.area;
    if (area > stopAboveMm2) break;
  }
  return area;
}

}  // namespace

double unavoidableRiskyAreaMm2(const TriangleMesh& model, const MachineSpec& machine, const PlatformRegion& platform,
                               double alphaMaxDegrees, double supportedBandMm, double stopAboveMm2) {
  const double sinAlpha = std::sin(degToRad(alphaMaxDegrees));
  switch (machine.kind) {
    case MachineKind::RotaryPlatform:
      return rotaryBound(model, machine, platform, sinAlpha, supportedBandMm, stopAboveMm2);
    case MachineKind::TiltRotate:
      return tiltBound(model, machine, platform, sinAlpha, supportedBandMm, stopAboveMm2);
    case MachineKind::ThreeAxis:
    case MachineKind::Apart:
      return 0.0;
  }
  return 0.0;
}

}  // namespace multidir::core::detail
