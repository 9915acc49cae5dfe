// The Search panel's "Scales" box (SearchOptions::volumeScales, docs/search.md): it starts at core's default,
// goes into and comes out of the panel's options unchanged, is editable for the beam scheme only, and a
// project saved with one scale reopens with one.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

#include "multidir/core/samples/samples.h"
#include "multidir/core/search/search_options.h"
#include "ui/main_window.h"
#include "ui/panels/search_panel.h"
#include "ui/project/project_session.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

QSpinBox* scalesBox(const SearchPanel& panel) { return panel.findChild<QSpinBox*>(QStringLiteral("volumeScales")); }

// Chooses the scheme in the panel's combo box as a user would.
void chooseScheme(const SearchPanel& panel, core::SearchScheme scheme) {
  auto* combo = panel.findChild<QComboBox*>(QStringLiteral("scheme"));
  ASSERT_NE(combo, nullptr);
  const int index = combo->findData(static_cast<int>(scheme));
  ASSERT_GE(index, 0);
  combo->setCurrentIndex(index);
}

TEST(SearchPanelScales, BoxStartsAtCoreDefaultWithinOneToFourAndSaysWhatItDoes) {
  SearchPanel panel;
  QSpinBox* box = scalesBox(panel);
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->value(), core::SearchOptions{}.volumeScales);
  EXPECT_EQ(panel.searchOptions().volumeScales, core::SearchOptions{}.volumeScales);
  EXPECT_EQ(box->minimum(), 1);
  EXPECT_EQ(box->maximum(), 4);
  EXPECT_TRUE(box->toolTip().contains(QStringLiteral("side by side"))) << box->toolTip().toStdString();
}

TEST(SearchPanelScales, SetSearchOptionsShowsTheScalesAndSearchOptionsReturnsThem) {
  SearchPanel panel;
  QSpinBox* box = scalesBox(panel);
  ASSERT_NE(box, nullptr);
  for (const int scales : {1, 3, 4, 2}) {
    core::SearchOptions options;
    options.volumeScales = scales;
    panel.setSearchOptions(options);
    EXPECT_EQ(box->value(), scales);
    EXPECT_EQ(panel.searchOptions().volumeScales, scales);
  }
}

TEST(SearchPanelScales, EditingTheBoxChangesTheOptionsAndSaysSettingsChanged) {
  SearchPanel panel;
  QSpinBox* box = scalesBox(panel);
  ASSERT_NE(box, nullptr);
  QSignalSpy changed(&panel, &SearchPanel::settingsChanged);
  box->setValue(box->value() == 1 ? 3 : 1);
  EXPECT_EQ(changed.count(), 1);
  EXPECT_EQ(panel.searchOptions().volumeScales, box->value());
}

TEST(SearchPanelScales, ScalesAndBeamWidthAreEditableForTheBeamSchemeOnlyAndKeepTheirValues) {
  SearchPanel panel;
  QSpinBox* box = scalesBox(panel);
  auto* beamWidth = panel.findChild<QSpinBox*>(QStringLiteral("beamWidth"));
  ASSERT_NE(box, nullptr);
  ASSERT_NE(beamWidth, nullptr);
  core::SearchOptions options;
  options.volumeScales = 3;
  panel.setSearchOptions(options);
  EXPECT_TRUE(box->isEnabled());
  EXPECT_TRUE(beamWidth->isEnabled());
  for (const core::SearchScheme greedy : {core::SearchScheme::Greedy, core::SearchScheme::ConstrainedGreedy}) {
    ASSERT_NO_FATAL_FAILURE(chooseScheme(panel, greedy));
    EXPECT_FALSE(box->isEnabled()) << core::schemeName(greedy);
    EXPECT_FALSE(beamWidth->isEnabled()) << core::schemeName(greedy);
    EXPECT_EQ(panel.searchOptions().volumeScales, 3) << "a greedy search's options still carry the scales";
  }
  ASSERT_NO_FATAL_FAILURE(chooseScheme(panel, core::SearchScheme::Beam));
  EXPECT_TRUE(box->isEnabled());
  EXPECT_TRUE(beamWidth->isEnabled());
}

TEST(SearchPanelScales, ScalesBoxIsLockedWhileASearchRunsLikeItsNeighbours) {
  SearchPanel panel;
  QSpinBox* box = scalesBox(panel);
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(test::lockedWhilePanelSearches(panel, *box));
}

TEST(StudioProjectScales, ProjectSavedWithOneScaleReopensWithOne) {
  test::resetStudioSettings();
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  ASSERT_NE(core::SearchOptions{}.volumeScales, 1) << "one scale must differ from the default to prove anything";
  ASSERT_EQ(test::quickSearchOptions().volumeScales, 1);
  const QString path = dir.filePath(QStringLiteral("scales.multidir"));
  {
    MainWindow window;
    ASSERT_NO_FATAL_FAILURE(test::openSample(window, QString::fromStdString(core::samples::catalogue().front().id)));
    const SearchRun run = test::runQuickSearch(window);  // with one scale
    ASSERT_TRUE(run.plan);
    ASSERT_EQ(run.options.volumeScales, 1);
    QString error;
    ASSERT_TRUE(window.projectSession()->saveProjectAs(path, &error)) << error.toStdString();
  }
  MainWindow other;
  ASSERT_EQ(scalesBox(*other.searchPanel())->value(), core::SearchOptions{}.volumeScales);
  ASSERT_NO_FATAL_FAILURE(
      test::waitProjectOpened(other.projectSession(), [&] { return other.projectSession()->openProject(path); }));
  EXPECT_EQ(scalesBox(*other.searchPanel())->value(), 1);
  EXPECT_EQ(other.searchPanel()->searchOptions().volumeScales, 1);
  ASSERT_TRUE(other.plan().has_value());
  EXPECT_EQ(other.plan()->options.volumeScales, 1) << "the plan's own options";
  test::resetStudioSettings();
}

}  // namespace
}  // namespace multidir::ui
