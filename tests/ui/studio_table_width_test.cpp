// The pose and estimate tables fit their docks at the window's default size: every column shown whole, no
// horizontal scrolling.
#include <gtest/gtest.h>

#include <QDockWidget>
#include <QHeaderView>
#include <QScrollBar>
#include <QTableWidget>
#include <QTest>

#include "multidir/core/search/pose_search.h"
#include "multidir/slicing/slice_job.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/pose_search_box.h"
#include "ui/panels/slice_panel.h"
#include "ui/project/window_state.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

void showAtDefaultSize(MainWindow& window) {
  test::resetStudioSettings();
  window.resize(kPreferredWindowSize);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
}

// A pose search's result with numbers as wide as real ones get (thousands of mm², an oblique up).
core::PoseSearchResult threePoses() {
  core::PoseSearchResult result;
  for (int i = 0; i < 3; ++i) {
    core::PoseTrial trial;
    trial.pose.up = core::Vec3(0.6, -0.35, 0.72).normalized();
    trial.pose.source = i == 0 ? core::PoseSource::Given : core::PoseSource::Resting;
    trial.pose.contactAreaMm2 = 12345.6;
    trial.pose.stabilityMarginMm = 23.45;
    trial.pose.riskyAreaMm2 = 8535.5;
    trial.searched = i < 2;
    trial.jgAfterMm2 = 1402.7;
    trial.regions = 12;
    result.trials.push_back(trial);
  }
  return result;
}

void expectFits(QTableWidget* table) {
  QCoreApplication::processEvents();
  EXPECT_EQ(table->horizontalScrollBar()->maximum(), 0)
      << "table " << table->objectName().toStdString() << " is " << table->width() << " px wide, its columns "
      << table->horizontalHeader()->length() << " px";
}

TEST(StudioTableWidth, PoseTableFitsTheMachineDockAtTheDefaultWindowSize) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showAtDefaultSize(window));
  window.findChild<QDockWidget*>(QStringLiteral("machineDock"))->raise();
  PoseSearchBox* box = window.machinePanel()->poseBox();
  box->showResult(threePoses(), false);
  expectFits(box->table());
}

TEST(StudioTableWidth, EstimatesTableFitsThePlanDockAtTheDefaultWindowSize) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showAtDefaultSize(window));
  auto* panel = window.findChild<SlicePanel*>();
  ASSERT_NE(panel, nullptr);
  window.findChild<QDockWidget*>(QStringLiteral("planDock"))->raise();
  slicing::SlicedJob job;
  for (int i = 1; i <= 3; ++i) {
    slicing::SlicedStep step;
    step.index = i;
    step.estimate = {36000.0 + 3599.0 * i, 123456.0, 297.0, 368.3};
    job.steps.push_back(step);
    job.total += step.estimate;
  }
  job.fixedDirection = slicing::Estimate{99999.0, 234567.0, 564.0, 700.0};
  panel->showResult(job, 10);
  expectFits(panel->estimatesTable());
}

// The step column may be elided: each of its cells says its whole text in its tooltip, unless it has one of its
// own (the fixed-direction row explains the comparison).
TEST(StudioTableWidth, ElidedStepNamesAreWholeInTheirTooltips) {
  SlicePanel panel;
  slicing::SlicedJob job;
  slicing::SlicedStep step;
  step.index = 1;
  step.gcodeFile = "step-01.gcode";
  step.estimate = {3600.0, 1000.0, 2.4, 3.0};
  job.steps.push_back(step);
  job.total = step.estimate;
  job.fixedDirection = step.estimate;
  panel.showResult(job, 1);
  QTableWidget* table = panel.estimatesTable();
  ASSERT_EQ(table->rowCount(), 3);
  EXPECT_EQ(table->item(0, 0)->toolTip(), table->item(0, 0)->text());
  EXPECT_NE(table->item(2, 0)->toolTip(), table->item(2, 0)->text());
  EXPECT_FALSE(table->item(2, 0)->toolTip().isEmpty());
}

}  // namespace
}  // namespace multidir::ui
