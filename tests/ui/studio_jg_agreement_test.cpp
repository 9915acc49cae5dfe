// The studio shows the one J_G of docs/jg-definition.md: the same number core's search gives for the same
// model, machine and options, in the search panel and in the plan's summary.
#include <gtest/gtest.h>

#include <QLabel>
#include <QLocale>

#include "multidir/core/search/decompose.h"
#include "ui/main_window.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

TEST(StudioJg, SearchPanelAndPlanSummaryShowCoresJgForTheSameSearch) {
  MainWindow window;
  test::showDefaultSample(window);
  const SearchRun run = test::runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  ASSERT_TRUE(window.model());

  core::JobContext job;
  const auto expected = core::decompose(*window.model()->mesh, run.machine, run.options, job);
  ASSERT_TRUE(expected.ok()) << expected.error().describe();
  EXPECT_NEAR(run.plan->jgAfterMm2, expected->jgAfterMm2, 1e-9 * std::max(1.0, expected->jgAfterMm2));
  EXPECT_NEAR(run.plan->jgBeforeMm2, expected->jgBeforeMm2, 1e-9 * expected->jgBeforeMm2);

  const QString after = QLocale().toString(expected->jgAfterMm2, 'f', 1);
  const auto* best = window.searchPanel()->findChild<QLabel*>(QStringLiteral("bestJg"));
  ASSERT_TRUE(best);
  EXPECT_TRUE(best->text().contains(after)) << best->text().toStdString() << " vs " << after.toStdString();
  bool summaryShown = false;
  for (const QLabel* label : window.planPanel()->findChildren<QLabel*>())
    summaryShown = summaryShown || (label->text().contains(QStringLiteral("J_G")) && label->text().contains(after));
  EXPECT_TRUE(summaryShown) << "the plan summary names J_G " << after.toStdString();
}

TEST(StudioJg, PrintabilityLimitsRoundTripThroughTheSearchPanel) {
  MainWindow window;
  core::SearchOptions options;
  options.minRegionHeightMm = 3.5;
  options.minPlaneGainPercent = 2.5;
  window.searchPanel()->setSearchOptions(options);
  const core::SearchOptions shown = window.searchPanel()->searchOptions();
  EXPECT_DOUBLE_EQ(shown.minRegionHeightMm, 3.5);
  EXPECT_DOUBLE_EQ(shown.minPlaneGainPercent, 2.5);
}

}  // namespace
}  // namespace multidir::ui
