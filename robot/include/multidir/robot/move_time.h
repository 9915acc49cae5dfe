#pragma once
// The time of one move from rest to rest on a trapezoidal speed profile: up to `speed` at `accel`, on at it,
// down at `accel`; a triangle where the move is too short to reach `speed`. The robot's own estimate of a movel
// or a movej (docs/robot-cell.md): the programs' summary counts it, and the run's progress counts it the same way.
// One length unit for all three (mm, mm/s, mm/s^2; or rad, rad/s, rad/s^2).
namespace multidir::robot {

double trapezoidSeconds(double distance, double speed, double accel);

}  // namespace multidir::robot
