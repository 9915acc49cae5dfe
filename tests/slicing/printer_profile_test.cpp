// Printer profiles: the shipped ones load with their platform drive; a bed without area, an unknown key and a
// missing profile are refused naming the file and key.
#include "multidir/slicing/printer_profile.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "slicing_fixtures.h"
#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;

namespace {

std::string profileFile(const std::string& name, const std::string& text) {
  return test::writeProfileFile("printer_profile", name, text);
}

}  // namespace

TEST(PrinterProfile, ShippedProfilesLoadByName) {
  const auto marlin = loadPrinterProfile("marlin-220");
  ASSERT_TRUE(marlin.ok()) << marlin.error().describe();
  EXPECT_EQ(marlin->platform, PlatformDrive::Modbus);
  EXPECT_EQ(marlin->bedMax(), Eigen::Vector2d(220, 220));
  EXPECT_DOUBLE_EQ(marlin->nozzleDiameterMm, 0.4);
  EXPECT_EQ(marlin->platformCenter, Eigen::Vector2d(110, 110));

  const auto klipper = loadPrinterProfile("klipper-rotary");
  ASSERT_TRUE(klipper.ok()) << klipper.error().describe();
  EXPECT_EQ(klipper->platform, PlatformDrive::FirmwareAxis);
  EXPECT_EQ(klipper->dialect, Dialect::Klipper);

  const auto robot = loadPrinterProfile("robot-0.8");
  ASSERT_TRUE(robot.ok()) << robot.error().describe();
  EXPECT_DOUBLE_EQ(robot->nozzleDiameterMm, 0.8);
  EXPECT_EQ(builtinPrinterNames(),
            (std::vector<std::string>{"klipper-2axis", "klipper-rotary", "marlin-220", "open5x-rrf", "robot-0.8",
                                      "ur5-cell-0.8"}));
  // The robot cell's profile: G-code relative to the platform centre, on the platform plane at rest.
  const auto cell = loadPrinterProfile("ur5-cell-0.8");
  ASSERT_TRUE(cell.ok()) << cell.error().describe();
  EXPECT_EQ(cell->platformCenter, Eigen::Vector2d(0, 0));
  EXPECT_DOUBLE_EQ(cell->platformZMm, 0.0);
  EXPECT_DOUBLE_EQ(cell->nozzleDiameterMm, 0.8);
}

TEST(PrinterProfile, BedWithoutAreaIsRefusedNamingTheKey) {
  const auto p = loadPrinterProfile(profileFile("flat", "bed_shape = 0x0,220x0,440x0\n"));
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(p.error().where.find("bed_shape"), std::string::npos) << p.error().describe();
}

TEST(PrinterProfile, UnreadableBedCornerIsMalformed) {
  const auto p = loadPrinterProfile(profileFile("corner", "bed_shape = 0x0,220,220x220\n"));
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, core::ErrorCode::MalformedFile);
}

TEST(PrinterProfile, UnknownMultiDirKeyIsRefused) {
  const auto p = loadPrinterProfile(profileFile("unknown", "# multidir.platfrom = modbus\n"));
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().where.find("multidir.platfrom"), std::string::npos) << p.error().describe();
}

TEST(PrinterProfile, MissingProfileListsTheShippedOnes) {
  const auto p = loadPrinterProfile("no-such-printer");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, core::ErrorCode::FileNotFound);
  EXPECT_NE(p.error().message.find("marlin-220"), std::string::npos);
}

TEST(PrinterProfile, DialectsParseByName) {
  EXPECT_EQ(*parseDialect("rrf"), Dialect::RepRapFirmware);
  EXPECT_FALSE(parseDialect("grbl").ok());
}

TEST(PrinterProfile, SettingAssignmentsParseInOrderAndRefuseAWordWithoutEquals) {
  const auto settings = parseSettingAssignments("  layer_height=0.3\tfill_density=0% ");
  ASSERT_TRUE(settings.ok());
  ASSERT_EQ(settings->size(), 2u);
  EXPECT_EQ((*settings)[0], std::make_pair(std::string("layer_height"), std::string("0.3")));
  EXPECT_EQ((*settings)[1], std::make_pair(std::string("fill_density"), std::string("0%")));
  EXPECT_TRUE(parseSettingAssignments("").ok());
  const auto wrong = parseSettingAssignments("layer_height=0.3 perimeters");
  ASSERT_FALSE(wrong.ok());
  EXPECT_EQ(wrong.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(wrong.error().message.find("'perimeters' is not KEY=VALUE"), std::string::npos);
}

TEST(PrinterProfile, AHotendTemperatureBeyondAnyHotendIsRefusedNamingTheFileKeyAndRange) {
  // The slicer took it and wrote `M104 S1`.
  const std::string path = profileFile("hot", "temperature = 1e308\n");
  const auto p = loadPrinterProfile(path);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_EQ(p.error().where, path + ": temperature");
  EXPECT_NE(p.error().message.find("1e308"), std::string::npos) << p.error().message;
  EXPECT_NE(p.error().message.find("°C in [0, 500]"), std::string::npos) << p.error().message;
}

TEST(PrinterProfile, ABedCornerBeyondAnyPrinterIsRefusedNamingTheFileKeyAndRange) {
  const std::string path = profileFile("huge-bed", "bed_shape = 0x0,1e308x0,1e308x1e308,0x1e308\n");
  const auto p = loadPrinterProfile(path);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_EQ(p.error().where, path + ": bed_shape");
  EXPECT_NE(p.error().message.find("mm in [-10000, 10000]"), std::string::npos) << p.error().message;
}

TEST(PrinterProfile, EveryNumericSettingMustBeFiniteAndWithinItsRange) {
  // Each line alone in a profile: the key it names is refused, with the range in the message.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"first_layer_temperature = 205,600", "first_layer_temperature"},
      {"bed_temperature = 1e308", "bed_temperature"},
      {"first_layer_bed_temperature = -5", "first_layer_bed_temperature"},
      {"max_print_height = 1e308", "max_print_height"},
      {"nozzle_diameter = 1e308", "nozzle_diameter"},
      {"layer_height = 1e308", "layer_height"},
      {"layer_height = 0", "layer_height"},
      {"first_layer_height = 1e308", "first_layer_height"},
      {"first_layer_height = 5000%", "first_layer_height"},
      {"extrusion_width = 1e308", "extrusion_width"},
      {"retract_length = nan", "retract_length"},
      {"retract_restart_extra = 1e308", "retract_restart_extra"},
      {"retract_speed = 1e308", "retract_speed"},
      {"deretract_speed = -1", "deretract_speed"},
      {"travel_speed = inf", "travel_speed"},
      {"# multidir.platform_z = 1e308", "multidir.platform_z"},
      {"# multidir.platform_center = 1e308,0", "multidir.platform_center"},
      {"# multidir.park = 0,-1e308", "multidir.park"},
      {"# multidir.rotary_feed = 1e308", "multidir.rotary_feed"},
      {"# multidir.clearance_margin = 1e308", "multidir.clearance_margin"},
  };
  for (const auto& [line, key] : cases) {
    SCOPED_TRACE(line);
    const std::string path = profileFile("range", line + "\n");
    const auto p = loadPrinterProfile(path);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().where, path + ": " + key);
    EXPECT_NE(p.error().message.find(" in "), std::string::npos) << p.error().message;  // "give mm in (0, 10)"
  }
}

TEST(PrinterProfile, PhysicalValuesAtTheEndsOfTheirRangesLoad) {
  const auto p = loadPrinterProfile(profileFile(
      "ends",
      "temperature = 0,500\nbed_temperature = 200\nfirst_layer_height = 150%\nextrusion_width = 0\n"
      "retract_restart_extra = -0.5\nderetract_speed = 0\nbed_shape = -10000x-10000,10000x-10000,10000x10000\n"
      "# multidir.platform_z = -10\n"));
  ASSERT_TRUE(p.ok()) << p.error().describe();
}
