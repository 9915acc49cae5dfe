// A project opened at start-up (multidir-studio kitten.multidir) is shown with its own up direction, like one
// opened from File > Open Project (issue 11, item 10): the view, the status bar and the Up box agree.
#include <gtest/gtest.h>

#include <QLabel>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include "ui/main_window.h"
#include "ui/project/project_session.h"
#include "ui/studio_startup.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

QString riskyAreaStatus(const MainWindow& window) {
  for (const QLabel* label : window.statusBar()->findChildren<QLabel*>()) {
    if (label->text().startsWith(QStringLiteral("Risky area"))) return label->text();
  }
  return {};
}

TEST(StudioStartupProject, ProjectGivenOnTheCommandLineIsShownWithItsOwnUpDirection) {
  test::resetStudioSettings();
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString project = dir.filePath(QStringLiteral("tbar.multidir"));
  {
    MainWindow window;
    ASSERT_NO_FATAL_FAILURE(test::openModelFile(window, test::writeTBar(dir, QStringLiteral("tbar.off"))));
    window.setUpDirection(core::Vec3::UnitY());
    ASSERT_TRUE(window.projectSession()->saveProjectAs(project));
  }

  MainWindow window;
  window.resize(1000, 700);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  StudioOptions options;
  options.modelPath = project;
  ASSERT_NO_FATAL_FAILURE(test::waitProjectOpened(window.projectSession(), [&] {
    startStudio(window, options);
    return true;
  }));
  EXPECT_TRUE(window.upDirection().isApprox(core::Vec3::UnitY()));
  window.viewer()->grabFramebuffer();  // a rendered frame after the fit
  EXPECT_TRUE(window.viewer()->viewUp().isApprox(core::Vec3::UnitY(), 1e-9))
      << "the model is drawn with another up than the Up box says";
  const QString status = riskyAreaStatus(window);
  EXPECT_TRUE(status.contains(QStringLiteral("+Y up"))) << status.toStdString();
  test::resetStudioSettings();
}

}  // namespace
}  // namespace multidir::ui
