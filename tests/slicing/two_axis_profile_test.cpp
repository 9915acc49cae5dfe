// Printer profiles with two firmware axes (multidir.platform = firmware-2axis): the shipped ones load with their
// axes; every multidir.tilt_* / rotation_* key is checked, naming the file, the key and what to give; only the
// Open5x arrangement (the rotation axis on the tilt cradle) is accepted.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "multidir/slicing/printer_profile.h"
#include "slicing_fixtures.h"
#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;

namespace {

std::string profileFile(const std::string& name, const std::string& text) {
  return test::writeProfileFile("two_axis_profile", name, text);
}

}  // namespace

TEST(PrinterProfile, ShippedOpen5xProfileHasATiltAndARotationAxisUnderRrf) {
  const auto p = loadPrinterProfile("open5x-rrf");
  ASSERT_TRUE(p.ok()) << p.error().describe();
  EXPECT_EQ(p->platform, PlatformDrive::FirmwareTwoAxis);
  EXPECT_STREQ(platformDriveName(p->platform), "firmware-2axis");
  EXPECT_EQ(p->dialect, Dialect::RepRapFirmware);
  EXPECT_EQ(p->twoAxis.tilt.letter, "U");
  EXPECT_EQ(p->twoAxis.rotation.letter, "V");
  EXPECT_EQ(p->twoAxis.tiltAlong, TiltAlong::X);
  EXPECT_DOUBLE_EQ(p->twoAxis.tilt.minDegrees, -90.0);
  EXPECT_DOUBLE_EQ(p->twoAxis.tilt.maxDegrees, 90.0);
  EXPECT_EQ(p->twoAxis.rotationCenter, Eigen::Vector2d(110, 110));
}

TEST(PrinterProfile, ShippedKlipperTwoAxisProfileNamesItsTwoManualSteppers) {
  const auto p = loadPrinterProfile("klipper-2axis");
  ASSERT_TRUE(p.ok()) << p.error().describe();
  EXPECT_EQ(p->platform, PlatformDrive::FirmwareTwoAxis);
  EXPECT_EQ(p->dialect, Dialect::Klipper);
  EXPECT_EQ(p->twoAxis.tilt.klipperStepper, "tilt");
  EXPECT_EQ(p->twoAxis.rotation.klipperStepper, "rotation");
  EXPECT_EQ(p->twoAxis.tilt.letter + p->twoAxis.rotation.letter, "BC");
}

TEST(PrinterProfile, EveryTwoAxisKeyIsRead) {
  const auto p = loadPrinterProfile(profileFile(
      "all",
      "# multidir.platform = firmware-2axis\n# multidir.axis_mount = rotation-on-tilt\n"
      "# multidir.tilt_axis = A\n# multidir.rotation_axis = C\n# multidir.tilt_zero = 12.5\n"
      "# multidir.tilt_direction = -1\n# multidir.tilt_min = -30\n# multidir.tilt_max = 120\n"
      "# multidir.rotation_zero = -45\n# multidir.rotation_direction = -1\n# multidir.rotation_min = -36000\n"
      "# multidir.rotation_max = 36000\n# multidir.tilt_along = Y\n# multidir.tilt_height = 42.5\n"
      "# multidir.rotation_center = 80,90\n# multidir.klipper_tilt_stepper = stepper_a\n"
      "# multidir.klipper_rotation_stepper = stepper_c\n"));
  ASSERT_TRUE(p.ok()) << p.error().describe();
  const TwoAxisPlatform& axes = p->twoAxis;
  EXPECT_EQ(axes.tilt.letter, "A");
  EXPECT_EQ(axes.rotation.letter, "C");
  EXPECT_DOUBLE_EQ(axes.tilt.zeroDegrees, 12.5);
  EXPECT_DOUBLE_EQ(axes.tilt.direction, -1.0);
  EXPECT_DOUBLE_EQ(axes.tilt.minDegrees, -30.0);
  EXPECT_DOUBLE_EQ(axes.tilt.maxDegrees, 120.0);
  EXPECT_DOUBLE_EQ(axes.rotation.zeroDegrees, -45.0);
  EXPECT_DOUBLE_EQ(axes.rotation.direction, -1.0);
  EXPECT_DOUBLE_EQ(axes.rotation.minDegrees, -36000.0);
  EXPECT_DOUBLE_EQ(axes.rotation.maxDegrees, 36000.0);
  EXPECT_EQ(axes.tiltAlong, TiltAlong::Y);
  EXPECT_DOUBLE_EQ(axes.tiltHeightMm, 42.5);
  EXPECT_EQ(axes.rotationCenter, Eigen::Vector2d(80, 90));
  EXPECT_EQ(axes.tilt.klipperStepper, "stepper_a");
  EXPECT_EQ(axes.rotation.klipperStepper, "stepper_c");
}

TEST(PrinterProfile, TheRotationAxisStandsAtThePlatformCentreUnlessTold) {
  const auto p = loadPrinterProfile(
      profileFile("centre", "bed_shape = 0x0,250x0,250x210,0x210\n# multidir.platform = firmware-2axis\n"));
  ASSERT_TRUE(p.ok()) << p.error().describe();
  EXPECT_EQ(p->twoAxis.rotationCenter, Eigen::Vector2d(125, 105));
}

TEST(PrinterProfile, ATiltAxisCarriedByTheTurntableIsRefusedSayingWhatIsSupported) {
  const std::string path = profileFile("mount", "# multidir.axis_mount = tilt-on-rotation\n");
  const auto p = loadPrinterProfile(path);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_EQ(p.error().where, path + ": multidir.axis_mount");
  EXPECT_NE(p.error().message.find("not supported"), std::string::npos) << p.error().message;
  EXPECT_NE(p.error().message.find("rotation-on-tilt"), std::string::npos) << p.error().message;
}

TEST(PrinterProfile, EveryTwoAxisValueOutOfItsRangeIsRefusedNamingTheFileKeyAndRange) {
  // Each line alone in a profile: the key and the part of the message that says what to give.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"tilt_zero = 400", "degrees in [-360, 360]"},
      {"tilt_min = -1e308", "degrees in [-360, 360]"},
      {"tilt_max = nan", "degrees in [-360, 360]"},
      {"rotation_zero = -361", "degrees in [-360, 360]"},
      {"rotation_min = -1e6", "degrees in [-100000, 100000]"},
      {"rotation_max = inf", "degrees in [-100000, 100000]"},
      {"tilt_height = 1e5", "mm in [-10000, 10000]"},
      {"rotation_center = 1e308,0", "mm in [-10000, 10000]"},
      {"tilt_direction = 2", "give 1"},
      {"rotation_direction = 0", "or -1"},
      {"tilt_axis = X", "A B C U V W"},
      {"rotation_axis = VV", "A B C U V W"},
      {"tilt_along = Z", "X or Y"},
      {"axis_mount = sideways", "rotation-on-tilt"},
      {"klipper_tilt_stepper = two words", "[manual_stepper]"},
      {"platform = firmware-3axis", "firmware-2axis"},
      {"platform_radius = -1", "mm in [0, 10000]"},
      {"platform_thickness = 1e9", "mm in [0, 1000]"},
      {"cradle_box = 1,2,3", "six numbers"},
      {"cradle_box = 0,0,0,10,10,nan", "six numbers"},
      {"cradle_box = 0,0,0,1e308,10,10", "mm in [-10000, 10000]"},
      {"cradle_box = 10,0,0,0,10,10", "minimum must be below its maximum"},
  };
  for (const auto& [line, range] : cases) {
    SCOPED_TRACE(line);
    const std::string key = "multidir." + line.substr(0, line.find(' '));
    const std::string path = profileFile("range", "# multidir." + line + "\n");
    const auto p = loadPrinterProfile(path);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().where, path + ": " + key);
    EXPECT_NE(p.error().message.find(range), std::string::npos) << p.error().message;
  }
}

TEST(PrinterProfile, TwoAxisLimitsMustBeInOrder) {
  const std::string path = profileFile("order", "# multidir.tilt_min = 90\n# multidir.tilt_max = -90\n");
  const auto p = loadPrinterProfile(path);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().where, path + ": multidir.tilt_min");
  EXPECT_NE(p.error().message.find("tilt_min (90) is not below tilt_max (-90)"), std::string::npos)
      << p.error().message;
}

TEST(PrinterProfile, TheTiltAndTheRotationAxisNeedTheirOwnLetters) {
  const std::string path = profileFile("letters", "# multidir.tilt_axis = V\n# multidir.rotation_axis = V\n");
  const auto p = loadPrinterProfile(path);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().where, path + ": multidir.rotation_axis");
  EXPECT_NE(p.error().message.find("both V"), std::string::npos) << p.error().message;
}

TEST(PrinterProfile, ThePlatformsBodyIsReadFromItsKeys) {
  const auto p = loadPrinterProfile(profileFile(
      "body", "# multidir.platform = firmware-2axis\n# multidir.platform_radius = 45\n"
              "# multidir.platform_thickness = 8\n# multidir.cradle_box = 60,70,-40,160,150,-5\n"));
  ASSERT_TRUE(p.ok()) << p.error().describe();
  EXPECT_DOUBLE_EQ(p->twoAxis.platformRadiusMm, 45.0);
  EXPECT_DOUBLE_EQ(p->twoAxis.platformThicknessMm, 8.0);
  ASSERT_TRUE(p->twoAxis.cradle.has_value());
  EXPECT_EQ(p->twoAxis.cradle->min(), Eigen::Vector3d(60, 70, -40));
  EXPECT_EQ(p->twoAxis.cradle->max(), Eigen::Vector3d(160, 150, -5));
}
