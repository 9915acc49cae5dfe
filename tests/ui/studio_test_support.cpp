#include "ui/studio_test_support.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>

#include "ui/main_window.h"
#include "ui/panels/search_panel.h"
#include "ui/studio_startup.h"

namespace multidir::test {

void showDefaultSample(ui::MainWindow& window, const QSize& size) {
  window.resize(size);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  QSignalSpy shown(&window, &ui::MainWindow::modelShown);
  ui::startStudio(window, ui::StudioOptions{});
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs)) << "the default sample did not load";
}

void openSample(ui::MainWindow& window, const QString& id) {
  QSignalSpy shown(&window, &ui::MainWindow::modelShown);
  window.openSample(id);
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs)) << "did not build " << id.toStdString();
}

core::SearchOptions quickSearchOptions() {
  core::SearchOptions options;
  options.beamWidth = 2;
  options.candidates.normalSamples = 60;
  options.candidates.offsetStepMm = 2.0;
  options.minVolumeDivisor = 10.0;  // a few large regions keep the scenes the tests look at readable
  return options;
}

ui::SearchRun runQuickSearch(ui::MainWindow& window) {
  window.searchPanel()->setSearchOptions(quickSearchOptions());
  QSignalSpy finished(&window, &ui::MainWindow::searchFinished);
  const bool started = window.runSearch();
  EXPECT_TRUE(started) << "the search did not start";
  if (!started) return {};
  EXPECT_TRUE(window.isSearching());
  EXPECT_TRUE(finished.wait(kSearchTimeoutMs)) << "the search did not finish";
  if (finished.isEmpty()) return {};
  return finished.front().front().value<ui::SearchRun>();
}

void openPlanFolder(ui::MainWindow& window, const QString& folder) {
  QSignalSpy planShown(&window, &ui::MainWindow::planShown);
  QString error;
  ASSERT_TRUE(window.openPlan(folder, &error)) << error.toStdString();
  // A plan without its model is shown at once; one with a model when the model has loaded.
  if (planShown.isEmpty()) {
    ASSERT_TRUE(planShown.wait(kLoadTimeoutMs)) << "the plan in " << folder.toStdString() << " was not shown";
  }
}

}  // namespace multidir::test
