#include "multidir/core/search/candidate_planes.h"

#include <cmath>
#include <limits>

#include "multidir/core/common/units.h"

namespace multidir::core {

std::vector<Vec3> fibonacciSphere(int count) {
  std::vector<Vec3> points;
  if (count <= 0) return points;
  points.reserve(count);
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    points.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return points;
}

Status validate(const CandidateOptions& options) {
  if (options.normalSamples < 1 || options.normalSamples > 100000)
    return Error{ErrorCode::InvalidParameter, "the number of normals must be between 1 and 100000", "normals"};
  if (!(options.offsetStepMm >= 0.01 && options.offsetStepMm <= 1000))
    return Error{ErrorCode::InvalidParameter, "the offset step must be between 0.01 and 1000 mm", "offset step"};
  if (!(options.rotarySpacingDegrees > 0 && options.rotarySpacingDegrees <= 90))
    return Error{ErrorCode::InvalidParameter, "the 4-DOF normal spacing must be above 0 and at most 90 degrees",
                 "rotary spacing"};
  if (!(options.platformClearanceMm >= 0 && options.platformClearanceMm < 1000))
    return Error{ErrorCode::InvalidParameter, "the platform clearance must be between 0 and 1000 mm", "clearance"};
  return Done{};
}

std::vector<Vec3> candidateNormals(const MachineSpec& machine, const CandidateOptions& options) {
  std::vector<Vec3> normals;
  switch (machine.kind) {
    case MachineKind::ThreeAxis:
      normals.push_back(machine.up);
      break;
    case MachineKind::RotaryPlatform: {
      // Every stride-th step of the stepper, so neighbouring candidates are about rotarySpacingDegrees apart.
      const int stride =
          std::max(1, static_cast<int>(std::round(options.rotarySpacingDegrees / machine.angleStepDegrees)));
      const int steps = static_cast<int>(std::floor(
          (machine.maxAngleDegrees - machine.minAngleDegrees) / machine.angleStepDegrees + 1e-9));
      for (int i = 0; i <= steps; ++i) {
        const double angle = machine.minAngleDegrees + i * machine.angleStepDegrees;
        if (std::abs(angle) < 1e-9) continue;
        if (i % stride != 0) continue;
        normals.push_back(rotaryDirection(machine, angle));
      }
      break;
    }
    case MachineKind::TiltRotate: {
      // The lattice is built around +Z; turn it so its pole is the machine's up.
      const Eigen::Quaterniond toUp = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), machine.up);
      for (const Vec3& p : fibonacciSphere(options.normalSamples)) {
        const Vec3 n = (toUp * p).normalized();
        if (n.dot(machine.up) > 1.0 - 1e-12) continue;
        if (isRealizable(machine, n)) normals.push_back(n);
      }
      break;
    }
  }
  return normals;
}

namespace {

// Highest point of the disc P along `normal`: its centre plus the radius times the in-plane part of n.
double platformTopAlong(const Vec3& normal, const PlatformRegion& platform, const Vec3& up) {
  const Vec3 inPlane = normal - normal.dot(up) * up;
  return normal.dot(platform.center) + platform.radiusMm * inPlane.norm();
}

}  // namespace

bool planeClearsPlatform(const Plane& plane, const PlatformRegion& platform, const Vec3& up, double clearanceMm) {
  return plane.offset > platformTopAlong(plane.normal, platform, up) + clearanceMm;
}

OffsetGrid candidateOffsets(const TriangleMesh& solid, const Vec3& normal, const PlatformRegion& platform,
                            const Vec3& up, const CandidateOptions& options) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  // Every vertex of a solid from loadMesh or clipByPlane belongs to a face.
  for (const Vec3& v : solid.vertices) {
    const double h = normal.dot(v);
    low = std::min(low, h);
    high = std::max(high, h);
  }
  OffsetGrid grid{0.0, options.offsetStepMm, 0};
  if (!(low < high)) return grid;
  const double start = std::max(low, platformTopAlong(normal, platform, up) + options.platformClearanceMm);
  // Offsets on a lattice anchored at 0 so that the same plane is the same candidate at every level.
  const double first = (std::floor(start / options.offsetStepMm) + 1.0) * options.offsetStepMm;
  if (first >= high) return grid;
  grid.firstMm = first;
  grid.count = static_cast<int>(std::ceil((high - first) / options.offsetStepMm));
  return grid;
}

}  // namespace multidir::core
