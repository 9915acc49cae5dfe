// The UR arms' kinematics: published tables, FK against UR's documented zero pose, IK's eight branches, joint
// limits and the three singularities.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "multidir/robot/ur_kinematics.h"

namespace multidir::robot {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRandomPoses = 10000;

ArmModel model(const std::string& name) {
  auto m = armModel(name);
  EXPECT_TRUE(m.ok()) << name;
  return m.value();
}

double poseError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const double position = (a.translation() - b.translation()).norm();                  // mm
  const double rotation = (a.linear() - b.linear()).cwiseAbs().maxCoeff();               // matrix entries
  return std::max(position, rotation);
}

double jointGapModuloTurns(const Joints& a, const Joints& b) {
  double worst = 0.0;
  for (int j = 0; j < 6; ++j) worst = std::max(worst, std::abs(wrapToPi(a[j] - b[j])));
  return worst;
}

// Random joints away from the singularities (within 1e-3 of one the branches meet and q6 or the elbow angle is
// determined only to sqrt(machine epsilon)); every model's whole joint space otherwise.
std::vector<Joints> randomRegularJoints(const ArmModel& arm, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  std::vector<Joints> result;
  while (static_cast<int>(result.size()) < kRandomPoses) {
    Joints q{};
    for (double& v : q) v = angle(random);
    const SingularityMargins margins = singularityMargins(arm, q);
    if (margins.shoulderMm < 1e-3 || margins.elbowRad < 1e-3 || margins.wristRad < 1e-3) continue;
    result.push_back(q);
  }
  return result;
}

// The 6x6 Jacobian by central differences (linear velocity in mm/rad, angular velocity in rad/rad).
Eigen::Matrix<double, 6, 6> numericJacobian(const ArmModel& arm, const Joints& q) {
  Eigen::Matrix<double, 6, 6> jacobian;
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Joints plus = q, minus = q;
    plus[j] += h;
    minus[j] -= h;
    const Eigen::Isometry3d a = forwardKinematics(arm, plus), b = forwardKinematics(arm, minus);
    const Eigen::AngleAxisd turn(a.linear() * b.linear().transpose());
    jacobian.block<3, 1>(0, j) = (a.translation() - b.translation()) / (2 * h);
    jacobian.block<3, 1>(3, j) = turn.axis() * turn.angle() / (2 * h);
  }
  return jacobian;
}

// The Jacobian's smallest singular value with the linear rows scaled to metres, so both halves weigh alike.
double smallestSingularValue(const ArmModel& arm, const Joints& q) {
  Eigen::Matrix<double, 6, 6> jacobian = numericJacobian(arm, q);
  jacobian.topRows<3>() /= 1000.0;
  return Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>>(jacobian).singularValues()(5);
}

TEST(UrKinematics, KnowsTheSevenPublishedModels) {
  EXPECT_EQ(armModelNames(), (std::vector<std::string>{"ur3", "ur5", "ur10", "ur3e", "ur5e", "ur10e", "ur16e"}));
  for (const auto& name : armModelNames()) EXPECT_TRUE(armModel(name).ok()) << name;
}

TEST(UrKinematics, UnknownModelErrorNamesTheKnownOnes) {
  auto m = armModel("ur7");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().message.find("ur7"), std::string::npos);
  EXPECT_NE(m.error().message.find("ur5e"), std::string::npos);
}

TEST(UrKinematics, DefaultLimitsAreFullTurnsAndPublishedSpeeds) {
  const ArmModel ur10 = model("ur10");
  EXPECT_DOUBLE_EQ(ur10.limits[0].minRad, -2 * kPi);
  EXPECT_DOUBLE_EQ(ur10.limits[5].maxRad, 2 * kPi);
  EXPECT_NEAR(ur10.limits[0].maxSpeedRadPerS, 120.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(ur10.limits[5].maxSpeedRadPerS, 180.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(model("ur3e").limits[4].maxSpeedRadPerS, 360.0 * kPi / 180.0, 1e-12);
}

// At all joints zero the UR5 stretches along -x: flange at (a2 + a3, -(d4 + d6), d1 - d5), its z along -y.
TEST(UrKinematics, Ur5AtZeroJointsIsStretchedAlongMinusX) {
  const Eigen::Isometry3d flange = forwardKinematics(model("ur5"), Joints{});
  EXPECT_NEAR(flange.translation().x(), -425.0 - 392.25, 1e-9);
  EXPECT_NEAR(flange.translation().y(), -109.15 - 82.3, 1e-9);
  EXPECT_NEAR(flange.translation().z(), 89.159 - 94.65, 1e-9);
  EXPECT_NEAR(flange.linear().col(2).dot(Eigen::Vector3d(0, -1, 0)), 1.0, 1e-12);
}

TEST(UrKinematics, EveryBranchReproducesTenThousandRandomPosesOfEveryModel) {
  for (const auto& name : armModelNames()) {
    const ArmModel arm = model(name);
    double worst = 0.0;
    for (const Joints& q : randomRegularJoints(arm, 25)) {
      const Eigen::Isometry3d pose = forwardKinematics(arm, q);
      const auto solutions = inverseKinematics(arm, pose);
      ASSERT_FALSE(solutions.empty()) << name;
      for (const auto& s : solutions) worst = std::max(worst, poseError(forwardKinematics(arm, s.joints), pose));
    }
    EXPECT_LT(worst, 1e-9) << name;
  }
}

TEST(UrKinematics, OriginalJointsAreAmongTheSolutionsModuloTwoPi) {
  for (const auto& name : armModelNames()) {
    const ArmModel arm = model(name);
    int missing = 0;
    double worst = 0.0;
    for (const Joints& q : randomRegularJoints(arm, 26)) {
      const auto solutions = inverseKinematics(arm, forwardKinematics(arm, q));
      double nearest = 1e9;
      for (const auto& s : solutions) nearest = std::min(nearest, jointGapModuloTurns(s.joints, q));
      worst = std::max(worst, nearest);
      if (nearest > 1e-9) ++missing;
    }
    EXPECT_EQ(missing, 0) << name << ": worst gap " << worst << " rad";
  }
}

TEST(UrKinematics, RegularPoseHasEightDistinctBranches) {
  const ArmModel arm = model("ur5");
  const Joints q{0.3, -1.2, 1.9, -1.4, 1.2, 0.4};
  const auto solutions = inverseKinematics(arm, forwardKinematics(arm, q));
  ASSERT_EQ(solutions.size(), 8u);
  for (int b = 0; b < 8; ++b) EXPECT_EQ(solutions[static_cast<std::size_t>(b)].branch, b);
  for (std::size_t i = 0; i < 8; ++i) {
    for (std::size_t k = i + 1; k < 8; ++k) EXPECT_GT(jointGapModuloTurns(solutions[i].joints, solutions[k].joints), 0.1);
  }
}

TEST(UrKinematics, PoseOutOfReachHasNoSolution) {
  for (const auto& name : armModelNames()) {
    const ArmModel arm = model(name);
    const double reach = std::abs(arm.a[1]) + std::abs(arm.a[2]) + arm.d[3] + arm.d[4] + arm.d[5] + arm.d[0];
    Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
    far.translation() = Eigen::Vector3d(reach + 10.0, 0.0, 0.0);
    EXPECT_TRUE(inverseKinematics(arm, far).empty()) << name;
  }
}

// The wrist centre within d4 of the base axis: no shoulder angle puts it d4 along the shoulder axis.
TEST(UrKinematics, WristCentreInsideTheBaseCylinderHasNoSolution) {
  const ArmModel arm = model("ur5");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // flange z up: the wrist centre d6 below the flange
  pose.translation() = Eigen::Vector3d(20.0, 30.0, 500.0);
  EXPECT_TRUE(inverseKinematics(arm, pose).empty());
}

TEST(UrKinematics, NearestWithinLimitsAddsTheTurnNearestToCurrent) {
  const ArmModel arm = model("ur5");
  const Joints q{0.3, -1.2, 1.1, -1.4, 1.2, 0.4};
  const auto solutions = inverseKinematics(arm, forwardKinematics(arm, q));
  Joints current = q;
  current[5] -= 2 * kPi + 0.01;  // wrist 3 one turn back (q6 - 2 pi is within the -360 deg limit)
  const auto chosen = nearestWithinLimits(arm, solutions, current);
  ASSERT_TRUE(chosen.has_value());
  for (int j = 0; j < 5; ++j) EXPECT_NEAR((*chosen)[j], q[j], 1e-9);
  EXPECT_NEAR((*chosen)[5], q[5] - 2 * kPi, 1e-9);
}

TEST(UrKinematics, NearestWithinLimitsRefusesJointsBeyondTheLimits) {
  ArmModel arm = model("ur5");
  const Joints q{0.3, -1.2, 1.1, -1.4, 1.2, 0.4};
  const auto solutions = inverseKinematics(arm, forwardKinematics(arm, q));
  ASSERT_TRUE(nearestWithinLimits(arm, solutions, q).has_value());
  // Wrist 2 limited to [-0.5, 0.5] rad: every branch has |q5| = 1.2 or pi - 1.2 (+- 2 pi), all beyond.
  arm.limits[4].minRad = -0.5;
  arm.limits[4].maxRad = 0.5;
  EXPECT_FALSE(nearestWithinLimits(arm, solutions, q).has_value());
}

TEST(UrKinematics, NearestWithinLimitsSkipsABranchBeyondTheLimits) {
  ArmModel arm = model("ur5");
  const Joints q{0.3, -1.2, 1.1, -1.4, 1.2, 0.4};
  const auto solutions = inverseKinematics(arm, forwardKinematics(arm, q));
  arm.limits[2].minRad = 0.0;  // elbow limited to [0, pi]: the nearest solution (q3 = 1.1) stays
  arm.limits[2].maxRad = kPi;
  Joints current = q;
  current[2] = -1.1;  // nearer to the elbow-negative branch, which the limit refuses
  const auto chosen = nearestWithinLimits(arm, solutions, current);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_GE((*chosen)[2], 0.0);
}

// The wrist centre's offset from the plane of the base and shoulder axes, from the whole arm's FK (not the
// margins' own sum): zero at the shoulder singularity.
double wristCentreAlongArmPlaneNormal(const ArmModel& arm, const Joints& q) {
  const Eigen::Isometry3d flange = forwardKinematics(arm, q);
  const Eigen::Vector3d wristCentre = flange.translation() - arm.d[5] * flange.linear().col(2);
  return wristCentre.x() * std::cos(q[0]) + wristCentre.y() * std::sin(q[0]);
}

// q2 (bisection) putting the wrist centre into the plane of the base and shoulder axes, elbow and wrist bent.
Joints shoulderSingularJoints(const ArmModel& arm) {
  Joints q{0.2, -kPi, 1.0, 0.3, 1.0, 0.3};
  double low = -kPi, high = 0.0;
  auto f = [&](double q2) {
    Joints probe = q;
    probe[1] = q2;
    return wristCentreAlongArmPlaneNormal(arm, probe);
  };
  for (double x = -kPi; x < kPi; x += 0.01) {
    if (f(x) * f(x + 0.01) <= 0.0) {
      low = x;
      high = x + 0.01;
      break;
    }
  }
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    (f(low) * f(mid) <= 0.0 ? high : low) = mid;
  }
  q[1] = 0.5 * (low + high);
  return q;
}

TEST(UrKinematics, ShoulderSingularityHasZeroShoulderMarginAndLosesRank) {
  for (const auto& name : armModelNames()) {
    const ArmModel arm = model(name);
    const Joints singular = shoulderSingularJoints(arm);
    EXPECT_NEAR(singularityMargins(arm, singular).shoulderMm, 0.0, 1e-9) << name;
    EXPECT_LT(smallestSingularValue(arm, singular), 1e-6) << name;
    Joints near = singular;
    near[1] += 0.05;
    EXPECT_GT(singularityMargins(arm, near).shoulderMm, 1.0) << name;
    EXPECT_GT(smallestSingularValue(arm, near), 1e-3) << name;
  }
}

TEST(UrKinematics, ShoulderMarginIsTheWristCentresDistanceInTheArmsPlane) {
  const ArmModel arm = model("ur10e");
  const Joints q{0.7, -1.0, 1.3, -0.6, 0.9, 0.2};
  const Eigen::Isometry3d flange = forwardKinematics(arm, q);
  const Eigen::Vector3d wristCentre = flange.translation() - arm.d[5] * flange.linear().col(2);
  const double fromAxis = std::hypot(wristCentre.x(), wristCentre.y());
  const double margin = singularityMargins(arm, q).shoulderMm;
  EXPECT_NEAR(margin * margin + arm.d[3] * arm.d[3], fromAxis * fromAxis, 1e-6);
}

TEST(UrKinematics, ElbowSingularityHasZeroElbowMarginAndLosesRank) {
  const ArmModel arm = model("ur5e");
  const Joints straight{0.2, -1.0, 0.0, -0.6, 1.0, 0.3};
  EXPECT_NEAR(singularityMargins(arm, straight).elbowRad, 0.0, 1e-15);
  EXPECT_LT(smallestSingularValue(arm, straight), 1e-6);
  Joints bent = straight;
  bent[2] = 0.4;
  EXPECT_NEAR(singularityMargins(arm, bent).elbowRad, std::sin(0.4), 1e-15);
  EXPECT_GT(smallestSingularValue(arm, bent), 1e-3);
}

TEST(UrKinematics, WristSingularityHasZeroWristMarginAndLosesRank) {
  const ArmModel arm = model("ur16e");
  const Joints flat{0.2, -1.0, 1.2, -0.6, 0.0, 0.3};
  EXPECT_NEAR(singularityMargins(arm, flat).wristRad, 0.0, 1e-15);
  EXPECT_LT(smallestSingularValue(arm, flat), 1e-6);
  Joints bent = flat;
  bent[4] = -0.5;
  EXPECT_NEAR(singularityMargins(arm, bent).wristRad, std::sin(0.5), 1e-15);
  EXPECT_GT(smallestSingularValue(arm, bent), 1e-3);
}

// At the wrist singularity the pose is still reached: q6 = 0 and q4 carries the turn.
TEST(UrKinematics, WristSingularPoseIsStillSolved) {
  const ArmModel arm = model("ur5");
  const Joints flat{0.2, -1.0, 1.2, -0.6, 0.0, 0.3};
  const Eigen::Isometry3d pose = forwardKinematics(arm, flat);
  const auto solutions = inverseKinematics(arm, pose);
  ASSERT_FALSE(solutions.empty());
  for (const auto& s : solutions) EXPECT_LT(poseError(forwardKinematics(arm, s.joints), pose), 1e-9);
}

}  // namespace
}  // namespace multidir::robot
