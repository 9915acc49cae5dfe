// The Search panel's "also the finalists" box (SearchOptions::polishFinalists, docs/search.md, "Polishing the
// finalists"): it starts at core's default, means something only while polishing is on, goes into and comes out
// of the panel's options unchanged, reaches the search that Run search starts, and a project keeps it.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QSignalSpy>
#include <QSpinBox>
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

QCheckBox* finalistsBox(const SearchPanel& panel) {
  return panel.findChild<QCheckBox*>(QStringLiteral("polishFinalists"));
}

// Whether the plan's notes say that the search's finalists were polished (core's note, polished_choice.cpp).
bool saysFinalistsWerePolished(const core::Decomposition& plan) {
  const auto& notes = plan.statistics.notes;
  return std::any_of(notes.begin(), notes.end(),
                     [](const std::string& note) { return note.find("finalists of the search") != std::string::npos; });
}

TEST(SearchPanelPolishFinalists, BoxStartsAtCoreDefaultAndSaysWhatItDoes) {
  SearchPanel panel;
  QCheckBox* box = finalistsBox(panel);
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->isChecked(), core::SearchOptions{}.polishFinalists);
  EXPECT_EQ(panel.searchOptions().polishFinalists, core::SearchOptions{}.polishFinalists);
  EXPECT_TRUE(box->isEnabled());
  EXPECT_TRUE(box->toolTip().contains(QStringLiteral("every other number of cuts"))) << box->toolTip().toStdString();
}

TEST(SearchPanelPolishFinalists, TickingTheBoxChangesTheOptionsAndSaysSettingsChanged) {
  SearchPanel panel;
  QCheckBox* box = finalistsBox(panel);
  ASSERT_NE(box, nullptr);
  QSignalSpy changed(&panel, &SearchPanel::settingsChanged);
  for (const bool finalists : {!box->isChecked(), box->isChecked()}) {
    box->setChecked(finalists);
    EXPECT_EQ(panel.searchOptions().polishFinalists, finalists);
  }
  EXPECT_EQ(changed.count(), 2);
}

TEST(SearchPanelPolishFinalists, PolishingOffDisablesTheBoxAndPolishesNoFinalists) {
  SearchPanel panel;
  QCheckBox* box = finalistsBox(panel);
  auto* effort = panel.findChild<QSpinBox*>(QStringLiteral("polishEffort"));
  ASSERT_NE(box, nullptr);
  ASSERT_NE(effort, nullptr);
  box->setChecked(true);
  effort->setValue(0);
  EXPECT_FALSE(box->isEnabled());
  EXPECT_FALSE(panel.searchOptions().polishFinalists);
  effort->setValue(2);
  EXPECT_TRUE(box->isEnabled());
  EXPECT_TRUE(panel.searchOptions().polishFinalists) << "the box kept its tick while polishing was off";
}

TEST(SearchPanelPolishFinalists, SetSearchOptionsShowsTheChoiceAndSearchOptionsReturnsIt) {
  SearchPanel panel;
  QCheckBox* box = finalistsBox(panel);
  ASSERT_NE(box, nullptr);
  for (const bool finalists : {true, false, true}) {
    core::SearchOptions options;
    options.polishFinalists = finalists;
    panel.setSearchOptions(options);
    EXPECT_EQ(box->isChecked(), finalists);
    EXPECT_EQ(panel.searchOptions().polishFinalists, finalists);
  }
}

TEST(SearchPanelPolishFinalists, BoxIsLockedWhileASearchRuns) {
  SearchPanel panel;
  QCheckBox* box = finalistsBox(panel);
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(test::lockedWhilePanelSearches(panel, *box));
}

// Both ways: the tick reaches core (its note on the finalists is in the plan or not), the plan keeps it, and a
// project saved with the choice other than the default reopens with it.
TEST(StudioPolishFinalists, TheBoxReachesTheSearchAndTheProjectKeepsIt) {
  test::resetStudioSettings();
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const bool other = !core::SearchOptions{}.polishFinalists;
  const QString path = dir.filePath(QStringLiteral("finalists.multidir"));
  {
    MainWindow window;
    ASSERT_NO_FATAL_FAILURE(test::openSample(window, QString::fromStdString(core::samples::catalogue().front().id)));
    for (const bool finalists : {!other, other}) {
      window.searchPanel()->setSearchOptions(test::quickSearchOptions());
      QCheckBox* box = finalistsBox(*window.searchPanel());
      ASSERT_NE(box, nullptr);
      box->setChecked(finalists);
      const SearchRun run = test::runSearchAsSet(window);
      ASSERT_TRUE(run.plan);
      EXPECT_EQ(run.options.polishFinalists, finalists);
      EXPECT_EQ(saysFinalistsWerePolished(*run.plan), finalists) << "ticked: " << finalists;
    }
    QString error;
    ASSERT_TRUE(window.projectSession()->saveProjectAs(path, &error)) << error.toStdString();
  }
  MainWindow reopened;
  ASSERT_EQ(finalistsBox(*reopened.searchPanel())->isChecked(), !other);
  ASSERT_NO_FATAL_FAILURE(test::waitProjectOpened(reopened.projectSession(),
                                                  [&] { return reopened.projectSession()->openProject(path); }));
  EXPECT_EQ(finalistsBox(*reopened.searchPanel())->isChecked(), other);
  ASSERT_TRUE(reopened.plan().has_value());
  EXPECT_EQ(reopened.plan()->options.polishFinalists, other) << "the plan's own options";
  test::resetStudioSettings();
}

}  // namespace
}  // namespace multidir::ui
