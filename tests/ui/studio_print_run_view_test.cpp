// The view during a print run: the Hardware panel's current region drives the plan view, so the operator
// sees the regions already on the platform and the one being printed; all regions once the run ends.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>

#include "ui/device/hardware_panel.h"
#include "ui/main_window.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/studio_startup.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

constexpr int kLoadTimeoutMs = 120000;
constexpr int kSearchTimeoutMs = 240000;

TEST(StudioPrintRun, ViewShowsTheRegionsUpToTheOneBeingPrintedThenAllAgain) {
  MainWindow window;
  window.resize(1400, 900);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  QSignalSpy shown(&window, &MainWindow::modelShown);
  startStudio(window, StudioOptions{});
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs)) << "the default sample did not load";

  core::SearchOptions quick;  // a search of a few seconds
  quick.beamWidth = 2;
  quick.candidates.normalSamples = 60;
  quick.candidates.offsetStepMm = 2.0;
  window.searchPanel()->setSearchOptions(quick);
  QSignalSpy finished(&window, &MainWindow::searchFinished);
  ASSERT_TRUE(window.runSearch());
  ASSERT_TRUE(finished.wait(kSearchTimeoutMs)) << "the search did not finish";
  ASSERT_TRUE(window.plan().has_value());
  const int regions = static_cast<int>(window.plan()->plan->regions.size());
  ASSERT_GE(regions, 3);
  ASSERT_EQ(window.viewer()->shownRegions(), regions);

  auto* panel = window.findChild<HardwarePanel*>();
  ASSERT_NE(panel, nullptr);
  ASSERT_EQ(panel->planRegionCount(), regions);
  emit panel->currentRegionChanged(0);
  EXPECT_EQ(window.viewer()->shownRegions(), 1);
  EXPECT_EQ(window.planPanel()->shownRegions(), 1);  // the stepper agrees with the view
  emit panel->currentRegionChanged(1);
  EXPECT_EQ(window.viewer()->shownRegions(), 2);
  EXPECT_EQ(window.planPanel()->shownRegions(), 2);
  emit panel->currentRegionChanged(-1);
  EXPECT_EQ(window.viewer()->shownRegions(), regions);
  EXPECT_EQ(window.planPanel()->shownRegions(), regions);
}

}  // namespace
}  // namespace multidir::ui
