// Which line each of Marlin's oks answers (marlin_line_ledger.h), without a printer: the oks are the test's.
#include "printer/marlin_line_ledger.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace multidir::hardware::marlin {
namespace {

// A ledger with the reset answered and `commands` numbered 1.. and sent; it records the lines acknowledged.
class LineLedgerTest : public ::testing::Test {
 protected:
  void sendAll(const std::vector<std::pair<std::string, LineRole>>& commands) {
    for (const auto& [command, role] : commands) ledger.append(StreamLine{command, role, 0});
    while (ledger.hasUnsent()) ledger.sendNext();
  }
  LineLedger::OkOutcome ok(const std::string& text) { return ledger.onOk(parseReply(text), record); }

  void SetUp() override {
    ledger.sendNext();  // N0 M110 N0
    ASSERT_EQ(ok("ok").acknowledged, 1);
    acknowledged.clear();
  }

  LineLedger ledger;
  std::vector<std::string> acknowledged;
  LineLedger::Acknowledge record = [this](const StreamLine& line) { acknowledged.push_back(line.command); };
};

TEST_F(LineLedgerTest, AnOkAnswersTheOldestLineInFlight) {
  sendAll({{"G1 X1", LineRole::File}, {"M400", LineRole::JobEnd}});
  EXPECT_EQ(ok("ok").acknowledged, 1);
  EXPECT_EQ(acknowledged, std::vector<std::string>{"G1 X1"});
  EXPECT_EQ(ledger.inFlight(), 1);
}

TEST_F(LineLedgerTest, AnOkWithNoLineInFlightAnswersNoLineAndSaysSo) {
  sendAll({{"M400", LineRole::JobEnd}});
  ASSERT_EQ(ok("ok").acknowledged, 1);
  const LineLedger::OkOutcome stray = ok("ok");
  EXPECT_EQ(stray.acknowledged, 0);
  EXPECT_NE(stray.warning.find("answers no line in flight (no line is)"), std::string::npos) << stray.warning;
  EXPECT_EQ(acknowledged, std::vector<std::string>{"M400"});
}

TEST_F(LineLedgerTest, AnAdvancedOkAnswersTheLineItNamesAndEveryLineBeforeIt) {
  sendAll({{"G1 X1", LineRole::File}, {"G1 X2", LineRole::File}, {"M400", LineRole::JobEnd}});
  EXPECT_EQ(ok("ok N2 P14 B2").acknowledged, 2);
  EXPECT_EQ(acknowledged, (std::vector<std::string>{"G1 X1", "G1 X2"}));
  EXPECT_EQ(ledger.inFlight(), 1);
}

TEST_F(LineLedgerTest, AnAdvancedOkForALineNotInFlightAnswersNoLine) {
  sendAll({{"G1 X1", LineRole::File}});
  const LineLedger::OkOutcome stale = ok("ok N0 P15 B3");
  EXPECT_EQ(stale.acknowledged, 0);
  EXPECT_NE(stale.warning.find("ok for line 0"), std::string::npos) << stale.warning;
  EXPECT_EQ(ledger.inFlight(), 1);
}

TEST_F(LineLedgerTest, ABareOkFromAPrinterWhoseOksCarryNumbersAnswersNoLineButM105sOkDoes) {
  sendAll({{"G1 X1", LineRole::File}, {"G1 X2", LineRole::File}});
  ASSERT_EQ(ok("ok N1 P15 B3").acknowledged, 1);
  EXPECT_EQ(ok("ok").acknowledged, 0);  // G1 X2 still waits for its numbered ok
  EXPECT_EQ(ledger.inFlight(), 1);
  ASSERT_EQ(ok("ok N2 P15 B3").acknowledged, 1);
  sendAll({{"M105", LineRole::Poll}});
  EXPECT_EQ(ok("ok T:20.0 /0.0 B:20.0 /0.0 @:0 B@:0").acknowledged, 1);  // Marlin writes M105's ok itself
}

TEST_F(LineLedgerTest, AnM105AnsweredWithoutTemperaturesIsABarePoll) {
  sendAll({{"M105", LineRole::Poll}, {"M105", LineRole::Poll}});
  EXPECT_TRUE(ok("ok").barePoll);
  EXPECT_FALSE(ok("ok T:20.0 /0.0").barePoll);
}

TEST_F(LineLedgerTest, TheOkAfterAResendAnswersNoNewLineAndTheRefusedLineGoesAgain) {
  sendAll({{"G1 X1", LineRole::File}, {"G1 X2", LineRole::File}});
  EXPECT_EQ(ledger.onResend(1, record), "");
  EXPECT_EQ(ok("ok").acknowledged, 0);
  EXPECT_TRUE(ledger.hasUnsent());
  EXPECT_EQ(ledger.sendNext(), 1);
  EXPECT_TRUE(acknowledged.empty());
}

}  // namespace
}  // namespace multidir::hardware::marlin
