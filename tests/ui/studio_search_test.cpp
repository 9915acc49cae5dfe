// Searching from the studio: the search runs off the GUI thread, the plan is shown as coloured regions
// with a table, plans and machine profiles round-trip through files, and cancelling keeps the best plan.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QElapsedTimer>
#include <QImage>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QTimer>

#include "multidir/core/plan/plan_file.h"
#include "support/test_models.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/picture_census.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

using test::runQuickSearch;
using test::showDefaultSample;

TEST(StudioSearch, PlanOfTheSampleIsShownAsColouredRegionsWithATable) {
  MainWindow window;
  showDefaultSample(window);
  const SearchRun run = runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  EXPECT_FALSE(run.plan->cancelled);
  const int regions = static_cast<int>(run.plan->regions.size());
  ASSERT_GE(regions, 3) << "the snowman should need at least three regions";
  EXPECT_LT(run.plan->jgAfterMm2, run.plan->jgBeforeMm2);

  // One table row per region, in printing order, with its volume.
  QTableWidget* table = window.planPanel()->regionTable();
  ASSERT_EQ(table->rowCount(), regions);
  EXPECT_EQ(table->item(0, 0)->text(), QStringLiteral("1"));
  EXPECT_EQ(table->item(regions - 1, 0)->text(), QString::number(regions));
  EXPECT_EQ(table->item(1, 1)->text(), QLocale().toString(run.plan->regions[1].volumeMm3, 'f', 1));
  EXPECT_TRUE(window.viewer()->hasPlan());
  EXPECT_FALSE(window.searchPanel()->noticeText().isEmpty());
  EXPECT_GE(window.searchPanel()->chartPointCount(), 2);

  // The view shows the regions in distinct palette colours.
  window.planPanel()->setClippingPlanesShown(false);
  const QImage picture = window.viewer()->grabFramebuffer();
  // Some regions are small (a nose, a brim): 0.02 % of the frame is still some 200 pixels.
  EXPECT_GE(test::regionColoursSeen(picture, regions, 0.0002), 3);
}

TEST(StudioSearch, SequenceStepperShowsTheFirstRegionsOnly) {
  MainWindow window;
  showDefaultSample(window);
  const SearchRun run = runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  const int regions = static_cast<int>(run.plan->regions.size());
  ASSERT_GE(regions, 2);
  window.planPanel()->setShownRegions(1);
  EXPECT_EQ(window.viewer()->shownRegions(), 1);
  const QImage first = window.viewer()->grabFramebuffer();
  EXPECT_EQ(test::regionColoursSeen(first, regions, 0.001), 1);

  // Turning with the machine puts the last shown region's printing direction up on screen.
  window.planPanel()->setShownRegions(regions);
  window.planPanel()->findChild<QCheckBox*>(QStringLiteral("turnWithMachine"))->setChecked(true);
  window.viewer()->grabFramebuffer();
  EXPECT_TRUE(window.viewer()->viewUp().isApprox(run.plan->regions.back().printingDirection.normalized(), 1e-9));
}

TEST(StudioSearch, ExportedPlanOpensAgainWithTheSameRegions) {
  MainWindow window;
  showDefaultSample(window);
  const SearchRun run = runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  const QString folder = QString::fromStdString(test::scratchDirectory("StudioPlanRoundTrip")) + QStringLiteral("/plan");
  QString error;
  ASSERT_TRUE(window.exportPlan(folder, &error)) << error.toStdString();
  EXPECT_TRUE(QFileInfo::exists(folder + QStringLiteral("/plan.json")));

  MainWindow other;
  other.resize(1000, 700);
  other.show();
  ASSERT_NO_FATAL_FAILURE(test::openPlanFolder(other, folder));
  ASSERT_TRUE(other.plan().has_value());
  EXPECT_EQ(other.plan()->plan->regions.size(), run.plan->regions.size());
  EXPECT_EQ(other.planPanel()->regionTable()->rowCount(), static_cast<int>(run.plan->regions.size()));
  EXPECT_TRUE(other.viewer()->hasPlan());
}

TEST(StudioSearch, CancelledSearchKeepsTheGuiResponsiveAndDeliversTheBestPlanSoFar) {
  MainWindow window;
  showDefaultSample(window);
  // A 4-DOF axis search over many axes with full settings runs far longer than the test waits.
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  machine.rotationAxis = core::Vec3::UnitX();
  window.machinePanel()->setMachineSpec(machine);
  window.searchPanel()->setAxisSearchCount(90);
  core::SearchOptions options;
  options.candidates.offsetStepMm = 0.5;
  window.searchPanel()->setSearchOptions(options);

  QSignalSpy finished(&window, &MainWindow::searchFinished);
  ASSERT_TRUE(window.runSearch());
  int ticks = 0;
  QTimer timer;
  QObject::connect(&timer, &QTimer::timeout, [&ticks] { ++ticks; });
  timer.start(20);
  QTest::qWait(1500);
  EXPECT_TRUE(window.isSearching()) << "the search ended before it could be cancelled";
  // The GUI thread kept running its event loop while the search ran.
  EXPECT_GE(ticks, 10);

  window.cancelSearch();
  ASSERT_TRUE(finished.wait(test::kSearchTimeoutMs));
  const SearchRun run = finished.front().front().value<SearchRun>();
  ASSERT_TRUE(run.plan);
  EXPECT_TRUE(run.plan->cancelled);
  EXPECT_FALSE(run.plan->regions.empty());
  EXPECT_FALSE(window.isSearching());
  EXPECT_TRUE(window.searchPanel()->noticeText().contains(QStringLiteral("Cancelled")))
      << window.searchPanel()->noticeText().toStdString();
}

TEST(StudioMachine, InvalidRotationAxisIsShownAndBlocksTheSearch) {
  MainWindow window;
  showDefaultSample(window);
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  machine.rotationAxis = core::Vec3::UnitZ();  // along up: not in the platform plane
  window.machinePanel()->setMachineSpec(machine);
  EXPECT_FALSE(window.machinePanel()->errorText().isEmpty());
  EXPECT_TRUE(window.machinePanel()->errorText().contains(QStringLiteral("rotation axis")))
      << window.machinePanel()->errorText().toStdString();
  EXPECT_FALSE(window.searchPanel()->findChild<QPushButton*>(QStringLiteral("runSearch"))->isEnabled());
  EXPECT_FALSE(window.runSearch());

  window.machinePanel()->findChild<QLineEdit*>(QStringLiteral("rotationAxis"))->setText(QStringLiteral("0,1,0"));
  EXPECT_TRUE(window.machinePanel()->errorText().isEmpty());
  EXPECT_TRUE(window.searchPanel()->findChild<QPushButton*>(QStringLiteral("runSearch"))->isEnabled());
  EXPECT_TRUE(window.viewer()->rotationAxisShown());
}

TEST(StudioMachine, ProfileSavedFromThePanelLoadsBack) {
  MainWindow window;
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  machine.rotationAxis = core::Vec3::UnitY();
  machine.minAngleDegrees = -45;
  machine.maxAngleDegrees = 30;
  machine.angleStepDegrees = 1.8;
  machine.platformRadiusMm = 40;
  window.machinePanel()->setMachineSpec(machine);
  const QString path =
      QString::fromStdString(test::scratchDirectory("StudioMachineProfile")) + QStringLiteral("/rotary.json");
  QString error;
  ASSERT_TRUE(window.saveMachineProfile(path, &error)) << error.toStdString();

  MainWindow other;
  ASSERT_TRUE(other.loadMachineProfile(path, &error)) << error.toStdString();
  const core::MachineSpec loaded = other.machinePanel()->machineSpec(other.upDirection());
  EXPECT_EQ(loaded.kind, core::MachineKind::RotaryPlatform);
  EXPECT_TRUE(loaded.rotationAxis.isApprox(core::Vec3::UnitY()));
  EXPECT_DOUBLE_EQ(loaded.minAngleDegrees, -45);
  EXPECT_DOUBLE_EQ(loaded.maxAngleDegrees, 30);
  EXPECT_DOUBLE_EQ(loaded.angleStepDegrees, 1.8);
  EXPECT_DOUBLE_EQ(loaded.platformRadiusMm, 40);
}

}  // namespace
}  // namespace multidir::ui
