// The run log follows its newest line, unless the reader scrolled up.
#include <gtest/gtest.h>

#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTextCursor>
#include <QTextDocument>
#include <QTest>

#include "ui/common/follow_newest_line.h"

namespace multidir::ui {
namespace {

void appendLines(QPlainTextEdit& log, int count) {
  for (int i = 0; i < count; ++i) log.appendPlainText(QStringLiteral("Step %1: printing").arg(i + 1));
  QCoreApplication::processEvents();
}

// The newest line is drawn inside the log's viewport.
bool newestLineInView(QPlainTextEdit& log) {
  QTextCursor end(log.document());
  end.movePosition(QTextCursor::End);
  const QRect line = log.cursorRect(end);
  return line.top() >= 0 && line.bottom() <= log.viewport()->rect().bottom();
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

// The Hardware dock seen once, then tabbed away during a run: shown again, the log is on its newest line (Qt's
// own follows only while the log is visible, and jumps to the cursor only on the very first show).
TEST_F(FollowNewestLineTest, ALogFilledWhileHiddenShowsItsNewestLineAgain) {
  log.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&log));
  appendLines(log, 20);
  log.hide();
  appendLines(log, 300);
  log.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&log));
  QCoreApplication::processEvents();
  QScrollBar* bar = log.verticalScrollBar();
  ASSERT_GT(bar->maximum(), 0);
  EXPECT_EQ(bar->value(), bar->maximum());
}

// The run log made shorter by its dock's layout while on its newest line (a banner or the "printer has no job"
// text appears above it, the dock is resized): the lines that no longer fit go above, and the log stays on its
// newest line, and on the lines that come after. Qt's own following sees the newest line below the view after
// such a resize and stops following (this test fails without FollowNewestLine).
TEST_F(FollowNewestLineTest, ALogMadeShorterByItsLayoutStaysOnTheNewestLine) {
  log.resize(300, 300);
  log.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&log));
  appendLines(log, 100);
  QScrollBar* bar = log.verticalScrollBar();
  ASSERT_EQ(bar->value(), bar->maximum());
  log.resize(300, 100);
  QCoreApplication::processEvents();
  EXPECT_EQ(bar->value(), bar->maximum());
  EXPECT_TRUE(newestLineInView(log));
  appendLines(log, 5);
  EXPECT_EQ(bar->value(), bar->maximum());
  EXPECT_TRUE(newestLineInView(log));
}

// Past the log's 1,000 lines the oldest go as new ones come: the view stays on the newest.
TEST_F(FollowNewestLineTest, ALogPastItsLineLimitStaysOnTheNewest) {
  log.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&log));
  for (int batch = 0; batch < 30; ++batch) appendLines(log, 50);
  QScrollBar* bar = log.verticalScrollBar();
  ASSERT_GT(bar->maximum(), 0);
  EXPECT_EQ(bar->value(), bar->maximum());
  EXPECT_EQ(log.document()->blockCount(), 1000);
}

}  // namespace
}  // namespace multidir::ui
