#include "multidir/robot/move_time.h"

#include <cmath>

namespace multidir::robot {

double trapezoidSeconds(double distance, double speed, double accel) {
  if (distance <= 0.0) return 0.0;
  if (distance >= speed * speed / accel) return distance / speed + speed / accel;
  return 2.0 * std::sqrt(distance / accel);
}

}  // namespace multidir::robot
