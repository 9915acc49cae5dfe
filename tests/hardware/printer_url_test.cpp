#include "multidir/hardware/printer_url.h"

#include <gtest/gtest.h>

namespace multidir::hardware {
namespace {

TEST(PrinterUrl, HttpAndBareAddressesStayMoonraker) {
  EXPECT_EQ(printerUrlScheme("http://192.168.0.20:7125").value(), "moonraker");
  EXPECT_EQ(printerUrlScheme("192.168.0.20:7125").value(), "moonraker");
  EXPECT_EQ(printerUrlScheme("moonraker://192.168.0.20").value(), "moonraker");
  const auto link = makePrinterLinkFromUrl("192.168.0.20", "");
  ASSERT_TRUE(link.ok()) << link.error().describe();
  EXPECT_EQ((*link)->name(), "Moonraker printer at 192.168.0.20:7125");
}

TEST(PrinterUrl, OctoPrintSchemeMakesAnOctoPrintLinkWithTheKey) {
  const auto link = makePrinterLinkFromUrl("octoprint://octopi.local:5000", "KEY");
  ASSERT_TRUE(link.ok()) << link.error().describe();
  EXPECT_EQ((*link)->name(), "OctoPrint printer at octopi.local:5000");
  const auto keyless = makePrinterLinkFromUrl("octoprint://octopi.local", "");
  ASSERT_FALSE(keyless.ok());
  EXPECT_NE(keyless.error().message.find("API key"), std::string::npos);
}

TEST(PrinterUrl, AnUnknownSchemeNamesTheOnesThereAre) {
  const auto link = makePrinterLinkFromUrl("prusalink://10.0.0.5", "");
  ASSERT_FALSE(link.ok());
  EXPECT_EQ(link.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(link.error().message.find("unknown printer scheme 'prusalink://'"), std::string::npos);
  EXPECT_NE(link.error().message.find("octoprint://HOST:PORT"), std::string::npos);
  EXPECT_NE(link.error().message.find("moonraker://HOST:PORT"), std::string::npos);
}

}  // namespace
}  // namespace multidir::hardware
