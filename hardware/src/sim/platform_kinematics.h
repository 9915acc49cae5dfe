#pragma once
// What the devices physically do with the angles they are sent, modelled from the device side (the URScript
// program's formulas, the rotary controller's shaft), not from core's pose convention: tests compare the
// two, so the simulators must not borrow core's answer.
//
// Frames: the platform frame at rest ("level TCP frame" in the URScript): z is the platform's normal, x the
// direction azimuth 0 points to (the machine files' +X, +Y, +Z). An orientation is the rotation taking
// platform-frame vectors to where they point now, in that same frame held fixed in the room.
#include <Eigen/Geometry>

namespace multidir::hardware::sim {

// multidir_platform.script's orientation_pose(tilt, azimuth): pose_trans(p_level, p[0, 0, 0, rx, ry, 0])
// with the rotation vector (rx, ry) = tilt * (sin a, -cos a).
Eigen::Matrix3d urscriptTargetOrientation(double tiltDegrees, double azimuthDegrees);

// The tilt and azimuth the script reports (ACTUAL_TILT, ACTUAL_AZIMUTH): the platform-frame direction that
// points straight up now (the room's z seen from the platform). Azimuth 0 while the tilt is below 0.01 deg.
struct ReportedTilt {
  double tiltDegrees = 0.0;
  double azimuthDegrees = 0.0;
};
ReportedTilt urscriptReportedTilt(const Eigen::Matrix3d& orientation);

// movel's orientation path: along the shortest rotation from `from` to `to`, at most `maxRadians` of it.
// Returns `to` when it is that close.
Eigen::Matrix3d turnedTowards(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to, double maxRadians);
// The angle of the rotation between two orientations (radians).
double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

// The rotary controller's shaft lies along `shaftAxis` (platform frame, unit); positive angles turn the
// platform's top towards z x shaftAxis, i.e. the platform turns by -angle about the shaft.
Eigen::Matrix3d rotaryShaftOrientation(double angleDegrees, const Eigen::Vector3d& shaftAxis);

}  // namespace multidir::hardware::sim
