// What the Search panel says while a search runs (issue 11, items 12 and 13): the progress bar names the
// level of how many, the beams alive, the best J_G, the candidates scored and the time taken, and says it is
// cancelling (never "done") while it cancels; the two "Max. overhang angle" controls are one value.
#include <gtest/gtest.h>

#include <vector>

#include <QDoubleSpinBox>
#include <QLocale>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSlider>
#include <QStringList>
#include <QTest>

#include "multidir/core/search/search_options.h"
#include "ui/jobs/search_job.h"
#include "ui/main_window.h"
#include "ui/panels/overhang_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

// Every text the progress bar shows from now on, read after the panel has taken each report.
class ProgressTexts {
 public:
  explicit ProgressTexts(MainWindow& window) : m_panel(window.searchPanel()) {
    auto* job = window.findChild<SearchJob*>();
    EXPECT_NE(job, nullptr);
    // Connected after the window's own connections, so these run once the panel has been updated.
    QObject::connect(job, &SearchJob::progressed, m_panel, [this] { record(); });
    QObject::connect(job, &SearchJob::fractionChanged, m_panel, [this] { record(); });
  }
  void record() {
    const QString text = m_panel->progressText();
    if (m_texts.isEmpty() || m_texts.back() != text) m_texts << text;
  }
  [[nodiscard]] const QStringList& texts() const { return m_texts; }

 private:
  SearchPanel* m_panel;
  QStringList m_texts;
};

TEST(StudioSearchProgress, ProgressSaysLevelOfHowManyBeamsBestJgCandidatesAndElapsedTime) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("snowman")));
  ProgressTexts progress(window);
  const int levels = core::maxSearchLevels(test::quickSearchOptions());
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  const QRegularExpression expected(QStringLiteral("^Level \\d+ of %1 · beams alive: \\d+ · best J_G [\\d.,]+ mm² · "
                                                   "[\\d.,]+ candidates · \\d+:\\d\\d$")
                                        .arg(levels));
  bool seen = false;
  for (const QString& text : progress.texts()) seen = seen || expected.match(text).hasMatch();
  EXPECT_TRUE(seen) << progress.texts().join(QStringLiteral(" | ")).toStdString();
  EXPECT_FALSE(progress.texts().contains(QStringLiteral("Starting...")));
}

TEST(StudioSearchProgress, CancellingSaysSoUntilTheSearchHasStoppedAndNeverDone) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("snowman")));
  window.searchPanel()->setSearchOptions(test::longSearchOptions());
  QSignalSpy finished(&window, &MainWindow::searchFinished);
  QSignalSpy failed(&window, &MainWindow::searchFailed);
  ASSERT_TRUE(window.runSearch());
  QTest::qWait(1000);  // under way: it has a best plan to deliver
  ASSERT_TRUE(window.isSearching()) << "the search ended before it could be cancelled";
  window.cancelSearch();
  ProgressTexts progress(window);
  progress.record();
  ASSERT_TRUE(test::waitUntil([&] { return !finished.isEmpty() || !failed.isEmpty(); }, test::kSearchTimeoutMs));
  ASSERT_FALSE(finished.isEmpty()) << failed.front().front().toString().toStdString();
  ASSERT_FALSE(progress.texts().isEmpty());
  for (const QString& text : progress.texts()) {
    EXPECT_TRUE(text.startsWith(QStringLiteral("Cancelling"))) << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("done"))) << text.toStdString();
  }
  EXPECT_EQ(window.searchPanel()->progressText(), QStringLiteral("Cancelled"));
}

// The Search dock's "Best J_G" read-out, as a number (the read-out is "level|beams|best J_G|candidates").
double shownBestJg(const SearchPanel& panel) {
  QString best = panel.readoutText().section(QLatin1Char('|'), 2, 2);
  best.remove(QStringLiteral(" mm²"));
  bool ok = false;
  const double value = QLocale().toDouble(best, &ok);
  EXPECT_TRUE(ok) << best.toStdString();
  return value;
}

TEST(StudioSearchProgress, AfterCancelBestJgIsTheDeliveredPlansAndNeverRoseOrJumped) {
  // Issue 29: fertility, the default search, cancelled part-way: "Best J_G" showed the beams' 559.1 mm² and
  // jumped to the delivered plan's 12.2 mm² on Cancel, and the level read "Level 3 of 122".
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(
      test::openModelFile(window, QStringLiteral(MULTIDIR_SHARED_MODELS_DIR "/fertility.off")));
  window.searchPanel()->setSearchOptions(core::SearchOptions{});
  auto* job = window.findChild<SearchJob*>();
  ASSERT_NE(job, nullptr);
  std::vector<double> shown;
  QStringList levels;
  // Connected after the window's own connections, so these read the dock once it took each report.
  QObject::connect(job, &SearchJob::progressed, window.searchPanel(), [&] {
    shown.push_back(shownBestJg(*window.searchPanel()));
    levels << window.searchPanel()->progressText();
  });
  QSignalSpy finished(&window, &MainWindow::searchFinished);
  ASSERT_TRUE(window.runSearch());
  ASSERT_TRUE(test::waitUntil([&] { return shown.size() >= 3 || !finished.isEmpty(); }, test::kSearchTimeoutMs));
  ASSERT_TRUE(window.isSearching()) << "the search ended before it could be cancelled";
  window.cancelSearch();
  ASSERT_TRUE(finished.wait(test::kSearchTimeoutMs));
  const SearchRun run = finished.front().front().value<SearchRun>();
  ASSERT_TRUE(run.plan);
  ASSERT_TRUE(run.plan->cancelled);

  const double delivered = shownBestJg(*window.searchPanel());
  EXPECT_NEAR(delivered, run.plan->jgAfterMm2, 0.05);
  ASSERT_FALSE(shown.empty());
  for (std::size_t i = 1; i < shown.size(); ++i) EXPECT_LE(shown[i], shown[i - 1]) << "report " << i;
  EXPECT_DOUBLE_EQ(shown.back(), delivered) << "Best J_G jumped on Cancel";
  // "Level k of n": k a level the search reached, n the deepest one search may reach.
  const QRegularExpression level(QStringLiteral("Level (\\d+) of (\\d+)"));
  const int bound = core::maxSearchLevels(core::SearchOptions{});
  for (const QString& text : levels) {
    const QRegularExpressionMatch match = level.match(text);
    if (!match.hasMatch()) continue;
    EXPECT_LE(match.captured(1).toInt(), run.plan->statistics.levels) << text.toStdString();
    EXPECT_EQ(match.captured(2).toInt(), bound) << text.toStdString();
  }
  EXPECT_EQ(bound, 81);  // w = 40 at two scales: the finer scale's regions keep V/80
  EXPECT_EQ(window.searchPanel()->progressText(), QStringLiteral("Cancelled"));
}

TEST(StudioOverhangAngle, OverhangsAndSearchPanelsShowOneValue) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("snowman")));
  auto* overhangSpin = window.overhangPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("alphaSpin"));
  auto* overhangSlider = window.overhangPanel()->findChild<QSlider*>(QStringLiteral("alphaSlider"));
  auto* searchSpin = window.searchPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("searchAlpha"));
  ASSERT_TRUE(overhangSpin && overhangSlider && searchSpin);

  overhangSlider->setValue(30);
  EXPECT_DOUBLE_EQ(searchSpin->value(), 30.0);
  EXPECT_DOUBLE_EQ(window.searchPanel()->searchOptions().alphaMaxDegrees, 30.0);

  const QString riskyAt30 = window.overhangPanel()->riskyAreaText();
  searchSpin->setValue(52.5);
  EXPECT_DOUBLE_EQ(overhangSpin->value(), 52.5);
  EXPECT_DOUBLE_EQ(window.overhangPanel()->alphaMaxDegrees(), 52.5);
  EXPECT_EQ(overhangSlider->value(), 53);
  EXPECT_NE(window.overhangPanel()->riskyAreaText(), riskyAt30) << "the overhangs were not recoloured";

  // A project's or plan's settings set both.
  core::SearchOptions options = test::quickSearchOptions();
  options.alphaMaxDegrees = 40.0;
  window.searchPanel()->setSearchOptions(options);
  EXPECT_DOUBLE_EQ(overhangSpin->value(), 40.0);
}

}  // namespace
}  // namespace multidir::ui
