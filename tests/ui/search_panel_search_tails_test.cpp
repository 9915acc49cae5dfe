// The Search panel's "Search again: the tails of the polished plan" box (SearchOptions::searchTails,
// docs/search.md, "Searching the tails again"): it starts at core's default, goes into and comes out of the
// panel's options unchanged, is locked while a search runs, reaches the search that Run search starts, and a
// project keeps it.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <algorithm>
#include <string>

#include "multidir/core/samples/samples.h"
#include "multidir/core/search/search_options.h"
#include "ui/main_window.h"
#include "ui/panels/search_panel.h"
#include "ui/project/project_session.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

QCheckBox* tailsBox(const SearchPanel& panel) { return panel.findChild<QCheckBox*>(QStringLiteral("searchTails")); }

// Whether the plan's notes say that its tails were searched again (core's notes, tail_search.cpp).
bool saysTailsWereSearched(const core::Decomposition& plan) {
  const auto& notes = plan.statistics.notes;
  return std::any_of(notes.begin(), notes.end(),
                     [](const std::string& note) { return note.find("tails searched again") != std::string::npos; });
}

TEST(SearchPanelSearchTails, BoxStartsAtCoreDefaultAndSaysWhatItCosts) {
  SearchPanel panel;
  QCheckBox* box = tailsBox(panel);
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->isChecked(), core::SearchOptions{}.searchTails);
  EXPECT_EQ(panel.searchOptions().searchTails, core::SearchOptions{}.searchTails);
  EXPECT_TRUE(box->toolTip().contains(QStringLiteral("twice the time"))) << box->toolTip().toStdString();
}

TEST(SearchPanelSearchTails, TickingTheBoxChangesTheOptionsAndSaysSettingsChanged) {
  SearchPanel panel;
  QCheckBox* box = tailsBox(panel);
  ASSERT_NE(box, nullptr);
  QSignalSpy changed(&panel, &SearchPanel::settingsChanged);
  for (const bool tails : {!box->isChecked(), box->isChecked()}) {
    box->setChecked(tails);
    EXPECT_EQ(panel.searchOptions().searchTails, tails);
  }
  EXPECT_EQ(changed.count(), 2);
}

TEST(SearchPanelSearchTails, SetSearchOptionsShowsTheChoiceAndSearchOptionsReturnsIt) {
  SearchPanel panel;
  QCheckBox* box = tailsBox(panel);
  ASSERT_NE(box, nullptr);
  for (const bool tails : {true, false, true}) {
    core::SearchOptions options;
    options.searchTails = tails;
    panel.setSearchOptions(options);
    EXPECT_EQ(box->isChecked(), tails);
    EXPECT_EQ(panel.searchOptions().searchTails, tails);
  }
}

TEST(SearchPanelSearchTails, BoxIsLockedWhileASearchRuns) {
  SearchPanel panel;
  QCheckBox* box = tailsBox(panel);
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(test::lockedWhilePanelSearches(panel, *box));
}

// The tick reaches core (its note on the tails is in the plan or not) and a project saved with the other choice
// than the default reopens with it, in the box and in the plan's own options.
TEST(StudioSearchTails, TheBoxReachesTheSearchAndTheProjectKeepsIt) {
  test::resetStudioSettings();
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const bool other = !core::SearchOptions{}.searchTails;
  const QString path = dir.filePath(QStringLiteral("tails.multidir"));
  {
    MainWindow window;
    ASSERT_NO_FATAL_FAILURE(test::openSample(window, QString::fromStdString(core::samples::catalogue().front().id)));
    for (const bool tails : {!other, other}) {
      window.searchPanel()->setSearchOptions(test::quickSearchOptions());
      tailsBox(*window.searchPanel())->setChecked(tails);
      const SearchRun run = test::runSearchAsSet(window);
      ASSERT_TRUE(run.plan);
      ASSERT_FALSE(run.plan->clippingPlanes.empty()) << "a plan without planes has no tails to search";
      EXPECT_EQ(run.options.searchTails, tails);
      EXPECT_EQ(saysTailsWereSearched(*run.plan), tails) << "ticked: " << tails;
    }
    QString error;
    ASSERT_TRUE(window.projectSession()->saveProjectAs(path, &error)) << error.toStdString();
  }
  MainWindow reopened;
  ASSERT_NO_FATAL_FAILURE(test::waitProjectOpened(reopened.projectSession(),
                                                  [&] { return reopened.projectSession()->openProject(path); }));
  EXPECT_EQ(tailsBox(*reopened.searchPanel())->isChecked(), other);
  ASSERT_TRUE(reopened.plan().has_value());
  EXPECT_EQ(reopened.plan()->options.searchTails, other) << "the plan's own options";
  test::resetStudioSettings();
}

}  // namespace
}  // namespace multidir::ui
