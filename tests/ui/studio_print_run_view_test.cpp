// The view during a print run: the Hardware panel's current region drives the plan view, so the operator
// sees the regions already on the platform and the one being printed; all regions once the run ends.
#include <gtest/gtest.h>

#include "ui/device/hardware_panel.h"
#include "ui/main_window.h"
#include "ui/panels/plan_panel.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

TEST(StudioPrintRun, ViewShowsTheRegionsUpToTheOneBeingPrintedThenAllAgain) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
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
