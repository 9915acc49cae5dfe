#include <gtest/gtest.h>

#include "multidir/core/common/units.h"

using namespace multidir::core;

TEST(Units, DegreesAndRadiansConvertBothWays) {
  EXPECT_DOUBLE_EQ(degToRad(180.0), kPi);
  EXPECT_DOUBLE_EQ(radToDeg(degToRad(45.0)), 45.0);
}
