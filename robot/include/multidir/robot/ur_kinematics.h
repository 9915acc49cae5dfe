#pragma once
// Universal Robots arms (UR3, UR5, UR10 and the e-Series UR3e, UR5e, UR10e, UR16e): forward and closed-form
// inverse kinematics from UR's published Denavit-Hartenberg tables, joint limits and the three singularities.
//
// Frames: the robot base frame as the UR controller defines it (the DH base: z up the base axis), the flange is
// DH frame 6 (the controller's tool flange with a zero TCP). Millimetres and radians; degrees only where a name
// says so (the cell file). docs/robot-cell.md has the conventions and the sources.
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::robot {

using Joints = std::array<double, 6>;  // radians, base..wrist 3

struct JointLimits {
  double minRad;
  double maxRad;
  double maxSpeedRadPerS;
  double maxAccelRadPerS2;
};

struct ArmModel {
  std::string name;                   // "ur5", "ur5e", ...
  std::array<double, 6> d, a, alpha;  // standard DH, mm and rad (UR's published table)
  std::array<JointLimits, 6> limits;  // defaults: +-360 deg, UR's published max joint speeds
};

// ur3 ur5 ur10 ur3e ur5e ur10e ur16e
std::vector<std::string> armModelNames();

// The model's DH table and default limits; the error names the known models.
core::Result<ArmModel> armModel(std::string_view name);

// The flange in the base frame (mm).
Eigen::Isometry3d forwardKinematics(const ArmModel&, const Joints&);

// branch 0..7: shoulder * 4 + wrist * 2 + elbow, each bit 0 or 1:
//   shoulder 0: q1 = psi + asin(d4 / r), 1: q1 = psi + pi - asin(d4 / r) (psi, r: the wrist centre's azimuth and
//               distance from the base axis); the arm reaches forward or backward over the base.
//   wrist    0: q5 in [0, pi], 1: q5 in (-pi, 0) (wrist 2 bent one way or the other);
//   elbow    0: q3 in [0, pi], 1: q3 in (-pi, 0) (elbow bent one way or the other).
// Within one branch the joints vary continuously with the pose away from the singularities.
struct IkSolution {
  Joints joints;
  int branch;
};

// All real branches for the flange pose, angles in (-pi, pi]; empty when the pose is out of reach. At the wrist
// singularity (sin q5 = 0) q6 is set to 0 and q4 carries the rotation.
std::vector<IkSolution> inverseKinematics(const ArmModel&, const Eigen::Isometry3d& flange);

// The same without allocating (the conversion's hot loop): writes the solutions into `out`, returns their count.
int inverseKinematics(const ArmModel&, const Eigen::Isometry3d& flange, std::array<IkSolution, 8>& out);

// The joints of `solutions` (with 2*pi turns added/removed within the limits) nearest to `current`; empty if none
// within limits. "Nearest": the least sum of squared joint differences.
std::optional<Joints> nearestWithinLimits(const ArmModel&, const std::vector<IkSolution>& solutions,
                                          const Joints& current);
// The same over the first `count` of an array (no allocation); `branch` receives the chosen solution's branch.
std::optional<Joints> nearestWithinLimits(const ArmModel&, const IkSolution* solutions, int count,
                                          const Joints& current, int* branch = nullptr);

// How far the joints are from each of the arm's three singularities (each is zero at its singularity):
//   shoulderMm: the wrist centre's (DH frame 5's origin) distance from the base axis, measured in the arm's plane
//               (perpendicular to the shoulder axis; the shoulder offset d4 runs along that axis, so the wrist
//               centre's plain distance from the base axis is sqrt(shoulderMm^2 + d4^2));
//   elbowRad:   |sin q3| (elbow straight);
//   wristRad:   |sin q5| (wrist 1 and wrist 3 axes parallel).
struct SingularityMargins {
  double shoulderMm, elbowRad, wristRad;
};
SingularityMargins singularityMargins(const ArmModel&, const Joints&);

// An angle brought into (-pi, pi].
double wrapToPi(double angleRad);

}  // namespace multidir::robot
