// How a firmware-2axis printer moves the part (two_axis_motion.h), checked against the machine as
// docs/slicing.md describes it, written out here: the rotation turns the platform about its normal through
// rotation_center, the tilt turns the cradle about its line along X at tilt_height by minus the angle; the turns'
// swept tops are what a dense replay of the moves reaches, and the order chosen is the lowest.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/two_axis_motion.h"
#include "slicing_fixtures.h"

using namespace multidir;
using namespace multidir::slicing;
using core::Vec3;

namespace {

// A tilt axis 20 mm below the platform, crossing the rotation axis 15 mm off the platform centre.
PrinterProfile offsetMachine() {
  PrinterProfile p;
  p.platform = PlatformDrive::FirmwareTwoAxis;
  p.platformCenter = Eigen::Vector2d(100, 100);
  p.platformZMm = 30.0;
  p.twoAxis.rotationCenter = Eigen::Vector2d(115, 100);
  p.twoAxis.tiltHeightMm = 10.0;
  p.twoAxis.platformRadiusMm = 40.0;
  return p;
}

// The machine as built, from the device's side: rotate about the vertical line through the rotation centre,
// then tilt by minus the angle about the line along X at the tilt height (machine frame: the printer's minus
// the platform centre and height).
Vec3 onTheMachine(const Vec3& restPoint, const PrinterProfile& p, double tiltDegrees, double rotationDegrees) {
  const Vec3 origin(p.platformCenter.x(), p.platformCenter.y(), p.platformZMm);
  const Vec3 rotationPoint = Vec3(p.twoAxis.rotationCenter.x(), p.twoAxis.rotationCenter.y(), p.platformZMm) - origin;
  const Vec3 tiltPoint = Vec3(p.twoAxis.rotationCenter.x(), p.twoAxis.rotationCenter.y(), p.twoAxis.tiltHeightMm) - origin;
  const Vec3 rotated =
      rotationPoint + Eigen::AngleAxisd(rotationDegrees * M_PI / 180.0, Vec3::UnitZ()) * (restPoint - rotationPoint);
  return tiltPoint + Eigen::AngleAxisd(-tiltDegrees * M_PI / 180.0, Vec3::UnitX()) * (rotated - tiltPoint);
}

std::vector<Vec3> randomPoints(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-30.0, 30.0);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.push_back(Vec3(u(random), u(random), 0.5 * (u(random) + 30.0)));
  return points;
}

// The highest z of `points` (rest frame) over the moves, replayed in 4,000 small steps per move.
double denseTop(const std::vector<Vec3>& points, const PrinterProfile& p, TwoAxisAngles at,
                const std::vector<AxisMove>& moves) {
  double top = -1e300;
  const auto sample = [&](const TwoAxisAngles& a) {
    for (const Vec3& q : points) top = std::max(top, onTheMachine(q, p, a.tiltDegrees, a.rotationDegrees).z());
  };
  sample(at);
  for (const AxisMove& move : moves)
    for (int i = 1; i <= 4000; ++i) {
      const double value = move.fromDegrees + (move.toDegrees - move.fromDegrees) * i / 4000.0;
      (move.axis == AxisMove::Axis::Tilt ? at.tiltDegrees : at.rotationDegrees) = value;
      sample(at);
    }
  return top;
}

}  // namespace

TEST(TwoAxisMachine, PoseMovesEveryPointAsTheAxesOnTheMachineDo) {
  const PrinterProfile profile = offsetMachine();
  const TwoAxisMachine machine(profile, 0.0);
  for (const TwoAxisAngles at : {TwoAxisAngles{35.0, -120.0}, TwoAxisAngles{-80.0, 300.0}, TwoAxisAngles{0.0, 45.0}})
    for (const Vec3& q : randomPoints(50, 7))
      EXPECT_LT((machine.pose(at) * q - onTheMachine(q, profile, at.tiltDegrees, at.rotationDegrees)).norm(), 1e-9)
          << "tilt " << at.tiltDegrees << ", rotation " << at.rotationDegrees;
}

TEST(TwoAxisMachine, EveryStepsAnglesPointItsDirectionUpOnTheMachine) {
  const PrinterProfile profile = offsetMachine();
  const TwoAxisMachine machine(profile, 0.0);
  std::mt19937 random(26);
  std::normal_distribution<double> normal;
  core::PrintJob job;
  for (int k = 0; k < 200; ++k) {
    core::PrintJobStep step;
    step.index = k + 1;
    Vec3 d(normal(random), normal(random), std::abs(normal(random)));  // within the +-90 degree tilt limits
    step.printingDirection = k == 0 ? Vec3::UnitZ() : d.normalized();
    job.steps.push_back(step);
  }
  const core::Result<std::vector<TwoAxisAngles>> angles = machine.stepAngles(job);
  ASSERT_TRUE(angles.ok()) << angles.error().describe();
  for (std::size_t k = 0; k < job.steps.size(); ++k) {
    const TwoAxisAngles& at = (*angles)[k];
    const Vec3 tip = onTheMachine(job.steps[k].printingDirection, profile, at.tiltDegrees, at.rotationDegrees) -
                     onTheMachine(Vec3::Zero(), profile, at.tiltDegrees, at.rotationDegrees);
    EXPECT_LT((tip - Vec3::UnitZ()).norm(), 1e-9) << "step " << k + 1;
  }
}

TEST(TwoAxisMachine, ATurnsSweptTopIsWhatADenseReplayOfItsMovesReaches) {
  const PrinterProfile profile = offsetMachine();
  const TwoAxisMachine machine(profile, 0.0);
  const std::vector<Vec3> part = randomPoints(200, 3);
  const TwoAxisAngles from{50.0, 20.0}, to{-70.0, 160.0};
  const TwoAxisTurn turn = machine.planTurn(part, from, to);
  ASSERT_FALSE(turn.moves.empty());
  // The swept top is exact (the replay is a lower bound that comes within its steps' chord error).
  const double replayed = denseTop(part, profile, from, turn.moves);
  EXPECT_GE(turn.sweptTopZ, replayed - 1e-9);
  EXPECT_LT(turn.sweptTopZ - replayed, 1e-3);
}

TEST(TwoAxisMachine, ATurnTakesTheAxesInTheOrderThatKeepsThePartLowest) {
  const PrinterProfile profile = offsetMachine();
  const TwoAxisMachine machine(profile, 0.0);
  const std::vector<Vec3> part = randomPoints(200, 5);
  const TwoAxisAngles from{60.0, 0.0}, to{45.0, 180.0};
  const TwoAxisTurn turn = machine.planTurn(part, from, to);
  const std::vector<std::vector<AxisMove>> orders = {
      {{AxisMove::Axis::Rotation, 0.0, 180.0}, {AxisMove::Axis::Tilt, 60.0, 45.0}},
      {{AxisMove::Axis::Tilt, 60.0, 45.0}, {AxisMove::Axis::Rotation, 0.0, 180.0}},
      {{AxisMove::Axis::Tilt, 60.0, 0.0}, {AxisMove::Axis::Rotation, 0.0, 180.0}, {AxisMove::Axis::Tilt, 0.0, 45.0}}};
  double lowest = 1e300;
  for (const std::vector<AxisMove>& order : orders) lowest = std::min(lowest, denseTop(part, profile, from, order));
  EXPECT_LT(turn.sweptTopZ, lowest + 1e-3);
  // A half turn of a part tilted by 60 degrees lifts it far more than going through level does.
  EXPECT_EQ(turn.moves.size(), 3u);
}

TEST(TwoAxisMachine, ThePlatformsBodyLiesInThePlatformPlaneAtRestAndRisesByItsRadiusTimesTheTiltsSine) {
  PrinterProfile profile = offsetMachine();
  profile.twoAxis.rotationCenter = profile.platformCenter;
  profile.twoAxis.tiltHeightMm = profile.platformZMm;  // the tilt axis in the platform plane
  const TwoAxisMachine machine(profile, 0.0);
  EXPECT_NEAR(machine.bodyTopZ({0.0, 0.0}), 0.0, 1e-9);
  EXPECT_NEAR(machine.bodyTopZ({30.0, 0.0}), 40.0 * std::sin(M_PI / 6.0), 1e-9);
  EXPECT_NEAR(machine.bodyTopZ({30.0, 77.0}), 40.0 * std::sin(M_PI / 6.0), 1e-9) << "the disc is round";
  profile.twoAxis.cradle = Eigen::AlignedBox3d(Vec3(40, 60, 0), Vec3(160, 140, 28));
  EXPECT_NEAR(TwoAxisMachine(profile, 0.0).bodyTopZ({0.0, 0.0}), 0.0, 1e-9) << "the cradle lies below the platform";
}

TEST(TwoAxisMachine, WithoutAProfileRadiusThePlatformIsThePlansDisc) {
  const PrinterProfile profile = [] {
    PrinterProfile p = offsetMachine();
    p.twoAxis.platformRadiusMm = 0.0;
    return p;
  }();
  EXPECT_DOUBLE_EQ(TwoAxisMachine(profile, 27.5).platformRadiusMm(), 27.5);
}
