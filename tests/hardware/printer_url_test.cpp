// Printer addresses: which protocol a URL names (makePrinterLinkFromUrl), and how each protocol reads its host
// and port (parseMoonrakerUrl, parseOctoPrintUrl; Marlin's parseMarlinUrl in marlin_link_test.cpp), with their
// refusals.
#include "multidir/hardware/printer_url.h"

#include <gtest/gtest.h>

#include <vector>

#include "multidir/hardware/moonraker_link.h"
#include "multidir/hardware/octoprint_link.h"

namespace multidir::hardware {
namespace {

struct UrlCase {
  std::string url;
  std::string linkName;  // the link's name(): protocol, host and port as read
};

TEST(PrinterUrl, EachSchemeNamesItsProtocolHostAndDefaultPort) {
  const std::vector<UrlCase> cases = {
      {"http://192.168.0.20:7125", "Moonraker printer at 192.168.0.20:7125"},
      {"http://printer.local/", "Moonraker printer at printer.local:80"},
      {"127.0.0.1", "Moonraker printer at 127.0.0.1:7125"},
      {"moonraker://printer.local", "Moonraker printer at printer.local:7125"},
      {"octoprint://192.168.0.21:5000", "OctoPrint printer at 192.168.0.21:5000"},
      {"octoprint://octopi.local/", "OctoPrint printer at octopi.local:80"},
      {"serial:///dev/ttyACM0?baud=250000", "Marlin printer at /dev/ttyACM0"},
  };
  for (const UrlCase& c : cases) {
    const auto link = makePrinterLinkFromUrl(c.url, "KEY");
    ASSERT_TRUE(link.ok()) << c.url << ": " << link.error().describe();
    EXPECT_EQ((*link)->name(), c.linkName) << c.url;
  }
  ASSERT_TRUE(parseOctoPrintUrl("http://octopi.local").ok());
  EXPECT_EQ(parseOctoPrintUrl("http://octopi.local")->port, 80);
  EXPECT_EQ(parseOctoPrintUrl("octopi.local")->port, 80);
}

struct RefusedCase {
  std::string url;
  std::string says;
};

TEST(PrinterUrl, RefusesHttpsPathsNoHostAndBadPortsSayingWhy) {
  const std::vector<RefusedCase> cases = {
      {"https://p:7125", "https is not supported"},
      {"http://p:7125/api", "without a path"},
      {"p:99999", "1 to 65535"},
      {"http://:80", "names no host"},
      {"octoprint://octopi/api", "without a path"},
      {"octoprint://octopi:0", "1 to 65535"},
      {"octoprint://:80", "names no host"},
      {"serial://dev", "absolute device path"},
      {"serial:///dev/ttyACM0?baud=123", "baud must be one of"},
      {"prusalink://10.0.0.5", "unknown printer scheme 'prusalink://'"},
  };
  for (const RefusedCase& c : cases) {
    const auto link = makePrinterLinkFromUrl(c.url, "KEY");
    ASSERT_FALSE(link.ok()) << c.url;
    EXPECT_EQ(link.error().code, core::ErrorCode::InvalidParameter) << c.url;
    EXPECT_NE(link.error().message.find(c.says), std::string::npos) << c.url << ": " << link.error().message;
  }
}

TEST(PrinterUrl, AnUnknownSchemeNamesTheOnesThereAre) {
  const auto link = makePrinterLinkFromUrl("ftp://10.0.0.5", "");
  ASSERT_FALSE(link.ok());
  EXPECT_NE(link.error().message.find("octoprint://HOST:PORT"), std::string::npos);
  EXPECT_NE(link.error().message.find("moonraker://HOST:PORT"), std::string::npos);
  EXPECT_NE(link.error().message.find("serial:///dev/ttyACM0"), std::string::npos);
}

TEST(PrinterUrl, OctoPrintNeedsItsApiKeyMoonrakerAndMarlinDoNot) {
  EXPECT_TRUE(makePrinterLinkFromUrl("192.168.0.20", "").ok());
  EXPECT_TRUE(makePrinterLinkFromUrl("serial:///dev/ttyACM0", "").ok());
  const auto keyless = makePrinterLinkFromUrl("octoprint://octopi.local", "");
  ASSERT_FALSE(keyless.ok());
  EXPECT_NE(keyless.error().message.find("OctoPrint needs an API key"), std::string::npos);
}

}  // namespace
}  // namespace multidir::hardware
