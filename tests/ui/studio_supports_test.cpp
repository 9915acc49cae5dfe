// Supports in the studio: a search whose plan leaves risky area grows supports off the GUI thread; the view
// draws them in the support colour with their regions, the Plan panel lists their volumes and can hide them,
// and exported plans carry them.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QFileInfo>
#include <QImage>
#include <QLocale>
#include <QSignalSpy>
#include <QTableWidget>

#include "multidir/core/plan/plan_file.h"
#include "multidir/core/samples/samples.h"
#include "support/test_models.h"
#include "ui/jobs/search_job.h"
#include "ui/main_window.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/picture_census.h"
#include "ui/common/region_palette.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// The quick search leaves the default sample's (the snowman's) plan with risky area under its bottom
// (J_G > 0), so it needs supports.
using test::runQuickSearch;
using test::showDefaultSample;

int nonEmptySets(const std::vector<core::SupportSet>& sets, int firstCount) {
  int count = 0;
  for (int i = 0; i < firstCount && i < static_cast<int>(sets.size()); ++i) count += sets[static_cast<std::size_t>(i)].empty() ? 0 : 1;
  return count;
}

TEST(StudioSupports, SearchJobGrowsSupportsAfterThePlanAsItsLastPhase) {
  const core::Result<core::TriangleMesh> snowman = core::samples::makeSample("snowman");
  ASSERT_TRUE(snowman.ok());
  auto model = std::make_shared<const core::TriangleMesh>(snowman.value());
  SearchJob job;
  QSignalSpy phases(&job, &SearchJob::fractionChanged);
  QSignalSpy finished(&job, &SearchJob::finished);
  core::MachineSpec machine;
  machine.up = core::samples::sampleUp();
  ASSERT_TRUE(job.start(model, machine, test::quickSearchOptions()));
  ASSERT_TRUE(finished.wait(test::kSearchTimeoutMs));
  const SearchRun run = finished.front().front().value<SearchRun>();
  ASSERT_TRUE(run.plan);
  ASSERT_GT(run.plan->jgAfterMm2, 0.0);
  ASSERT_TRUE(run.supports) << run.supportsNote.toStdString();
  EXPECT_TRUE(run.supportsNote.isEmpty());
  ASSERT_EQ(run.supports->size(), run.plan->regions.size());
  EXPECT_GT(nonEmptySets(*run.supports, static_cast<int>(run.supports->size())), 0);
  ASSERT_FALSE(phases.isEmpty());
  EXPECT_EQ(phases.back().at(1).toString(), QStringLiteral("growing supports"));
  EXPECT_DOUBLE_EQ(phases.back().at(0).toDouble(), 1.0);
}

TEST(StudioSupports, SearchLeavingRiskyAreaShowsSupportsThatTheCheckboxHides) {
  MainWindow window;
  showDefaultSample(window);
  const SearchRun run = runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  ASSERT_GT(run.plan->jgAfterMm2, 0.0);
  ASSERT_TRUE(run.supports) << run.supportsNote.toStdString();
  ASSERT_EQ(run.supports->size(), run.plan->regions.size());
  MeshViewerWidget* viewer = window.viewer();
  EXPECT_GT(viewer->supportSetsShown(), 0);

  window.planPanel()->setClippingPlanesShown(false);
  const double shown = test::colourFraction(viewer->grabFramebuffer(), supportColor());
  EXPECT_GT(shown, 0.001) << "too few pixels in the support colour";

  auto* box = window.planPanel()->findChild<QCheckBox*>(QStringLiteral("showSupports"));
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->isEnabled());
  box->setChecked(false);
  EXPECT_EQ(viewer->supportSetsShown(), 0);
  const double hidden = test::colourFraction(viewer->grabFramebuffer(), supportColor());
  EXPECT_LT(hidden, 0.1 * shown);
}

TEST(StudioSupports, RegionTableListsEachRegionsSupportVolume) {
  MainWindow window;
  showDefaultSample(window);
  const SearchRun run = runQuickSearch(window);
  ASSERT_TRUE(run.plan && run.supports);
  QTableWidget* table = window.planPanel()->regionTable();
  ASSERT_GT(table->columnCount(), PlanPanel::kSupportVolumeColumn);
  EXPECT_EQ(table->horizontalHeaderItem(PlanPanel::kSupportVolumeColumn)->text(), QStringLiteral("Supports (mm³)"));
  ASSERT_EQ(table->rowCount(), static_cast<int>(run.supports->size()));
  for (int i = 0; i < table->rowCount(); ++i) {
    EXPECT_EQ(table->item(i, PlanPanel::kSupportVolumeColumn)->text(),
              QLocale().toString((*run.supports)[static_cast<std::size_t>(i)].volumeMm3, 'f', 1))
        << "region " << i + 1;
  }
}

TEST(StudioSupports, StepperShowsTheSupportsOfTheRegionsShownOnly) {
  MainWindow window;
  showDefaultSample(window);
  const SearchRun run = runQuickSearch(window);
  ASSERT_TRUE(run.plan && run.supports);
  const int regions = static_cast<int>(run.plan->regions.size());
  for (int shown = 1; shown <= regions; ++shown) {
    window.planPanel()->setShownRegions(shown);
    EXPECT_EQ(window.viewer()->supportSetsShown(), nonEmptySets(*run.supports, shown)) << shown << " regions shown";
  }
}

TEST(StudioSupports, ExportedPlanCarriesTheSupportsAndShowsThemWhenOpened) {
  MainWindow window;
  showDefaultSample(window);
  const SearchRun run = runQuickSearch(window);
  ASSERT_TRUE(run.plan && run.supports);
  const QString folder = QString::fromStdString(test::scratchDirectory("StudioSupportsExport")) + QStringLiteral("/plan");
  QString error;
  ASSERT_TRUE(window.exportPlan(folder, &error)) << error.toStdString();
  EXPECT_TRUE(QFileInfo::exists(folder + QStringLiteral("/region-01-supports.stl")) ||
              nonEmptySets(*run.supports, 1) == 0);
  const core::Result<core::LoadedPlan> loaded = core::loadPlan(folder.toStdString());
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  ASSERT_EQ(loaded->supports.size(), run.supports->size());
  for (std::size_t i = 0; i < run.supports->size(); ++i) {
    EXPECT_NEAR(loaded->supports[i].volumeMm3, (*run.supports)[i].volumeMm3, 1e-6 * (1.0 + (*run.supports)[i].volumeMm3));
  }

  MainWindow other;
  other.resize(1000, 700);
  other.show();
  ASSERT_NO_FATAL_FAILURE(test::openPlanFolder(other, folder));
  ASSERT_TRUE(other.plan() && other.plan()->supports);
  EXPECT_EQ(other.viewer()->supportSetsShown(), nonEmptySets(*run.supports, static_cast<int>(run.supports->size())));
  EXPECT_TRUE(other.planPanel()->findChild<QCheckBox*>(QStringLiteral("showSupports"))->isEnabled());
}

TEST(StudioSupports, RegionRowSaysWhatItsSupportHoldsUp) {
  // Issue 29: the bunny's region 5 showed 0.0 mm² risky and a 20.6 mm³ support, with no reason. Each row says
  // what its support holds up: risky faces, lowest points, downward edges or later regions' struts.
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::openModelFile(window, QStringLiteral(MULTIDIR_SHARED_MODELS_DIR "/bunny.off")));
  window.searchPanel()->setSearchOptions(core::SearchOptions{});
  QSignalSpy finished(&window, &MainWindow::searchFinished);
  ASSERT_TRUE(window.runSearch());
  ASSERT_TRUE(finished.wait(test::kSearchTimeoutMs));
  const SearchRun run = finished.front().front().value<SearchRun>();
  ASSERT_TRUE(run.plan && run.supports) << run.supportsNote.toStdString();
  QTableWidget* table = window.planPanel()->regionTable();
  ASSERT_GT(table->columnCount(), PlanPanel::kSupportCauseColumn);
  EXPECT_EQ(table->horizontalHeaderItem(PlanPanel::kSupportCauseColumn)->text(), QStringLiteral("Supports hold up"));
  ASSERT_EQ(table->rowCount(), static_cast<int>(run.supports->size()));
  for (int i = 0; i < table->rowCount(); ++i) {
    const core::SupportSet& set = (*run.supports)[static_cast<std::size_t>(i)];
    const QString cause = table->item(i, PlanPanel::kSupportCauseColumn)->text();
    EXPECT_EQ(cause.isEmpty(), set.empty()) << "region " << i + 1 << ": " << cause.toStdString();
    // A region with no risky area holds up no risky face.
    if (run.plan->regions[static_cast<std::size_t>(i)].riskyAreaMm2 == 0.0) {
      EXPECT_FALSE(cause.contains(QStringLiteral("risky faces"))) << "region " << i + 1;
    }
  }

  // A region with 0.0 mm² risky area whose supports hold up two lowest points and a downward edge says so.
  core::Decomposition plan = *run.plan;
  std::vector<core::SupportSet> supports = *run.supports;
  const std::size_t last = plan.regions.size() - 1;
  plan.regions[last].riskyAreaMm2 = 0.0;
  supports[last] = (*run.supports)[0];
  supports[last].regionIndex = static_cast<int>(last);
  supports[last].cause = core::SupportCause{};
  supports[last].cause.pointContacts = 2;
  supports[last].cause.edgeContacts = 3;
  supports[last].cause.edgeLengthMm = 4.1;
  ASSERT_FALSE(supports[last].empty());
  PlanPanel panel;
  panel.setPlan(plan, core::MachineKind::TiltRotate, supports);
  EXPECT_EQ(panel.regionTable()->item(static_cast<int>(last), PlanPanel::kSupportCauseColumn)->text(),
            QStringLiteral("2 lowest points, %1 mm of downward edges").arg(QLocale().toString(4.1, 'f', 1)));
}

TEST(StudioSupports, PlanWithoutSupportsLeavesTheCheckboxDisabledAndTheColumnUnknown) {
  core::Decomposition plan;
  plan.regions.resize(2);
  PlanPanel panel;
  panel.setPlan(plan, core::MachineKind::TiltRotate);
  EXPECT_FALSE(panel.findChild<QCheckBox*>(QStringLiteral("showSupports"))->isEnabled());
  EXPECT_EQ(panel.regionTable()->item(1, PlanPanel::kSupportVolumeColumn)->text(), QStringLiteral("–"));

  // Sets without struts: known to need none, still nothing to show.
  std::vector<core::SupportSet> empty(2);
  empty[1].regionIndex = 1;
  panel.setPlan(plan, core::MachineKind::TiltRotate, empty);
  EXPECT_FALSE(panel.findChild<QCheckBox*>(QStringLiteral("showSupports"))->isEnabled());
  EXPECT_EQ(panel.regionTable()->item(1, PlanPanel::kSupportVolumeColumn)->text(), QLocale().toString(0.0, 'f', 1));
}

}  // namespace
}  // namespace multidir::ui
