// GUI tests need a QApplication (and VTK's OpenGL 3.2 core surface format) before any widget exists.
// They need a real X display with OpenGL: ctest runs them under xvfb-run (Mesa). Qt's offscreen platform
// has no OpenGL for QOpenGLWidget (Qt 6.4 crashes flushing such a window), so there is no fallback to it.
#include <gtest/gtest.h>

#include <QApplication>

#include "ui/studio_startup.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  multidir::ui::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("MultiDir Studio tests"));
  QApplication::setOrganizationName(QStringLiteral("MultiDir"));
  return RUN_ALL_TESTS();
}
