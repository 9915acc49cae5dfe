// Studio projects: a saved project reopens with the same plan, changed or missing models are reported,
// unsaved changes are marked, asked about and autosaved, a crashed session's autosave is recovered, and the
// recent files, dropped files and the window's layout behave as the File menu promises.
#include <gtest/gtest.h>

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>
#include <algorithm>
#include <functional>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/plan/project_file.h"
#include "multidir/core/samples/samples.h"
#include "support/primitives.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/project/autosave.h"
#include "ui/project/project_session.h"
#include "ui/project/recent_files.h"
#include "ui/studio_startup.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

using test::kLoadTimeoutMs;
using test::kSearchTimeoutMs;
using test::quickSearchOptions;
using test::writeTBar;
using test::dropFile;

// Empty settings, recent files and autosaves before and after each test: they outlive the test process.
class StudioProject : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    reset();
  }
  void TearDown() override { reset(); }

  static void reset() { test::resetStudioSettings(); }

  static void show(MainWindow& window) {
    window.resize(1000, 700);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  }

  static void open(MainWindow& window, const QString& path) {
    QSignalSpy shown(&window, &MainWindow::modelShown);
    window.openFile(path);
    ASSERT_TRUE(shown.wait(kLoadTimeoutMs)) << "did not load " << path.toStdString();
  }

  static void search(MainWindow& window) {
    ASSERT_TRUE(test::runQuickSearch(window).plan);
    ASSERT_TRUE(window.plan().has_value());
    ASSERT_GE(window.plan()->plan->clippingPlanes.size(), 1u) << "a plan without planes proves nothing here";
  }

  static void waitOpened(ProjectSession* session, const std::function<bool()>& start) {
    test::waitProjectOpened(session, start);
  }

  static void expectSamePlan(const MainWindow& reopened, const SearchRun& saved) {
    ASSERT_TRUE(reopened.plan().has_value());
    const core::Decomposition& a = *saved.plan;
    const core::Decomposition& b = *reopened.plan()->plan;
    ASSERT_EQ(b.clippingPlanes.size(), a.clippingPlanes.size());
    for (std::size_t k = 0; k < a.clippingPlanes.size(); ++k) {
      EXPECT_EQ(b.clippingPlanes[k].normal, a.clippingPlanes[k].normal) << "plane " << k;
      EXPECT_EQ(b.clippingPlanes[k].offset, a.clippingPlanes[k].offset) << "plane " << k;
    }
    EXPECT_EQ(b.regions.size(), a.regions.size());
    EXPECT_NEAR(b.jgAfterMm2, a.jgAfterMm2, 1e-9 * std::max(1.0, a.jgAfterMm2));
    EXPECT_NEAR(b.jgBeforeMm2, a.jgBeforeMm2, 1e-9 * a.jgBeforeMm2);
  }

  QTemporaryDir m_dir;
};

TEST_F(StudioProject, SavedSampleProjectReopensInANewWindowWithTheSamePlan) {
  MainWindow window;
  show(window);
  const QString sample = QString::fromStdString(core::samples::catalogue().front().id);
  test::openSample(window, sample);
  search(window);
  const SearchRun saved = *window.plan();
  ASSERT_GE(saved.plan->clippingPlanes.size(), 1u);
  ProjectSession* session = window.projectSession();
  EXPECT_TRUE(session->isModified()) << "a searched plan is an unsaved change";

  const QString path = m_dir.filePath(QStringLiteral("snow.multidir"));
  QString error;
  ASSERT_TRUE(session->saveProjectAs(path, &error)) << error.toStdString();
  EXPECT_FALSE(session->isModified());
  EXPECT_FALSE(window.isWindowModified());
  EXPECT_EQ(window.windowTitle(), QStringLiteral("snow.multidir[*] - MultiDir Studio"));

  // File > Open takes projects too.
  MainWindow other;
  show(other);
  waitOpened(other.projectSession(), [&other, &path] {
    other.openFile(path);
    return true;
  });
  ASSERT_TRUE(other.model().has_value());
  EXPECT_EQ(other.model()->sampleId, sample);
  expectSamePlan(other, saved);
  EXPECT_EQ(other.plan()->options.candidates.normalSamples, quickSearchOptions().candidates.normalSamples);
  EXPECT_FALSE(other.projectSession()->isModified());
  EXPECT_EQ(other.projectSession()->projectPath(), QFileInfo(path).absoluteFilePath());
  EXPECT_EQ(other.searchPanel()->searchOptions().beamWidth, quickSearchOptions().beamWidth);

  // Any setting changed afterwards marks the project.
  core::SearchOptions changed = quickSearchOptions();
  changed.beamWidth = 3;
  other.searchPanel()->setSearchOptions(changed);
  EXPECT_TRUE(other.projectSession()->isModified());
  EXPECT_TRUE(other.isWindowModified());
}

TEST_F(StudioProject, ProjectWhoseModelFileChangedReopensWithAWarning) {
  const QString model = writeTBar(m_dir, QStringLiteral("tbar.off"));
  MainWindow window;
  show(window);
  open(window, model);
  search(window);
  const SearchRun saved = *window.plan();
  const QString path = m_dir.filePath(QStringLiteral("tbar.multidir"));
  ASSERT_TRUE(window.projectSession()->saveProjectAs(path));

  {  // Another program touches the model file: same shape, other bytes.
    QFile file(model);
    ASSERT_TRUE(file.open(QIODevice::Append));
    file.write("# edited elsewhere\n");
  }
  MainWindow other;
  show(other);
  waitOpened(other.projectSession(), [&other, &path] { return other.projectSession()->openProject(path); });
  expectSamePlan(other, saved);
  const QString status = other.statusBar()->currentMessage();
  EXPECT_TRUE(status.contains(QStringLiteral("tbar.off"))) << status.toStdString();
  EXPECT_TRUE(status.contains(QStringLiteral("recomputed on the changed file"))) << status.toStdString();
  auto* box = other.findChild<QMessageBox*>(QStringLiteral("projectWarningBox"));
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->isVisible());
  EXPECT_TRUE(other.projectSession()->isModified()) << "what is shown no longer matches the file";
}

TEST_F(StudioProject, MissingModelFileIsAClearErrorAndTheModelShownStays) {
  const QString model = writeTBar(m_dir, QStringLiteral("gone.off"));
  const QString path = m_dir.filePath(QStringLiteral("gone.multidir"));
  {
    MainWindow window;
    show(window);
    open(window, model);
    ASSERT_TRUE(window.projectSession()->saveProjectAs(path));
  }
  ASSERT_TRUE(QFile::remove(model));

  MainWindow other;
  show(other);
  const QString kept = writeTBar(m_dir, QStringLiteral("kept.off"));
  open(other, kept);
  QString error;
  EXPECT_FALSE(other.projectSession()->openProject(path, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("missing"))) << error.toStdString();
  EXPECT_TRUE(error.contains(QDir::toNativeSeparators(model))) << error.toStdString();
  EXPECT_TRUE(other.statusBar()->currentMessage().contains(QStringLiteral("gone.off")))
      << other.statusBar()->currentMessage().toStdString();
  EXPECT_NE(other.findChild<QMessageBox*>(QStringLiteral("projectErrorBox")), nullptr);
  EXPECT_FALSE(other.isLoading());
  ASSERT_TRUE(other.model().has_value());
  EXPECT_EQ(other.model()->sourcePath, kept);
  EXPECT_TRUE(other.projectSession()->projectPath().isEmpty());
}

TEST_F(StudioProject, ModifiedProjectIsAutosavedAndANewWindowRecoversItsPlan) {
  QSettings().setValue(QStringLiteral("autosave/intervalSeconds"), 1);
  const QString model = writeTBar(m_dir, QStringLiteral("tbar.off"));
  QString crashed;
  QString own;
  SearchRun saved;
  {
    MainWindow window;
    show(window);
    open(window, model);
    EXPECT_FALSE(window.projectSession()->isModified()) << "a model opened into an untitled project is no change";
    QSignalSpy autosaved(window.projectSession(), &ProjectSession::autosaved);
    search(window);
    saved = *window.plan();
    ASSERT_TRUE(autosaved.wait(10000)) << "nothing was autosaved";
    own = window.projectSession()->autosavePath();
    EXPECT_TRUE(QFileInfo::exists(own));
    EXPECT_TRUE(own.startsWith(Autosave::folder()));
    EXPECT_TRUE(window.projectSession()->recoverableAutosave().isEmpty())
        << "a running window's autosave is not offered to others";
    // A crash leaves the autosave behind; this window, going away normally, deletes its own.
    crashed = Autosave::folder() + QStringLiteral("/crashed.multidir");
    ASSERT_TRUE(QFile::copy(own, crashed));
  }
  EXPECT_FALSE(QFileInfo::exists(own));
  MainWindow other;
  show(other);
  ProjectSession* session = other.projectSession();
  EXPECT_EQ(session->recoverableAutosave(), crashed);
  waitOpened(session, [session] { return session->recoverAutosave(); });
  expectSamePlan(other, saved);
  EXPECT_TRUE(session->isModified()) << "recovered work is unsaved";
  EXPECT_TRUE(session->projectPath().isEmpty()) << "it was untitled";
  EXPECT_EQ(session->autosavePath(), crashed) << "the recovered file is now this window's autosave";
  EXPECT_TRUE(session->recoverableAutosave().isEmpty());
}

TEST_F(StudioProject, InteractiveStartOffersAnAutosaveLeftByACrashWithoutBlocking) {
  QDir().mkpath(Autosave::folder());
  const QString left = Autosave::folder() + QStringLiteral("/left.multidir");
  core::Project project;
  project.model.sampleId = core::samples::catalogue().front().id;
  project.multidirVersion = "test";
  ASSERT_TRUE(core::saveProject(project, left.toStdString()).ok());

  MainWindow screenshot;
  StudioOptions batch;
  batch.screenshotPath = m_dir.filePath(QStringLiteral("shot.png"));
  startStudio(screenshot, batch);
  EXPECT_EQ(screenshot.findChild<QMessageBox*>(QStringLiteral("recoverAutosaveBox")), nullptr)
      << "--screenshot runs never ask";

  MainWindow window;
  show(window);
  startStudio(window, StudioOptions{});
  auto* box = window.findChild<QMessageBox*>(QStringLiteral("recoverAutosaveBox"));
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->isVisible());
  EXPECT_FALSE(box->isModal());
  QAbstractButton* discard = nullptr;
  for (QAbstractButton* button : box->buttons())
    if (box->buttonRole(button) == QMessageBox::DestructiveRole) discard = button;
  ASSERT_NE(discard, nullptr);
  discard->click();
  EXPECT_FALSE(QFileInfo::exists(left));
  EXPECT_TRUE(window.projectSession()->recoverableAutosave().isEmpty());
}

TEST_F(StudioProject, CleanSaveDeletesTheAutosave) {
  QSettings().setValue(QStringLiteral("autosave/intervalSeconds"), 1);
  MainWindow window;
  show(window);
  open(window, writeTBar(m_dir, QStringLiteral("tbar.off")));
  QSignalSpy autosaved(window.projectSession(), &ProjectSession::autosaved);
  core::MachineSpec machine;
  machine.platformRadiusMm = 30;
  window.machinePanel()->setMachineSpec(machine);
  ASSERT_TRUE(window.projectSession()->isModified());
  ASSERT_TRUE(autosaved.wait(10000));
  const QString autosave = window.projectSession()->autosavePath();
  ASSERT_TRUE(QFileInfo::exists(autosave));
  ASSERT_TRUE(window.projectSession()->saveProjectAs(m_dir.filePath(QStringLiteral("t.multidir"))));
  EXPECT_FALSE(QFileInfo::exists(autosave));
  EXPECT_TRUE(window.projectSession()->autosavePath().isEmpty());
}

TEST_F(StudioProject, ClosingWithUnsavedChangesAsksFirst) {
  MainWindow window;
  show(window);
  open(window, writeTBar(m_dir, QStringLiteral("tbar.off")));
  window.setUpDirection(core::Vec3::UnitY());
  ProjectSession* session = window.projectSession();
  ASSERT_TRUE(session->isModified());

  session->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Cancel);
  EXPECT_FALSE(window.close());
  EXPECT_TRUE(window.isVisible());

  // Asked for real: the question does not block; answering Discard closes the window.
  session->setUnsavedChangesAnswer(std::nullopt);
  EXPECT_FALSE(window.close());
  auto* box = window.findChild<QMessageBox*>(QStringLiteral("unsavedChangesBox"));
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->isVisible());
  box->button(QMessageBox::Discard)->click();
  for (int i = 0; i < 100 && window.isVisible(); ++i) QTest::qWait(20);
  EXPECT_FALSE(window.isVisible());
}

TEST_F(StudioProject, ClosingAfterSavingAnswersSaveAndWritesTheProject) {
  MainWindow window;
  show(window);
  open(window, writeTBar(m_dir, QStringLiteral("tbar.off")));
  const QString path = m_dir.filePath(QStringLiteral("t.multidir"));
  ASSERT_TRUE(window.projectSession()->saveProjectAs(path));
  window.setUpDirection(core::Vec3::UnitY());
  window.projectSession()->setUnsavedChangesAnswer(ProjectSession::UnsavedAnswer::Save);
  EXPECT_TRUE(window.close());
  const core::Result<core::Project> written = core::loadProject(path.toStdString());
  ASSERT_TRUE(written.ok()) << written.error().describe();
  EXPECT_TRUE(written->model.up.isApprox(core::Vec3::UnitY()));
}

TEST_F(StudioProject, RecentFilesListTheLatestFirstAndDropOnesThatAreGone) {
  const QString a = writeTBar(m_dir, QStringLiteral("a.off"));
  const QString b = writeTBar(m_dir, QStringLiteral("b.off"));
  const QString project = m_dir.filePath(QStringLiteral("p.multidir"));
  MainWindow window;
  show(window);
  open(window, a);
  open(window, b);
  ASSERT_TRUE(window.projectSession()->saveProjectAs(project));
  EXPECT_EQ(recentFiles(), (QStringList{project, b, a}));
  open(window, a);
  EXPECT_EQ(recentFiles(), (QStringList{a, project, b}));
  auto* first = window.projectSession()->recentMenu()->findChild<QAction*>(QStringLiteral("recentFile1"));
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(first->text().contains(QStringLiteral("a.off"))) << first->text().toStdString();

  ASSERT_TRUE(QFile::remove(b));
  window.projectSession()->openRecent(b);
  EXPECT_EQ(recentFiles(), (QStringList{a, project}));
  EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("b.off")))
      << window.statusBar()->currentMessage().toStdString();
  EXPECT_FALSE(window.isLoading());

  for (int i = 0; i < kMaxRecentFiles + 2; ++i) addRecentFile(m_dir.filePath(QStringLiteral("m%1.stl").arg(i)));
  const QStringList capped = recentFiles();
  ASSERT_EQ(capped.size(), kMaxRecentFiles);
  EXPECT_EQ(capped.front(), m_dir.filePath(QStringLiteral("m%1.stl").arg(kMaxRecentFiles + 1)));

  window.projectSession()->recentMenu()->refresh();
  auto* clear = window.projectSession()->recentMenu()->findChild<QAction*>(QStringLiteral("clearRecentFiles"));
  ASSERT_NE(clear, nullptr);
  clear->trigger();
  EXPECT_TRUE(recentFiles().isEmpty());
}

// Drags `path` over the window and drops it there, as a file manager would.
TEST_F(StudioProject, DroppedMeshFileIsOpened) {
  const QString model = writeTBar(m_dir, QStringLiteral("dropped.off"));
  MainWindow window;
  show(window);
  QSignalSpy shown(&window, &MainWindow::modelShown);
  dropFile(window, model);
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs));
  EXPECT_EQ(window.model()->sourcePath, model);
}

TEST_F(StudioProject, DroppedTextFileIsRefusedNamingItAndWhatIsAccepted) {
  const QString notes = m_dir.filePath(QStringLiteral("notes.txt"));
  QFile file(notes);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write("not a mesh\n");
  file.close();
  MainWindow window;
  show(window);
  dropFile(window, notes);
  const QString status = window.statusBar()->currentMessage();
  EXPECT_TRUE(status.contains(QStringLiteral("notes.txt"))) << status.toStdString();
  EXPECT_TRUE(status.contains(QStringLiteral(".stl")) && status.contains(QStringLiteral(".multidir")))
      << status.toStdString();
  EXPECT_FALSE(window.isLoading());
  EXPECT_FALSE(window.hasModel());
}

TEST_F(StudioProject, WindowGeometryAndDockLayoutAreRestoredAtTheNextStart) {
  QSize closedSize;
  {
    MainWindow window;
    window.resize(1111, 777);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    window.findChild<QDockWidget*>(QStringLiteral("overhangDock"))->hide();
    closedSize = window.size();
    EXPECT_EQ(closedSize.width(), 1111);
    EXPECT_TRUE(window.close());
  }
  MainWindow next;
  EXPECT_EQ(next.size(), closedSize) << "not the constructor's default size";
  next.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&next));
  EXPECT_TRUE(next.findChild<QDockWidget*>(QStringLiteral("overhangDock"))->isHidden());
  EXPECT_FALSE(next.findChild<QDockWidget*>(QStringLiteral("machineDock"))->isHidden());
}

}  // namespace
}  // namespace multidir::ui
