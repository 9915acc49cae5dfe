// The File and Help menus keep their promises (issue 11, item 16): a failed load changes nothing, Export
// plan creates the folder it is given, each file dialog starts where that kind of file was last used, and
// Help > About names the version.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "ui/main_window.h"
#include "ui/project/project_session.h"
#include "ui/studio_startup.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

class StudioFileMenu : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    test::resetStudioSettings();
    m_window.resize(1000, 700);
    m_window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&m_window));
  }
  void TearDown() override { test::resetStudioSettings(); }

  QAction* action(const QString& name) { return m_window.findChild<QAction*>(name); }

  // The folder the file dialog `trigger` opens starts in (the dialog is then closed); empty when none came.
  static QString dialogStartFolder(const std::function<void()>& trigger) {
    QString folder;
    test::answerFileDialog(trigger, [&folder](QFileDialog& dialog) {
      folder = dialog.directory().absolutePath();
      dialog.reject();
    });
    return folder;
  }

  QString makeFolder(const QString& name) {
    EXPECT_TRUE(QDir(m_dir.path()).mkpath(name));
    return QDir(m_dir.filePath(name)).absolutePath();
  }

  QTemporaryDir m_dir;
  MainWindow m_window;
};

TEST_F(StudioFileMenu, FailedLoadInAnEmptySessionMarksNothingModified) {
  const QString broken = m_dir.filePath(QStringLiteral("broken.stl"));
  QFile file(broken);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write("solid broken\nthis is not a mesh\n");
  file.close();
  // As `multidir-studio broken.stl --up y` starts: the up direction is set before the load fails.
  QSignalSpy failed(&m_window, &MainWindow::loadFailed);
  StudioOptions options;
  options.modelPath = broken;
  options.up = core::Vec3::UnitY();
  startStudio(m_window, options);
  ASSERT_TRUE(failed.wait(test::kLoadTimeoutMs));
  QTest::qWait(20);
  EXPECT_FALSE(m_window.projectSession()->isModified());
  EXPECT_FALSE(m_window.isWindowModified());
  EXPECT_FALSE(m_window.hasModel());
}

TEST_F(StudioFileMenu, ExportPlanIntoAFolderNamedInTheDialogCreatesIt) {
  ASSERT_NO_FATAL_FAILURE(test::openSample(m_window, QStringLiteral("snowman")));
  ASSERT_TRUE(test::runQuickSearch(m_window).plan);
  const QString folder = m_dir.filePath(QStringLiteral("snowman-plan"));
  ASSERT_FALSE(QFileInfo::exists(folder));
  bool answered = false;
  const QStringList messages = test::answerFileDialog(
      [this] { action(QStringLiteral("exportPlan"))->trigger(); },
      [&folder](QFileDialog& dialog) {
        dialog.selectFile(folder);
        static_cast<QDialog&>(dialog).accept();  // QFileDialog::accept is protected; QDialog's calls it
      },
      &answered);
  ASSERT_TRUE(answered) << "File > Export plan showed no dialog";
  EXPECT_TRUE(messages.isEmpty()) << messages.join(QStringLiteral(" | ")).toStdString();
  EXPECT_TRUE(QFileInfo::exists(folder + QStringLiteral("/plan.json"))) << "the plan was not written to a new folder";
}

TEST_F(StudioFileMenu, EachFileDialogStartsWhereThatKindOfFileWasLastUsed) {
  const QString models = makeFolder(QStringLiteral("models"));
  const QString projects = makeFolder(QStringLiteral("projects"));
  const QString model = test::writeTBar(m_dir, QStringLiteral("models/tbar.off"));
  QSignalSpy shown(&m_window, &MainWindow::modelShown);
  m_window.projectSession()->openFromUser(model);
  ASSERT_TRUE(shown.wait(test::kLoadTimeoutMs));
  ASSERT_TRUE(m_window.projectSession()->saveProjectAs(projects + QStringLiteral("/tbar.multidir")));

  EXPECT_EQ(dialogStartFolder([this] { action(QStringLiteral("openModel"))->trigger(); }), models)
      << "File > Open should look where models were opened from";
  EXPECT_EQ(dialogStartFolder([this] { action(QStringLiteral("openProject"))->trigger(); }), projects)
      << "File > Open Project should look where the project was saved";
}

TEST_F(StudioFileMenu, HelpAboutNamesTheVersion) {
  QAction* about = action(QStringLiteral("about"));
  ASSERT_NE(about, nullptr) << "there is no Help > About";
  about->trigger();
  QMessageBox* box = test::waitForMessageBox(m_window, QStringLiteral("aboutBox"));
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->text().contains(studioVersion())) << box->text().toStdString();
  box->close();
}

}  // namespace
}  // namespace multidir::ui
