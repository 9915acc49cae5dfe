// The run log follows its newest line, unless the reader scrolled up.
#include <gtest/gtest.h>

#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTest>

#include "ui/common/follow_newest_line.h"

namespace multidir::ui {
namespace {

void appendLines(QPlainTextEdit& log, int count) {
  for (int i = 0; i < count; ++i) log.appendPlainText(QStringLiteral("Step %1: printing").arg(i + 1));
  QCoreApplication::processEvents();
}

class FollowNewestLineTest : public ::testing::Test {
 protected:
  void SetUp() override {
    log.setMaximumBlockCount(1000);  // as the Hardware panel's run log
    log.resize(300, 120);
    new FollowNewestLine(&log);
  }
  QPlainTextEdit log;
};

TEST_F(FollowNewestLineTest, NewLinesScrollTheLogToTheNewest) {
  log.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&log));
  appendLines(log, 200);
  QScrollBar* bar = log.verticalScrollBar();
  ASSERT_GT(bar->maximum(), 0);
  EXPECT_EQ(bar->value(), bar->maximum());
}

TEST_F(FollowNewestLineTest, AReaderScrolledUpStaysWhereHeIs) {
  log.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&log));
  appendLines(log, 200);
  QScrollBar* bar = log.verticalScrollBar();
  bar->setValue(10);
  appendLines(log, 50);
  EXPECT_EQ(bar->value(), 10);
  bar->setValue(bar->maximum());  // back at the bottom: following again
  appendLines(log, 50);
  EXPECT_EQ(bar->value(), bar->maximum());
}

TEST_F(FollowNewestLineTest, ALogFilledWhileHiddenOpensOnItsNewestLine) {
  appendLines(log, 300);  // the Hardware dock tabbed away during a run
  log.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&log));
  QCoreApplication::processEvents();
  QScrollBar* bar = log.verticalScrollBar();
  ASSERT_GT(bar->maximum(), 0);
  EXPECT_EQ(bar->value(), bar->maximum());
}

}  // namespace
}  // namespace multidir::ui
