// A plan that comes without its supports is never shown or exported without them (issue 11, item 3): a
// reopened project and a cancelled search's plan get their supports regrown, and File > Export plan waits
// for them instead of writing regions without supports.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "multidir/core/plan/plan_file.h"
#include "ui/main_window.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/project/project_session.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

void show(MainWindow& window) {
  window.resize(1000, 700);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
}

bool supportsCheckboxEnabled(const MainWindow& window) {
  return window.planPanel()->findChild<QCheckBox*>(QStringLiteral("showSupports"))->isEnabled();
}

class StudioSupportsRegrowth : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    test::resetStudioSettings();
  }
  void TearDown() override { test::resetStudioSettings(); }

  // The snowman searched (J_G > 0 left, so the plan needs supports) and saved as a project; its path.
  QString savedSnowmanProject() {
    MainWindow window;
    show(window);
    test::openSample(window, QStringLiteral("snowman"));
    const SearchRun run = test::runQuickSearch(window);
    EXPECT_TRUE(run.plan && run.plan->jgAfterMm2 > 0.0) << "the plan should need supports";
    EXPECT_TRUE(run.supports);
    const QString path = m_dir.filePath(QStringLiteral("snowman.multidir"));
    EXPECT_TRUE(window.projectSession()->saveProjectAs(path));
    return path;
  }

  QTemporaryDir m_dir;
};

TEST_F(StudioSupportsRegrowth, ReopenedProjectShowsItsPlanWithSupports) {
  const QString project = savedSnowmanProject();
  MainWindow window;
  show(window);
  ASSERT_NO_FATAL_FAILURE(test::waitProjectOpened(window.projectSession(), [&] {
    return window.projectSession()->openProject(project);
  }));
  ASSERT_NO_FATAL_FAILURE(test::waitForRegrownSupports(window));
  ASSERT_TRUE(window.plan().has_value());
  ASSERT_TRUE(window.plan()->supports) << window.plan()->supportsNote.toStdString();
  EXPECT_EQ(window.plan()->supports->size(), window.plan()->plan->regions.size());
  EXPECT_TRUE(supportsCheckboxEnabled(window));
  EXPECT_GT(window.viewer()->supportSetsShown(), 0);
  EXPECT_FALSE(window.projectSession()->isModified()) << "regrown supports are no change to the project";
}

TEST_F(StudioSupportsRegrowth, ExportOfAReopenedProjectWritesTheSupports) {
  const QString project = savedSnowmanProject();
  MainWindow window;
  show(window);
  ASSERT_NO_FATAL_FAILURE(test::waitProjectOpened(window.projectSession(), [&] {
    return window.projectSession()->openProject(project);
  }));
  const QString folder = m_dir.filePath(QStringLiteral("plan"));
  QString error;
  if (window.isGrowingSupports()) {
    // Not yet: export says so instead of writing regions without supports.
    EXPECT_FALSE(window.exportPlan(folder, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("supports"))) << error.toStdString();
  }
  ASSERT_NO_FATAL_FAILURE(test::waitForRegrownSupports(window));
  QString warning;
  ASSERT_TRUE(window.exportPlan(folder, &error, &warning)) << error.toStdString();
  EXPECT_TRUE(warning.isEmpty()) << warning.toStdString();
  const core::Result<core::LoadedPlan> loaded = core::loadPlan(folder.toStdString());
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->supports.size(), loaded->decomposition.regions.size());
}

TEST_F(StudioSupportsRegrowth, CancelledSearchsPlanGetsItsSupports) {
  MainWindow window;
  show(window);
  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("snowman")));
  window.searchPanel()->setSearchOptions(test::longSearchOptions());
  QSignalSpy finished(&window, &MainWindow::searchFinished);
  QSignalSpy failed(&window, &MainWindow::searchFailed);
  ASSERT_TRUE(window.runSearch());
  QTest::qWait(1000);  // under way: it has a best plan to deliver
  ASSERT_TRUE(window.isSearching()) << "the search ended before it could be cancelled";
  window.cancelSearch();
  ASSERT_TRUE(test::waitUntil([&] { return !finished.isEmpty() || !failed.isEmpty(); }, test::kSearchTimeoutMs));
  ASSERT_FALSE(finished.isEmpty()) << failed.front().front().toString().toStdString();
  const SearchRun run = finished.front().front().value<SearchRun>();
  ASSERT_TRUE(run.plan && run.plan->cancelled);
  ASSERT_GT(run.plan->jgAfterMm2, 0.0);
  EXPECT_FALSE(run.supports) << "the search itself grows none once cancelled";
  ASSERT_NO_FATAL_FAILURE(test::waitForRegrownSupports(window));
  ASSERT_TRUE(window.plan() && window.plan()->supports) << window.plan()->supportsNote.toStdString();
  EXPECT_EQ(window.plan()->supports->size(), window.plan()->plan->regions.size());
  EXPECT_TRUE(supportsCheckboxEnabled(window));
}

}  // namespace
}  // namespace multidir::ui
