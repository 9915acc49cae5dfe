// GUI tests need a QApplication (and VTK's OpenGL 3.2 core surface format) before any widget exists.
// They need a real X display with OpenGL: ctest runs them under xvfb-run (Mesa). Qt's offscreen platform
// has no OpenGL for QOpenGLWidget (Qt 6.4 crashes flushing such a window), so there is no fallback to it.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>

#include "ui/studio_startup.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  // Settings, autosaves and recent files go to a test folder (~/.qttest), never the user's own.
  QStandardPaths::setTestModeEnabled(true);
  multidir::ui::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  // One settings file and data folder per process: ctest runs tests side by side, and tests of settings, recent
  // files and autosaves must not see each other's. Both are removed when the tests end.
  QApplication::setApplicationName(QStringLiteral("MultiDir Studio tests %1").arg(QCoreApplication::applicationPid()));
  QApplication::setOrganizationName(QStringLiteral("MultiDir"));
  // Tests close windows without running the application's event loop; closing one must not end the others.
  QApplication::setQuitOnLastWindowClosed(false);
  const int result = RUN_ALL_TESTS();
  QFile::remove(QSettings().fileName());
  QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
  return result;
}
