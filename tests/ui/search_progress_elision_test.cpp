// The search's progress text never wraps or is cut off blindly: in a narrow Search dock it is elided to the
// bar's width ("...") and read whole in the bar's tooltip.
#include <gtest/gtest.h>

#include <QProgressBar>
#include <QTest>

#include "multidir/core/search/search_options.h"
#include "ui/panels/search_panel.h"

namespace multidir::ui {
namespace {

core::SearchProgress someLevel() {
  core::SearchProgress progress;
  progress.level = 7;
  progress.beamsAlive = 12;
  progress.bestJgMm2 = 1402.7;
  progress.candidatesScored = 123456;
  return progress;
}

TEST(SearchProgressElision, LongProgressTextIsElidedToTheBarAndWholeInItsTooltip) {
  SearchPanel panel;
  panel.resize(260, 700);
  panel.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
  panel.searchStarted(2000.0, 122);
  panel.showProgress(someLevel());
  auto* bar = panel.findChild<QProgressBar*>(QStringLiteral("searchProgress"));
  ASSERT_NE(bar, nullptr);
  const QString whole = panel.progressText();
  EXPECT_TRUE(whole.startsWith(QStringLiteral("Level 7 of 122 · beams alive: 12"))) << whole.toStdString();
  EXPECT_EQ(bar->toolTip(), whole);
  const QString shown = bar->text();
  EXPECT_LE(bar->fontMetrics().horizontalAdvance(shown), bar->contentsRect().width()) << shown.toStdString();
  EXPECT_TRUE(shown.endsWith(QChar(0x2026))) << shown.toStdString();

  // Wider, it shows more of it; wide enough, all of it.
  panel.resize(1400, 700);
  QCoreApplication::processEvents();
  EXPECT_EQ(bar->text(), whole);
}

}  // namespace
}  // namespace multidir::ui
