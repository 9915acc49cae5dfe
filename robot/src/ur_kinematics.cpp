// Forward and closed-form inverse kinematics of the UR arms (standard DH, alpha = pi/2, 0, 0, pi/2, -pi/2, 0).
//
// The inverse, in four steps (docs/robot-cell.md, "Kinematics"):
//  1. q1: the wrist centre P5 (DH frame 5's origin, d6 behind the flange along its z) lies d4 along the shoulder
//     axis z1 = (sin q1, -cos q1, 0), so P5x sin q1 - P5y cos q1 = d4: two solutions (shoulder branch).
//  2. q5: the flange's z along z1 is cos q5 (and its position along z1 d4 + d6 cos q5): two solutions (wrist
//     branch).
//  3. q6: z1 seen from the flange is (sin q5 cos q6, -sin q5 sin q6, cos q5).
//  4. q2, q3, q4: frames 1 to 4 are a planar 3R chain (axes parallel to z1): the law of cosines gives q3 (elbow
//     branch), then q2, and q4 from the chain's summed angle.
#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/robot/ur_kinematics.h"

namespace multidir::robot {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
// How far past +-1 a cosine may come out of rounding and still count as reached (a pose that far outside the
// workspace is within 1e-9 of its boundary).
constexpr double kCosineSlack = 1e-9;
// Below this |sin q5| the wrist is singular: q6 and q4 turn about one axis and q6 is set to 0.
constexpr double kWristSingularSin = 1e-12;

Eigen::Matrix4d dhMatrix(double theta, double d, double a, double alpha) {
  const double ct = std::cos(theta), st = std::sin(theta);
  const double ca = std::cos(alpha), sa = std::sin(alpha);
  Eigen::Matrix4d m;
  m << ct, -st * ca, st * sa, a * ct,  //
      st, ct * ca, -ct * sa, a * st,   //
      0.0, sa, ca, d,                  //
      0.0, 0.0, 0.0, 1.0;
  return m;
}

Eigen::Matrix4d dhInverse(double theta, double d, double a, double alpha) {
  const Eigen::Matrix4d m = dhMatrix(theta, d, a, alpha);
  Eigen::Matrix4d inv = Eigen::Matrix4d::Identity();
  inv.topLeftCorner<3, 3>() = m.topLeftCorner<3, 3>().transpose();
  inv.topRightCorner<3, 1>() = -(m.topLeftCorner<3, 3>().transpose() * m.topRightCorner<3, 1>());
  return inv;
}

double clampUnit(double c) { return std::clamp(c, -1.0, 1.0); }

}  // namespace

double wrapToPi(double angleRad) {
  double w = std::remainder(angleRad, kTwoPi);  // in [-pi, pi]
  if (w <= -kPi) w += kTwoPi;
  return w;
}

Eigen::Isometry3d forwardKinematics(const ArmModel& m, const Joints& q) {
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  for (int j = 0; j < 6; ++j) t = t * dhMatrix(q[j], m.d[j], m.a[j], m.alpha[j]);
  Eigen::Isometry3d result;
  result.matrix() = t;
  return result;
}

int inverseKinematics(const ArmModel& m, const Eigen::Isometry3d& flange, std::array<IkSolution, 8>& out) {
  const double d1 = m.d[0], a2 = m.a[1], a3 = m.a[2], d4 = m.d[3], d6 = m.d[5];
  const Eigen::Matrix4d target = flange.matrix();
  const Eigen::Vector3d p = flange.translation();
  const Eigen::Vector3d x6 = flange.linear().col(0), y6 = flange.linear().col(1), z6 = flange.linear().col(2);
  const Eigen::Vector3d p5 = p - d6 * z6;
  const double r = std::hypot(p5.x(), p5.y());
  if (r < std::abs(d4) * (1.0 - kCosineSlack) || r == 0.0) return 0;  // inside the cylinder about the base axis
  const double psi = std::atan2(p5.y(), p5.x());
  const double offset = std::asin(clampUnit(d4 / r));
  int count = 0;
  for (int shoulder = 0; shoulder < 2; ++shoulder) {
    const double q1 = shoulder == 0 ? psi + offset : psi + kPi - offset;
    const double s1 = std::sin(q1), c1 = std::cos(q1);
    // z1 seen from the flange: (x6.z1, y6.z1, z6.z1) = (s5 c6, -s5 s6, c5). With q1 solved, z6.z1 equals the
    // flange's offset along z1, (p.z1 - d4) / d6, so every q1 has its q5; atan2 keeps q5 exact near sin q5 = 0,
    // where acos would lose half the digits.
    const double xz = x6.x() * s1 - x6.y() * c1;
    const double yz = y6.x() * s1 - y6.y() * c1;
    const double zz = z6.x() * s1 - z6.y() * c1;
    const double q5Abs = std::atan2(std::hypot(xz, yz), zz);
    const Eigen::Matrix4d a1Inverse = dhInverse(q1, d1, 0.0, m.alpha[0]);
    for (int wrist = 0; wrist < 2; ++wrist) {
      const double q5 = wrist == 0 ? q5Abs : -q5Abs;
      const double sign5 = wrist == 0 ? 1.0 : -1.0;
      const double q6 =
          std::abs(std::sin(q5)) < kWristSingularSin ? 0.0 : std::atan2(-yz * sign5, xz * sign5);
      // The planar chain: frame 4 in frame 1.
      const Eigen::Matrix4d t14 =
          a1Inverse * target * dhInverse(q6, m.d[5], m.a[5], m.alpha[5]) * dhInverse(q5, m.d[4], m.a[4], m.alpha[4]);
      const double px = t14(0, 3), py = t14(1, 3);
      const double c3 = (px * px + py * py - a2 * a2 - a3 * a3) / (2.0 * a2 * a3);
      if (std::abs(c3) > 1.0 + kCosineSlack) continue;
      const double q3Abs = std::acos(clampUnit(c3));
      const double q234 = std::atan2(t14(1, 0), t14(0, 0));
      for (int elbow = 0; elbow < 2; ++elbow) {
        const double q3 = elbow == 0 ? q3Abs : -q3Abs;
        const double q2 = std::atan2(py, px) - std::atan2(a3 * std::sin(q3), a2 + a3 * std::cos(q3));
        const double q4 = q234 - q2 - q3;
        IkSolution& s = out[static_cast<std::size_t>(count++)];
        s.joints = {wrapToPi(q1), wrapToPi(q2), wrapToPi(q3), wrapToPi(q4), wrapToPi(q5), wrapToPi(q6)};
        s.branch = shoulder * 4 + wrist * 2 + elbow;
      }
    }
  }
  return count;
}

std::vector<IkSolution> inverseKinematics(const ArmModel& m, const Eigen::Isometry3d& flange) {
  std::array<IkSolution, 8> buffer{};
  const int count = inverseKinematics(m, flange, buffer);
  return std::vector<IkSolution>(buffer.begin(), buffer.begin() + count);
}

std::optional<Joints> nearestWithinLimits(const ArmModel& m, const IkSolution* solutions, int count,
                                          const Joints& current, int* branch) {
  std::optional<Joints> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i) {
    Joints candidate{};
    double distance = 0.0;
    bool within = true;
    for (int j = 0; j < 6 && within; ++j) {
      const JointLimits& limit = m.limits[static_cast<std::size_t>(j)];
      const double q = solutions[i].joints[static_cast<std::size_t>(j)];
      const double turns = std::round((current[static_cast<std::size_t>(j)] - q) / kTwoPi);
      // The turn nearest to `current`, or the next ones either side when that one is past a limit.
      double chosen = std::numeric_limits<double>::quiet_NaN();
      double chosenGap = std::numeric_limits<double>::infinity();
      for (double k : {turns, turns - 1.0, turns + 1.0}) {
        const double value = q + k * kTwoPi;
        if (value < limit.minRad || value > limit.maxRad) continue;
        const double gap = std::abs(value - current[static_cast<std::size_t>(j)]);
        if (gap < chosenGap) {
          chosenGap = gap;
          chosen = value;
        }
      }
      if (std::isnan(chosen)) {
        within = false;
        break;
      }
      candidate[static_cast<std::size_t>(j)] = chosen;
      distance += chosenGap * chosenGap;
    }
    if (within && distance < bestDistance) {
      bestDistance = distance;
      best = candidate;
      if (branch != nullptr) *branch = solutions[i].branch;
    }
  }
  return best;
}

std::optional<Joints> nearestWithinLimits(const ArmModel& m, const std::vector<IkSolution>& solutions,
                                          const Joints& current) {
  return nearestWithinLimits(m, solutions.data(), static_cast<int>(solutions.size()), current);
}

SingularityMargins singularityMargins(const ArmModel& m, const Joints& q) {
  // The wrist centre (frame 5's origin) along frame 1's x, the horizontal radial direction of the arm's plane.
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  for (int j = 0; j < 5; ++j) t = t * dhMatrix(q[static_cast<std::size_t>(j)], m.d[j], m.a[j], m.alpha[j]);
  const double shoulder = t(0, 3) * std::cos(q[0]) + t(1, 3) * std::sin(q[0]);
  return {std::abs(shoulder), std::abs(std::sin(q[2])), std::abs(std::sin(q[4]))};
}

}  // namespace multidir::robot
