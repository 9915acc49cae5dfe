#include "multidir/core/search/candidate_planes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_measure.h"

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
    case MachineKind::TiltRotate:
    case MachineKind::Apart: {
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

double normalSpacingRadians(const MachineSpec& machine, const CandidateOptions& options) {
  switch (machine.kind) {
    case MachineKind::ThreeAxis: return 0.0;
    case MachineKind::RotaryPlatform: {
      const int stride =
          std::max(1, static_cast<int>(std::round(options.rotarySpacingDegrees / machine.angleStepDegrees)));
      return degToRad(stride * machine.angleStepDegrees);
    }
    case MachineKind::TiltRotate:
    case MachineKind::Apart: return std::sqrt(4.0 * kPi / options.normalSamples);
  }
  return 0.0;
}

std::vector<Vec3> neighbourNormals(const MachineSpec& machine, const Vec3& normal, double radiusRadians,
                                   double turnRadians) {
  std::vector<Vec3> neighbours;
  switch (machine.kind) {
    case MachineKind::ThreeAxis: break;
    case MachineKind::RotaryPlatform: {
      const double step = machine.angleStepDegrees;
      const int steps = static_cast<int>(std::round(radToDeg(radiusRadians) / step));
      if (steps < 1) break;
      const double angle = machineAnglesFor(machine, normal).rotaryDegrees;
      const double base = std::round(angle / step) * step;
      for (int sign : {-1, 1}) {
        const double a = base + sign * steps * step;
        if (a < machine.minAngleDegrees - 1e-9 || a > machine.maxAngleDegrees + 1e-9 || std::abs(a) < 1e-9) continue;
        neighbours.push_back(rotaryDirection(machine, a));
      }
      break;
    }
    case MachineKind::TiltRotate:
    case MachineKind::Apart: {
      const Vec3 n = normal.normalized();
      const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
      const Vec3 u = n.cross(helper).normalized();
      const Vec3 v = n.cross(u);
      for (int k = 0; k < 6; ++k) {
        const double theta = turnRadians + k * kPi / 3.0;
        const Vec3 d =
            (std::cos(radiusRadians) * n + std::sin(radiusRadians) * (std::cos(theta) * u + std::sin(theta) * v))
                .normalized();
        if (d.dot(machine.up) > 1.0 - 1e-12) continue;  // up itself is the platform's own direction
        if (isRealizable(machine, d)) neighbours.push_back(d);
      }
      break;
    }
  }
  return neighbours;
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

namespace {

// Every offsetStepMm from just above max(the solid's lowest point, `floorMm`) to below its top.
OffsetGrid offsetsAbove(const LevelRange& range, double floorMm, const CandidateOptions& options) {
  const double low = range.lowMm, high = range.highMm;
  OffsetGrid grid{0.0, options.offsetStepMm, 0};
  if (!(low < high)) return grid;
  const double start = std::max(low, floorMm);
  // Offsets on a lattice anchored at 0 so that the same plane is the same candidate at every level.
  const double first = (std::floor(start / options.offsetStepMm) + 1.0) * options.offsetStepMm;
  if (first >= high) return grid;
  grid.firstMm = first;
  const double count = std::ceil((high - first) / options.offsetStepMm);
  grid.count = static_cast<int>(std::min(count, static_cast<double>(kMaxCandidatesPerLevel)));
  return grid;
}

}  // namespace

LevelRange levelRange(const TriangleMesh& solid, const Vec3& normal) {
  LevelRange range;
  // Every vertex of a solid from loadMesh or clipByPlane belongs to a face.
  for (const Vec3& v : solid.vertices) range.include(normal.dot(v));
  return range;
}

OffsetGrid candidateOffsets(const LevelRange& range, const Vec3& normal, const PlatformRegion& platform,
                            const Vec3& up, const CandidateOptions& options) {
  return offsetsAbove(range, platformTopAlong(normal, platform, up) + options.platformClearanceMm, options);
}

OffsetGrid candidateOffsets(const LevelRange& range, const CandidateOptions& options) {
  return offsetsAbove(range, -std::numeric_limits<double>::infinity(), options);
}

OffsetGrid candidateOffsets(const TriangleMesh& solid, const Vec3& normal, const PlatformRegion& platform,
                            const Vec3& up, const CandidateOptions& options) {
  return candidateOffsets(levelRange(solid, normal), normal, platform, up, options);
}

OffsetGrid candidateOffsets(const TriangleMesh& solid, const Vec3& normal, const CandidateOptions& options) {
  return candidateOffsets(levelRange(solid, normal), options);
}

Status checkCandidateCount(const TriangleMesh& model, const MachineSpec& machine, const CandidateOptions& options) {
  if (Status valid = validate(options); !valid) return valid;
  const BoundingBox box = boundingBox(model);
  const double widthMm = (box.max - box.min).norm();
  const auto normals = static_cast<double>(std::max<std::size_t>(1, candidateNormals(machine, options).size()));
  const double offsets = std::ceil(widthMm / options.offsetStepMm);
  const double candidates = normals * offsets;
  if (std::isfinite(candidates) && offsets <= static_cast<double>(kMaxOffsetsPerNormal) &&
      candidates <= static_cast<double>(kMaxCandidatesPerLevel))
    return Done{};
  char width[64];
  std::snprintf(width, sizeof width, "%.4g", widthMm / 1000.0);
  char count[64];
  std::snprintf(count, sizeof count, "%.3g", candidates);
  char step[64];
  std::snprintf(step, sizeof step, "%g", options.offsetStepMm);
  return Error{ErrorCode::InvalidParameter,
               "the model is " + std::string(width) + " m wide (its bounding-box diagonal), so the search would score " +
                   count + " candidate planes per level (" + std::to_string(static_cast<long long>(normals)) +
                   " normals, an offset every " + step +
                   " mm), more than it can hold (" + std::to_string(kMaxOffsetsPerNormal) + " offsets per normal, " +
                   std::to_string(kMaxCandidatesPerLevel) + " planes in all). Wrong units? Use --scale (0.001 for a model in micrometres, 25.4 for inches); "
                   "or a larger --offset-step or fewer --normals",
               "model"};
}

}  // namespace multidir::core
