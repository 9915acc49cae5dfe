// The Best pose box: its status names the stage the pose search is in, and the table's row for a pose the
// search ruled out shows that it has no plan, only the area every plan of it keeps.
#include <gtest/gtest.h>

#include <QTableWidget>

#include "multidir/core/search/pose_search.h"
#include "ui/panels/pose_search_box.h"

namespace multidir::ui {
namespace {

core::PoseSearchResult givenUpAndOneRuledOut() {
  core::PoseSearchResult result;
  core::PoseTrial given;
  given.pose.up = core::Vec3::UnitY();
  given.pose.source = core::PoseSource::Given;
  given.pose.riskyAreaMm2 = 1507.2;
  given.searched = true;
  given.jgAfterMm2 = 11.71;
  given.regions = 4;
  core::PoseTrial ruledOut;
  ruledOut.pose.up = core::Vec3::UnitX();
  ruledOut.pose.source = core::PoseSource::Resting;
  ruledOut.pose.contactAreaMm2 = 120.0;
  ruledOut.pose.stabilityMarginMm = 3.0;
  ruledOut.pose.riskyAreaMm2 = 2100.0;
  ruledOut.ruledOut = true;
  ruledOut.unavoidableMm2 = 731.5;
  result.trials = {given, ruledOut};
  return result;
}

}  // namespace

TEST(PoseTable, ARuledOutPoseShowsTheAreaEveryPlanOfItKeepsAndNoRegions) {
  PoseSearchBox box;
  box.showResult(givenUpAndOneRuledOut(), false);
  QTableWidget* table = box.table();
  ASSERT_EQ(table->rowCount(), 2);
  EXPECT_EQ(table->item(1, PoseSearchBox::SearchColumn)->text(), PoseSearchBox::tr("ruled out"));
  EXPECT_EQ(table->item(1, PoseSearchBox::JgColumn)->text(),
            QStringLiteral("≥ ") + QLocale().toString(731.5, 'f', 1));
  EXPECT_EQ(table->item(1, PoseSearchBox::RegionsColumn)->text(), QStringLiteral("-"));
  EXPECT_TRUE(table->item(1, PoseSearchBox::JgColumn)->toolTip().contains(PoseSearchBox::tr("could not win")));
  EXPECT_EQ(table->item(0, PoseSearchBox::SearchColumn)->text(), PoseSearchBox::tr("full search"));
  EXPECT_EQ(table->item(0, PoseSearchBox::JgColumn)->text(), QLocale().toString(11.71, 'f', 1));
}

TEST(PoseSearchBox, StatusNamesEachStageOfTheSearchInTheOrderItRuns) {
  // The given up is searched in full first (its J_G rules the other poses out), then the others are scored,
  // then the best of them searched in full.
  PoseSearchBox box;
  box.setRunnable(true, QString());
  box.searchStarted();
  EXPECT_EQ(box.statusText(), PoseSearchBox::tr("Full search of the given up..."));
  box.showProgress(0.2, PoseSearchJob::Phase::GivenUpSearch);
  EXPECT_EQ(box.statusText(), PoseSearchBox::tr("Full search of the given up..."));
  box.showProgress(0.4, PoseSearchJob::Phase::CheapScores);
  EXPECT_EQ(box.statusText(), PoseSearchBox::tr("Scoring the poses that could beat it with quick plans..."));
  box.showProgress(0.6, PoseSearchJob::Phase::FullSearches);
  EXPECT_EQ(box.statusText(), PoseSearchBox::tr("Full searches of the best poses..."));
}

}  // namespace multidir::ui
