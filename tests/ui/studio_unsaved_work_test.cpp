// Nothing the user made is replaced without asking (issue 11, items 1, 2 and 4): opening a mesh leaves the
// project instead of saving into it, drops, File > Open plan, the Samples menu and the Up box ask before an
// unsaved plan is lost (and Cancel keeps it), a wheel over the Up box does nothing unless it has the focus,
// and opening a file during a search asks, stops the search and shows nothing of it beside the new model.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include "multidir/core/samples/samples.h"
#include "ui/main_window.h"
#include "ui/panels/search_panel.h"
#include "ui/project/project_session.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

using test::kLoadTimeoutMs;
using test::kSearchTimeoutMs;

QByteArray contents(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

class StudioUnsavedWork : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    test::resetStudioSettings();
    m_window.resize(1200, 800);
    m_window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&m_window));
  }
  void TearDown() override {
    session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Discard);
    session()->setRunningSearchAnswer(ProjectSession::RunningSearchAnswer::Stop);
    test::resetStudioSettings();
  }

  ProjectSession* session() { return m_window.projectSession(); }
  QComboBox* upBox() { return m_window.findChild<QComboBox*>(QStringLiteral("upBox")); }

  // A T-bar with a searched plan, not saved: unsaved work.
  void showUnsavedPlan() {
    ASSERT_NO_FATAL_FAILURE(test::openModelFile(m_window, test::writeTBar(m_dir, QStringLiteral("tbar.off"))));
    ASSERT_TRUE(test::runQuickSearch(m_window).plan);
    ASSERT_TRUE(m_window.plan().has_value());
    ASSERT_TRUE(session()->isModified()) << "a searched plan is an unsaved change";
  }

  // The snowman with a search that runs for many seconds unless stopped.
  void startLongSearch() {
    ASSERT_NO_FATAL_FAILURE(test::openSample(m_window, QStringLiteral("snowman")));
    m_window.searchPanel()->setSearchOptions(test::longSearchOptions());
    ASSERT_TRUE(m_window.runSearch());
  }

  QTemporaryDir m_dir;
  MainWindow m_window;
};

TEST_F(StudioUnsavedWork, OpeningAMeshLeavesTheProjectSoSaveAsksWhereInsteadOfOverwritingIt) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  const QString project = m_dir.filePath(QStringLiteral("kitten.multidir"));
  ASSERT_TRUE(session()->saveProjectAs(project));
  m_window.setUpDirection(core::Vec3::UnitY());  // a change: the title reads "kitten.multidir*"
  ASSERT_TRUE(session()->isModified());
  const QByteArray saved = contents(project);

  session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Discard);
  QSignalSpy shown(&m_window, &MainWindow::modelShown);
  session()->openFromUser(test::writeTBar(m_dir, QStringLiteral("fertility.off")));
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs));

  EXPECT_TRUE(session()->projectPath().isEmpty());
  EXPECT_FALSE(m_window.windowTitle().contains(QStringLiteral("kitten"))) << m_window.windowTitle().toStdString();
  EXPECT_TRUE(m_window.windowTitle().contains(QStringLiteral("fertility.off")));
  EXPECT_FALSE(m_window.isWindowModified());

  // Save now asks where (a file dialog), and the project file stays as it was.
  bool dialogShown = false;
  test::answerFileDialog([this] { session()->save(); }, [](QFileDialog& dialog) { dialog.reject(); }, &dialogShown);
  EXPECT_TRUE(dialogShown) << "Save wrote without asking where";
  EXPECT_EQ(contents(project), saved);
}

TEST_F(StudioUnsavedWork, OpeningAMeshOverUnsavedWorkAsksAndCancelKeepsThePlan) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  const auto plan = m_window.plan()->plan;
  session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Cancel);
  session()->openFromUser(test::writeTBar(m_dir, QStringLiteral("other.off")));
  QTest::qWait(50);
  EXPECT_FALSE(m_window.isLoading());
  ASSERT_TRUE(m_window.plan().has_value());
  EXPECT_EQ(m_window.plan()->plan, plan);
  EXPECT_TRUE(m_window.model()->sourcePath.endsWith(QStringLiteral("tbar.off")));
  EXPECT_TRUE(session()->isModified());
}

TEST_F(StudioUnsavedWork, DroppedFileAsksFirstAndOnlyDiscardReplacesThePlan) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  const auto plan = m_window.plan()->plan;
  const QString dropped = test::writeTBar(m_dir, QStringLiteral("dropped.off"));

  test::dropFile(m_window, dropped);
  QMessageBox* box = test::waitForMessageBox(m_window, QStringLiteral("unsavedChangesBox"));
  ASSERT_NE(box, nullptr) << "the drop replaced the plan without asking";
  box->button(QMessageBox::Cancel)->click();
  QTest::qWait(50);
  EXPECT_FALSE(m_window.isLoading());
  ASSERT_TRUE(m_window.plan().has_value());
  EXPECT_EQ(m_window.plan()->plan, plan);

  QSignalSpy shown(&m_window, &MainWindow::modelShown);
  test::dropFile(m_window, dropped);
  box = test::waitForMessageBox(m_window, QStringLiteral("unsavedChangesBox"));
  ASSERT_NE(box, nullptr);
  box->button(QMessageBox::Discard)->click();
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs));
  EXPECT_EQ(m_window.model()->sourcePath, dropped);
  EXPECT_FALSE(m_window.plan().has_value());
}

TEST_F(StudioUnsavedWork, OpenPlanFromTheMenuAsksBeforeReplacingAnUnsavedPlan) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  const QString folder = m_dir.filePath(QStringLiteral("plan"));
  QString error;
  ASSERT_TRUE(m_window.exportPlan(folder, &error)) << error.toStdString();
  ASSERT_TRUE(session()->isModified());
  const auto plan = m_window.plan()->plan;

  session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Cancel);
  m_window.openPlanFromUser(folder);
  QTest::qWait(50);
  ASSERT_TRUE(m_window.plan().has_value());
  EXPECT_EQ(m_window.plan()->plan, plan) << "File > Open plan replaced the unsaved plan without asking";
}

TEST_F(StudioUnsavedWork, SamplesMenuAsksBeforeReplacingAnUnsavedPlan) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Cancel);
  m_window.openSampleFromUser(QString::fromStdString(core::samples::catalogue().front().id));
  QTest::qWait(50);
  EXPECT_FALSE(m_window.isLoading());
  EXPECT_TRUE(m_window.plan().has_value());
}

TEST_F(StudioUnsavedWork, UpBoxAsksBeforeDroppingAnUnsavedPlanAndCancelPutsItBack) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  const auto plan = m_window.plan()->plan;
  QComboBox* box = upBox();
  ASSERT_NE(box, nullptr);
  const int before = box->currentIndex();
  box->setFocus();

  session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Cancel);
  QTest::keyClick(box, Qt::Key_Down);
  EXPECT_EQ(box->currentIndex(), before);
  EXPECT_TRUE(m_window.upDirection().isApprox(core::Vec3::UnitZ()));
  ASSERT_TRUE(m_window.plan().has_value());
  EXPECT_EQ(m_window.plan()->plan, plan);

  session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Discard);
  QTest::keyClick(box, Qt::Key_Down);
  EXPECT_EQ(box->currentIndex(), before + 1);
  EXPECT_TRUE(m_window.upDirection().isApprox(-core::Vec3::UnitZ()));
  EXPECT_FALSE(m_window.plan().has_value());
}

TEST_F(StudioUnsavedWork, WheelOverTheUpBoxWithoutFocusChangesNothing) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  QComboBox* box = upBox();
  ASSERT_NE(box, nullptr);
  m_window.viewer()->setFocus();
  ASSERT_FALSE(box->hasFocus());
  const int before = box->currentIndex();
  const QPointF centre = QRectF(box->rect()).center();
  QWheelEvent wheel(centre, box->mapToGlobal(centre), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
  QApplication::sendEvent(box, &wheel);
  QTest::qWait(20);
  EXPECT_EQ(box->currentIndex(), before);
  EXPECT_FALSE(box->hasFocus());
  EXPECT_TRUE(m_window.plan().has_value());
  EXPECT_FALSE(session()->findChild<QMessageBox*>(QStringLiteral("unsavedChangesBox")));
}

TEST_F(StudioUnsavedWork, OpeningAFileDuringASearchAsksAndCancelLetsTheSearchGoOn) {
  ASSERT_NO_FATAL_FAILURE(startLongSearch());
  session()->openFromUser(test::writeTBar(m_dir, QStringLiteral("other.off")));
  QMessageBox* box = test::waitForMessageBox(m_window, QStringLiteral("searchRunningBox"));
  ASSERT_NE(box, nullptr) << "opening a file dropped the search without asking";
  box->button(QMessageBox::Cancel)->click();
  QTest::qWait(50);
  EXPECT_FALSE(m_window.isLoading());
  EXPECT_TRUE(m_window.isSearching());
  EXPECT_EQ(m_window.model()->sampleId, QStringLiteral("snowman"));
  m_window.cancelSearch();
  QSignalSpy finished(&m_window, &MainWindow::searchFinished);
  if (m_window.isSearching()) {
    ASSERT_TRUE(finished.wait(kSearchTimeoutMs));
  }
}

TEST_F(StudioUnsavedWork, OpeningAFileDuringASearchStopsItAndShowsNothingOfItBesideTheNewModel) {
  ASSERT_NO_FATAL_FAILURE(startLongSearch());
  const QString other = test::writeTBar(m_dir, QStringLiteral("other.off"));
  QSignalSpy shown(&m_window, &MainWindow::modelShown);
  QSignalSpy planShown(&m_window, &MainWindow::planShown);
  session()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Discard);  // the search settings changed
  session()->openFromUser(other);
  QMessageBox* box = test::waitForMessageBox(m_window, QStringLiteral("searchRunningBox"));
  ASSERT_NE(box, nullptr);
  box->findChild<QPushButton*>(QStringLiteral("stopSearch"))->click();
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs));
  EXPECT_EQ(m_window.model()->sourcePath, other);
  ASSERT_TRUE(test::waitUntil([this] { return !m_window.isSearching(); }, kSearchTimeoutMs));
  QTest::qWait(50);
  EXPECT_TRUE(planShown.isEmpty()) << "the stopped search's plan was shown";
  EXPECT_FALSE(m_window.plan().has_value());
  SearchPanel* panel = m_window.searchPanel();
  EXPECT_EQ(panel->readoutText(), QStringLiteral("-|-|-|-")) << panel->readoutText().toStdString();
  EXPECT_EQ(panel->chartPointCount(), 0);
  EXPECT_TRUE(panel->noticeText().isEmpty()) << panel->noticeText().toStdString();
}

TEST_F(StudioUnsavedWork, SearchTabShowsNothingOfTheLastModelsSearchOnceAnotherModelIsShown) {
  ASSERT_NO_FATAL_FAILURE(showUnsavedPlan());
  ASSERT_NE(m_window.searchPanel()->readoutText(), QStringLiteral("-|-|-|-"));
  ASSERT_NO_FATAL_FAILURE(test::openModelFile(m_window, test::writeTBar(m_dir, QStringLiteral("other.off"))));
  EXPECT_EQ(m_window.searchPanel()->readoutText(), QStringLiteral("-|-|-|-"));
  EXPECT_EQ(m_window.searchPanel()->chartPointCount(), 0);
  EXPECT_TRUE(m_window.searchPanel()->noticeText().isEmpty());
}

}  // namespace
}  // namespace multidir::ui
