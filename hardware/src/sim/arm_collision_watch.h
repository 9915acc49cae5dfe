#pragma once
// The simulated cell's physical check (docs/hardware.md, "UR controller"): every stretch of joint motion the
// simulated arm executes (movej, movel, braking alike) sampled so no point of the arm or the platform moves more
// than kWatchSampleMm between samples, and at each sample the arm's links (robot/arm_links.h: capsules on the
// arm's forward kinematics) and the platform disc (the cell's flangeToPlatform, radius and thickness) tested
// against the cell's boxes, cylinders and the table plane itself (no margin: contact, as a real arm would crash).
// It knows only the cell file and the joints the arm took: nothing of robot-program's planning or answers.
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "multidir/robot/cell.h"

namespace multidir::hardware::sim {

constexpr double kWatchSampleMm = 2.0;

class ArmCollisionWatch {
 public:
  explicit ArmCollisionWatch(robot::Cell cell);
  // The first contact on the joint path from `from` to `to` (straight in joint space, as one tick moves), in words
  // ("the arm's forearm touches the cell's body \"extruder\""), or an empty string.
  [[nodiscard]] std::string firstContact(const robot::Joints& from, const robot::Joints& to) const;

 private:
  [[nodiscard]] std::string contactAt(const robot::Joints& q) const;

  robot::Cell m_cell;
  std::vector<Eigen::Vector3d> m_platform;  // rim points, top and bottom, in the platform frame
};

}  // namespace multidir::hardware::sim
