// Printer profiles: the shipped ones load with their platform drive; a bed without area, an unknown key and a
// missing profile are refused naming the file and key.
#include "multidir/slicing/printer_profile.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;

namespace {

std::string profileFile(const std::string& name, const std::string& text) {
  const std::string dir = test::scratchDirectory("printer_profile." + name);
  const std::string path = dir + "/" + name + ".ini";
  std::ofstream(path) << text;
  return path;
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
  EXPECT_EQ(builtinPrinterNames(), (std::vector<std::string>{"klipper-rotary", "marlin-220", "robot-0.8"}));
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
