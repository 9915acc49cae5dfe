// The Machine panel's "Best pose": the pose search runs off the GUI thread and lists the poses it tried, a
// clicked pose is only previewed, a used pose becomes the model's up (and the project's), and Cancel keeps
// the plan shown. On the T-bar (a stem standing on the platform with two wings overhanging it), which is
// better lying on its side or standing on its bar than standing on its stem.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <cmath>

#include "multidir/core/plan/plan_file.h"
#include "multidir/core/plan/project_file.h"
#include "multidir/core/search/pose_search.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/pose_search_box.h"
#include "ui/panels/search_panel.h"
#include "ui/project/project_session.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

using test::kSearchTimeoutMs;

// Few poses, two of them searched fully: a second or two on the T-bar.
constexpr int kPoses = 6;
constexpr int kFullSearches = 2;

class StudioPoseSearch : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    test::resetStudioSettings();
  }
  void TearDown() override { test::resetStudioSettings(); }

  // The window showing the T-bar standing on its stem (+Z up), with quick search settings and few poses.
  void showTBar(MainWindow& window) {
    window.resize(1400, 900);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    ASSERT_NO_FATAL_FAILURE(test::openModelFile(window, test::writeTBar(m_dir, QStringLiteral("tbar.stl"))));
    window.setUpDirection(core::Vec3::UnitZ());
    window.searchPanel()->setSearchOptions(test::quickSearchOptions());
    box(window)->setPoseOptions(kPoses, kFullSearches);
  }

  static PoseSearchBox* box(const MainWindow& window) { return window.machinePanel()->poseBox(); }

  // Clicks "Find best pose" and waits until its poses are listed and the chosen one's plan is shown.
  static void findBestPose(MainWindow& window) {
    QSignalSpy finished(&window, &MainWindow::poseSearchFinished);
    QSignalSpy planShown(&window, &MainWindow::planShown);
    auto* find = box(window)->findChild<QPushButton*>(QStringLiteral("findBestPose"));
    ASSERT_TRUE(find->isEnabled());
    QTest::mouseClick(find, Qt::LeftButton);
    ASSERT_TRUE(window.isPoseSearching());
    ASSERT_TRUE(finished.wait(kSearchTimeoutMs)) << "the pose search did not finish";
    ASSERT_TRUE(window.poseRun().has_value());
    if (planShown.isEmpty()) {
      ASSERT_TRUE(planShown.wait(kSearchTimeoutMs)) << "the chosen pose's plan was not shown";
    }
  }

  static void clickRow(QTableWidget* table, int row) {
    QTableWidgetItem* item = table->item(row, PoseSearchBox::SourceColumn);
    ASSERT_NE(item, nullptr);
    table->scrollToItem(item);
    QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::NoModifier, table->visualItemRect(item).center());
  }

  QTemporaryDir m_dir;
};

TEST_F(StudioPoseSearch, FindBestPoseListsEveryCandidateAndStandsTheModelOnTheChosenOne) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showTBar(window));
  ASSERT_NO_FATAL_FAILURE(findBestPose(window));
  const core::PoseSearchResult& result = *window.poseRun()->result;

  // One row per candidate core tries, in its order, the chosen one marked.
  core::PoseOptions poseOptions;
  poseOptions.poses = kPoses;
  const auto candidates =
      core::candidatePoses(*window.model()->mesh, core::Vec3::UnitZ(), poseOptions, test::quickSearchOptions());
  ASSERT_TRUE(candidates.ok());
  QTableWidget* table = box(window)->table();
  ASSERT_EQ(table->rowCount(), static_cast<int>(candidates->size()));
  ASSERT_EQ(result.trials.size(), candidates->size());
  for (int row = 0; row < table->rowCount(); ++row) {
    EXPECT_TRUE(result.trials[row].pose.up.isApprox((*candidates)[row].up, 1e-12)) << "row " << row;
    EXPECT_EQ(table->verticalHeaderItem(row)->text() == PoseSearchBox::tr("chosen"), row == result.chosenTrial);
    EXPECT_EQ(table->item(row, PoseSearchBox::SourceColumn)->font().bold(), row == result.chosenTrial);
  }
  EXPECT_EQ(box(window)->chosenTrial(), result.chosenTrial);
  int searched = 0;
  for (int row = 0; row < table->rowCount(); ++row) {
    const bool full = table->item(row, PoseSearchBox::SearchColumn)->text().startsWith(PoseSearchBox::tr("full search"));
    EXPECT_EQ(full, result.trials[row].searched) << "row " << row;
    searched += full ? 1 : 0;
  }
  EXPECT_EQ(searched, kFullSearches);

  // Standing on its stem is not the best: the chosen pose leaves no more risky area, in no more regions.
  const core::PoseTrial& given = result.trials.front();
  const core::PoseTrial& chosen = result.trials[result.chosenTrial];
  EXPECT_NE(result.chosenTrial, 0);
  EXPECT_LE(chosen.jgAfterMm2, given.jgAfterMm2);
  EXPECT_LE(chosen.regions, given.regions);

  // The chosen pose is the model's up, in the Up box, with its plan shown.
  EXPECT_TRUE(window.upDirection().isApprox(chosen.pose.up.normalized(), 1e-12));
  ASSERT_TRUE(window.upPose().has_value());
  EXPECT_EQ(window.upPose()->pose.source, core::poseSourceName(chosen.pose.source));
  ASSERT_TRUE(window.plan().has_value());
  EXPECT_EQ(window.plan()->plan->jgAfterMm2, chosen.jgAfterMm2);
  EXPECT_EQ(static_cast<int>(window.plan()->plan->regions.size()), chosen.regions);
  EXPECT_TRUE(window.plan()->machine.up.isApprox(chosen.pose.up.normalized(), 1e-12));
  EXPECT_TRUE(window.viewer()->hasPlan());
  EXPECT_TRUE(table->item(result.chosenTrial, PoseSearchBox::SearchColumn)->text().endsWith(PoseSearchBox::tr(", in use")));
}

TEST_F(StudioPoseSearch, CancelStopsTheSearchAndKeepsThePlanShown) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showTBar(window));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  const std::shared_ptr<const core::Decomposition> before = window.plan()->plan;

  // Long enough to be caught running: many poses, each searched with thousands of normals.
  window.searchPanel()->setSearchOptions(test::longSearchOptions());
  box(window)->setPoseOptions(24, 4);
  QSignalSpy finished(&window, &MainWindow::poseSearchFinished);
  QSignalSpy failed(&window, &MainWindow::poseSearchFailed);
  QTest::mouseClick(box(window)->findChild<QPushButton*>(QStringLiteral("findBestPose")), Qt::LeftButton);
  ASSERT_TRUE(window.isPoseSearching());
  EXPECT_TRUE(window.isSearching()) << "a pose search counts as a running search (asked about before replacing)";
  QTest::mouseClick(box(window)->findChild<QPushButton*>(QStringLiteral("cancelPoseSearch")), Qt::LeftButton);
  ASSERT_TRUE(test::waitUntil([&window] { return !window.isPoseSearching(); }, kSearchTimeoutMs));
  EXPECT_EQ(finished.size() + failed.size(), 1);

  // The plan shown, the up and the project's plan are those before the pose search.
  ASSERT_TRUE(window.plan().has_value());
  EXPECT_EQ(window.plan()->plan, before);
  EXPECT_TRUE(window.upDirection().isApprox(core::Vec3::UnitZ(), 1e-12));
  EXPECT_FALSE(window.upPose().has_value());
  // What finished is listed (or nothing, when no pose had finished), never more than one model's poses.
  if (!finished.isEmpty()) {
    EXPECT_TRUE(window.poseRun()->chosenRun.plan->cancelled);
    EXPECT_EQ(box(window)->trialCount(), static_cast<int>(window.poseRun()->result->trials.size()));
  } else {
    EXPECT_EQ(box(window)->trialCount(), 0);
  }
  // The studio goes on: a search runs again.
  window.searchPanel()->setSearchOptions(test::quickSearchOptions());
  EXPECT_TRUE(test::runQuickSearch(window).plan);
}

TEST_F(StudioPoseSearch, ClickingAPoseShowsItWithoutChangingTheProject) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showTBar(window));
  ASSERT_NO_FATAL_FAILURE(findBestPose(window));
  ASSERT_TRUE(window.projectSession()->saveProjectAs(m_dir.filePath(QStringLiteral("tbar.multidir"))));
  ASSERT_FALSE(window.projectSession()->isModified());
  const core::Vec3 up = window.upDirection();
  const std::shared_ptr<const core::Decomposition> plan = window.plan()->plan;
  window.viewer()->grabFramebuffer();
  EXPECT_TRUE(window.viewer()->viewUp().isApprox(up, 1e-9));

  // Row 0 is the given up (+Z), not the chosen pose: the view turns to it.
  clickRow(box(window)->table(), 0);
  ASSERT_TRUE(window.previewedUp().has_value());
  window.viewer()->grabFramebuffer();
  EXPECT_TRUE(window.viewer()->viewUp().isApprox(core::Vec3::UnitZ(), 1e-9));
  EXPECT_FALSE(window.projectSession()->isModified());
  EXPECT_FALSE(window.isWindowModified());
  EXPECT_TRUE(window.upDirection().isApprox(up, 1e-12));
  EXPECT_EQ(window.plan()->plan, plan);

  // "Show current up" turns the view back, with the plan.
  QTest::mouseClick(box(window)->findChild<QPushButton*>(QStringLiteral("showCurrentUp")), Qt::LeftButton);
  EXPECT_FALSE(window.previewedUp().has_value());
  window.viewer()->grabFramebuffer();
  EXPECT_TRUE(window.viewer()->viewUp().isApprox(up, 1e-9));
  EXPECT_TRUE(window.viewer()->hasPlan());
  EXPECT_FALSE(window.projectSession()->isModified());
}

TEST_F(StudioPoseSearch, UsedPoseIsSavedWithTheProjectAndReopensAsTheUp) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showTBar(window));
  ASSERT_NO_FATAL_FAILURE(findBestPose(window));
  // A pose along no axis (the T-bar's slanted resting poses): the Up box takes it as an entry of its own.
  const core::PoseSearchResult& result = *window.poseRun()->result;
  int row = -1;
  for (int i = 0; i < static_cast<int>(result.trials.size()) && row < 0; ++i) {
    if (result.trials[i].pose.up.cwiseAbs().maxCoeff() < 0.99) row = i;
  }
  ASSERT_GE(row, 0) << "no candidate pose off the axes";
  const core::PoseTrial used = result.trials[row];
  window.projectSession()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Discard);
  ASSERT_NO_FATAL_FAILURE(clickRow(box(window)->table(), row));
  QSignalSpy searched(&window, &MainWindow::searchFinished);
  QTest::mouseClick(box(window)->findChild<QPushButton*>(QStringLiteral("usePose")), Qt::LeftButton);
  ASSERT_TRUE(searched.wait(kSearchTimeoutMs)) << "the pose's plan was not searched";
  const core::Vec3 up = used.pose.up.normalized();
  EXPECT_TRUE(window.upDirection().isApprox(up, 1e-12));
  auto* upBox = window.findChild<QComboBox*>(QStringLiteral("upBox"));
  EXPECT_TRUE(upBox->currentText().startsWith(QStringLiteral("Pose: "))) << upBox->currentText().toStdString();
  ASSERT_TRUE(window.plan().has_value());
  EXPECT_TRUE(window.plan()->machine.up.isApprox(up, 1e-12));
  const double jg = window.plan()->plan->jgAfterMm2;

  // An exported plan records the pose as `multidir decompose --pose auto` does.
  const QString folder = m_dir.filePath(QStringLiteral("posed-plan"));
  QString exportError;
  ASSERT_TRUE(test::waitUntil([&window] { return !window.isGrowingSupports(); }, kSearchTimeoutMs));
  ASSERT_TRUE(window.exportPlan(folder, &exportError)) << exportError.toStdString();
  const core::Result<core::LoadedPlan> exported = core::loadPlan(folder.toStdString());
  ASSERT_TRUE(exported.ok()) << exported.error().describe();
  ASSERT_TRUE(exported->metadata.pose.has_value());
  EXPECT_TRUE(exported->metadata.pose->up.isApprox(up, 1e-12));
  EXPECT_EQ(exported->metadata.pose->source, core::poseSourceName(used.pose.source));
  EXPECT_TRUE(exported->metadata.machine.up.isApprox(up, 1e-12));
  EXPECT_TRUE(exported->metadata.up.isApprox(core::Vec3::UnitZ(), 1e-12));
  EXPECT_TRUE((exported->metadata.pose->rotation * up).isApprox(core::Vec3::UnitZ(), 1e-9));

  const QString path = m_dir.filePath(QStringLiteral("posed.multidir"));
  QString error;
  ASSERT_TRUE(window.projectSession()->saveProjectAs(path, &error)) << error.toStdString();
  const core::Result<core::Project> saved = core::loadProject(path.toStdString());
  ASSERT_TRUE(saved.ok());
  ASSERT_TRUE(saved->model.pose.has_value());
  EXPECT_EQ(saved->model.pose->source, core::poseSourceName(used.pose.source));
  EXPECT_TRUE(saved->model.pose->platformUp.isApprox(core::Vec3::UnitZ(), 1e-12));

  MainWindow other;
  other.resize(1400, 900);
  other.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&other));
  test::waitProjectOpened(other.projectSession(), [&other, &path] { return other.projectSession()->openProject(path); });
  EXPECT_EQ(other.upDirection(), window.upDirection()) << "the up comes back bit for bit";
  EXPECT_EQ(other.findChild<QComboBox*>(QStringLiteral("upBox"))->currentText(), upBox->currentText());
  ASSERT_TRUE(other.upPose().has_value());
  EXPECT_EQ(other.upPose()->pose.source, core::poseSourceName(used.pose.source));
  ASSERT_TRUE(other.plan().has_value());
  EXPECT_NEAR(other.plan()->plan->jgAfterMm2, jg, 1e-9 * std::max(1.0, jg));
  EXPECT_FALSE(other.projectSession()->isModified());
}

TEST_F(StudioPoseSearch, UsingAnotherPoseAsksBeforeDroppingAnUnsavedPlanThenSearchesIt) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showTBar(window));
  ASSERT_NO_FATAL_FAILURE(findBestPose(window));
  ASSERT_TRUE(window.projectSession()->isModified()) << "the plan found is an unsaved change";
  const core::Vec3 up = window.upDirection();
  const std::shared_ptr<const core::Decomposition> plan = window.plan()->plan;

  // Row 0, the up the search started from, is not the chosen one.
  QTableWidget* table = box(window)->table();
  ASSERT_NO_FATAL_FAILURE(clickRow(table, 0));
  auto* use = box(window)->findChild<QPushButton*>(QStringLiteral("usePose"));
  ASSERT_TRUE(use->isEnabled());
  window.projectSession()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Cancel);
  QTest::mouseClick(use, Qt::LeftButton);
  EXPECT_TRUE(window.upDirection().isApprox(up, 1e-12)) << "Cancel keeps the pose in force";
  EXPECT_EQ(window.plan()->plan, plan);

  window.projectSession()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Discard);
  QSignalSpy searched(&window, &MainWindow::searchFinished);
  QTest::mouseClick(use, Qt::LeftButton);
  EXPECT_TRUE(window.upDirection().isApprox(core::Vec3::UnitZ(), 1e-12));
  EXPECT_FALSE(window.upPose().has_value() && window.upPose()->pose.source != "given");
  ASSERT_TRUE(searched.wait(kSearchTimeoutMs)) << "another pose's plan is searched";
  EXPECT_TRUE(window.plan()->machine.up.isApprox(core::Vec3::UnitZ(), 1e-12));
}

}  // namespace
}  // namespace multidir::ui
