// File > Export Screenshot: the 3D view as shown, saved as PNG or JPEG by the file name's extension, with
// errors in the status bar.
#include <gtest/gtest.h>

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>
#include <QStatusBar>

#include "support/test_models.h"
#include "ui/main_window.h"
#include "ui/picture_census.h"
#include "ui/common/picture_file.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

void showDefaultSample(MainWindow& window) { test::showDefaultSample(window, QSize(1100, 800)); }

QString scratchFile(const std::string& test, const QString& name) {
  return QDir(QString::fromStdString(test::scratchDirectory(test))).filePath(name);
}

TEST(StudioScreenshot, FileMenuOffersIt) {
  MainWindow window;
  EXPECT_NE(window.findChild<QAction*>(QStringLiteral("exportScreenshot")), nullptr);
}

TEST(StudioScreenshot, PngHasTheViewersSizeAndShowsTheModel) {
  MainWindow window;
  showDefaultSample(window);
  const QString path = scratchFile("StudioScreenshotPng", QStringLiteral("view.png"));
  QString error;
  ASSERT_TRUE(window.exportScreenshot(path, &error)) << error.toStdString();
  QImageReader reader(path);
  EXPECT_EQ(reader.format(), QByteArray("png"));
  const QImage saved = reader.read();
  ASSERT_FALSE(saved.isNull()) << reader.errorString().toStdString();
  MeshViewerWidget* viewer = window.viewer();
  EXPECT_EQ(saved.size(), viewer->size() * viewer->devicePixelRatio());
  EXPECT_GT(test::census(saved).modelFraction, 0.02);
  EXPECT_TRUE(window.statusBar()->currentMessage().contains(path)) << window.statusBar()->currentMessage().toStdString();
}

TEST(StudioScreenshot, JpegIsChosenByTheExtension) {
  MainWindow window;
  showDefaultSample(window);
  const QString path = scratchFile("StudioScreenshotJpeg", QStringLiteral("view.JPG"));
  QString error;
  ASSERT_TRUE(window.exportScreenshot(path, &error)) << error.toStdString();
  QImageReader reader(path);
  EXPECT_EQ(reader.format(), QByteArray("jpeg"));
  const QImage saved = reader.read();
  ASSERT_FALSE(saved.isNull());
  EXPECT_EQ(saved.size(), window.viewer()->size() * window.viewer()->devicePixelRatio());
}

TEST(StudioScreenshot, UnwritablePathIsReportedInTheStatusBar) {
  MainWindow window;
  showDefaultSample(window);
  const QString path = scratchFile("StudioScreenshotUnwritable", QStringLiteral("no-such-folder/view.png"));
  QString error;
  EXPECT_FALSE(window.exportScreenshot(path, &error));
  EXPECT_FALSE(QFileInfo::exists(path));
  EXPECT_TRUE(error.contains(path)) << error.toStdString();
  EXPECT_TRUE(error.contains(QStringLiteral("folder"))) << error.toStdString();
  EXPECT_EQ(window.statusBar()->currentMessage(), error);
}

TEST(StudioScreenshot, OtherExtensionsAreRefusedWithTheOnesThatWork) {
  MainWindow window;
  showDefaultSample(window);
  const QString path = scratchFile("StudioScreenshotBmp", QStringLiteral("view.bmp"));
  QString error;
  EXPECT_FALSE(window.exportScreenshot(path, &error));
  EXPECT_FALSE(QFileInfo::exists(path));
  EXPECT_TRUE(error.contains(QStringLiteral(".png"))) << error.toStdString();
  EXPECT_FALSE(isPictureFileName(path));
  EXPECT_TRUE(isPictureFileName(QStringLiteral("a/b.Png")));
  EXPECT_TRUE(isPictureFileName(QStringLiteral("b.jpeg")));
}

TEST(PictureFile, NullPictureIsNotSaved) {
  const QString path = scratchFile("PictureFileNull", QStringLiteral("empty.png"));
  QString error;
  EXPECT_FALSE(savePicture(QImage(), path, &error));
  EXPECT_FALSE(QFileInfo::exists(path));
  EXPECT_FALSE(error.isEmpty());
}

}  // namespace
}  // namespace multidir::ui
