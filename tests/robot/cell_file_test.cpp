// The cell file written (the studio's Save): what parseCell reads back is the cell that was written.
#include <gtest/gtest.h>

#include "multidir/robot/arm_frames.h"
#include "multidir/robot/cell.h"
#include "multidir/robot/cell_file.h"
#include "support/test_models.h"

namespace multidir::robot {
namespace {

const std::string kShippedCell = std::string(MULTIDIR_SOURCE_DIR) + "/resources/cells/ur5-fixed-extruder.json";

void expectSameCell(const Cell& a, const Cell& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.arm.name, b.arm.name);
  for (std::size_t j = 0; j < 6; ++j) {
    EXPECT_NEAR(a.arm.limits[j].minRad, b.arm.limits[j].minRad, 1e-9) << "joint " << j;
    EXPECT_NEAR(a.arm.limits[j].maxRad, b.arm.limits[j].maxRad, 1e-9) << "joint " << j;
    EXPECT_NEAR(a.arm.limits[j].maxSpeedRadPerS, b.arm.limits[j].maxSpeedRadPerS, 1e-9) << "joint " << j;
    EXPECT_NEAR(a.arm.limits[j].maxAccelRadPerS2, b.arm.limits[j].maxAccelRadPerS2, 1e-9) << "joint " << j;
    EXPECT_NEAR(a.home[j], b.home[j], 1e-9) << "joint " << j;
  }
  EXPECT_LT((a.nozzleTipMm - b.nozzleTipMm).norm(), 1e-9);
  EXPECT_LT((a.nozzleAxis - b.nozzleAxis).norm(), 1e-9);
  EXPECT_TRUE(a.flangeToPlatform.isApprox(b.flangeToPlatform, 1e-9));
  EXPECT_DOUBLE_EQ(a.platformRadiusMm, b.platformRadiusMm);
  EXPECT_DOUBLE_EQ(a.tableZMm, b.tableZMm);
  EXPECT_DOUBLE_EQ(a.maxFilamentMmPerS, b.maxFilamentMmPerS);
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  for (std::size_t i = 0; i < a.boxes.size(); ++i) {
    EXPECT_EQ(a.boxes[i].name, b.boxes[i].name);
    EXPECT_TRUE(a.boxes[i].pose.isApprox(b.boxes[i].pose, 1e-9));
    EXPECT_LT((a.boxes[i].sizeMm - b.boxes[i].sizeMm).norm(), 1e-9);
  }
  ASSERT_EQ(a.cylinders.size(), b.cylinders.size());
  for (std::size_t i = 0; i < a.cylinders.size(); ++i) {
    EXPECT_LT((a.cylinders[i].baseMm - b.cylinders[i].baseMm).norm(), 1e-9);
    EXPECT_DOUBLE_EQ(a.cylinders[i].lengthMm, b.cylinders[i].lengthMm);
  }
  EXPECT_DOUBLE_EQ(a.margins.minReachMm, b.margins.minReachMm);
  EXPECT_DOUBLE_EQ(a.motion.travelSpeedMmPerS, b.motion.travelSpeedMmPerS);
}

TEST(CellFile, ShippedCellWrittenReadsBackUnchanged) {
  const Cell shipped = loadCell(kShippedCell).value();
  const std::string path = test::scratchDirectory("CellFile.Shipped") + "/cell.json";
  ASSERT_TRUE(writeCell(shipped, path).ok());
  const auto read = loadCell(path);
  ASSERT_TRUE(read.ok()) << read.error().describe();
  expectSameCell(shipped, *read);
}

TEST(CellFile, EditedModelNozzleAndCalibrationReadBack) {
  Cell cell = loadCell(kShippedCell).value();
  cell.arm = armModel("ur10e").value();
  cell.nozzleTipMm = Eigen::Vector3d(12.5, -480.25, 390.0);
  cell.flangeToPlatform.translation() = Eigen::Vector3d(0.3, -0.2, 52.7);
  cell.flangeToPlatform.linear() = Eigen::AngleAxisd(0.02, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  cell.tableZMm = -12.0;
  const std::string path = test::scratchDirectory("CellFile.Edited") + "/cell.json";
  ASSERT_TRUE(writeCell(cell, path).ok());
  const auto read = parseCell(path);
  ASSERT_TRUE(read.ok()) << read.error().describe();
  expectSameCell(cell, *read);
}

TEST(CellFile, UnwritablePathIsAnErrorNamingIt) {
  const Cell cell = loadCell(kShippedCell).value();
  const std::string path = test::scratchDirectory("CellFile.Unwritable") + "/no/such/folder/cell.json";
  const auto written = writeCell(cell, path);
  ASSERT_FALSE(written.ok());
  EXPECT_NE(written.error().describe().find("cell.json"), std::string::npos) << written.error().describe();
}

// The frames the studio draws the arm with end at the flange forward kinematics gives, for every model.
TEST(ArmFrames, LastFrameIsTheFlangeOfForwardKinematics) {
  const Joints q{0.3, -1.2, 1.1, -0.4, 1.3, 0.7};
  for (const std::string& name : armModelNames()) {
    const ArmModel arm = armModel(name).value();
    const auto frames = armFrames(arm, q);
    EXPECT_TRUE(frames[0].isApprox(Eigen::Isometry3d::Identity()));
    EXPECT_TRUE(frames[6].isApprox(forwardKinematics(arm, q), 1e-12)) << name;
    // The base joint's frame 1 sits d1 up the base axis.
    EXPECT_NEAR(frames[1].translation().z(), arm.d[0], 1e-12) << name;
  }
}

}  // namespace
}  // namespace multidir::robot
