// The printer link chosen from the address the operator types.
#include <gtest/gtest.h>

#include "multidir/hardware/printer_url.h"

namespace multidir::hardware {
namespace {

TEST(PrinterUrl, HttpAndBareHostPortMakeAMoonrakerLink) {
  for (const char* url : {"http://127.0.0.1:7125", "127.0.0.1:7126"}) {
    auto link = makePrinterLinkFromUrl(url, "");
    ASSERT_TRUE(link.ok()) << url << ": " << link.error().describe();
    EXPECT_NE((*link)->name().find("Moonraker printer at 127.0.0.1:712"), std::string::npos) << (*link)->name();
  }
}

TEST(PrinterUrl, AnUnknownSchemeIsRefusedNamingTheOnesKnown) {
  auto link = makePrinterLinkFromUrl("ftp://printer:21", "");
  ASSERT_FALSE(link.ok());
  EXPECT_EQ(link.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(link.error().message.find("'ftp://'"), std::string::npos) << link.error().message;
  EXPECT_NE(link.error().message.find("http://HOST:PORT"), std::string::npos) << link.error().message;
}

TEST(PrinterUrl, HttpsIsRefusedWithMoonrakersReason) {
  auto link = makePrinterLinkFromUrl("https://printer", "");
  ASSERT_FALSE(link.ok());
  EXPECT_NE(link.error().message.find("https is not supported"), std::string::npos) << link.error().message;
}

}  // namespace
}  // namespace multidir::hardware
