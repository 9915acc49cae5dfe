// The Search panel's "Polish the planes" box (SearchOptions::polish and polishEffort, docs/search.md,
// "Polishing"): it starts at core's default, 0 turns polishing off, and options go in and come out unchanged.
#include <gtest/gtest.h>

#include <QSpinBox>

#include "multidir/core/search/search_options.h"
#include "ui/panels/search_panel.h"

namespace multidir::ui {
namespace {

QSpinBox* polishBox(const SearchPanel& panel) { return panel.findChild<QSpinBox*>(QStringLiteral("polishEffort")); }

TEST(SearchPanelPolish, BoxStartsAtCoreDefaultAndPolishesByDefault) {
  SearchPanel panel;
  QSpinBox* box = polishBox(panel);
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->value(), core::SearchOptions{}.polishEffort);
  EXPECT_TRUE(panel.searchOptions().polish);
  EXPECT_EQ(panel.searchOptions().polishEffort, core::SearchOptions{}.polishEffort);
  EXPECT_EQ(box->minimum(), 0);
  EXPECT_EQ(box->maximum(), 6);
}

TEST(SearchPanelPolish, ZeroTurnsPolishingOff) {
  SearchPanel panel;
  QSpinBox* box = polishBox(panel);
  ASSERT_NE(box, nullptr);
  box->setValue(0);
  EXPECT_FALSE(panel.searchOptions().polish);
  EXPECT_EQ(box->text(), QStringLiteral("off"));
}

TEST(SearchPanelPolish, SetSearchOptionsShowsPolishingAndSearchOptionsReturnsIt) {
  SearchPanel panel;
  QSpinBox* box = polishBox(panel);
  ASSERT_NE(box, nullptr);
  core::SearchOptions off;
  off.polish = false;
  panel.setSearchOptions(off);
  EXPECT_EQ(box->value(), 0);
  EXPECT_FALSE(panel.searchOptions().polish);
  core::SearchOptions fine;
  fine.polishEffort = 4;
  panel.setSearchOptions(fine);
  EXPECT_EQ(box->value(), 4);
  EXPECT_TRUE(panel.searchOptions().polish);
  EXPECT_EQ(panel.searchOptions().polishEffort, 4);
}

}  // namespace
}  // namespace multidir::ui
