// The studio's main window and start-up: what opens, what errors look like, the --screenshot mode.
#include <gtest/gtest.h>

#include <QDir>
#include <QImage>
#include <QLabel>
#include <QMessageBox>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/samples/samples.h"
#include "support/test_models.h"
#include "ui/common/error_text.h"
#include "ui/main_window.h"
#include "ui/picture_census.h"
#include "ui/studio_startup.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

constexpr int kLoadTimeoutMs = 120000;

QString shared(const std::string& name) { return QString::fromStdString(test::sharedModelPath(name)); }

TEST(StudioStartup, ModelAndUpFromTheCommandLineAreOpened) {
  const QString kitten = shared("kitten.off");
  const StudioCommandLine commandLine =
      parseStudioCommandLine({QStringLiteral("multidir-studio"), kitten, QStringLiteral("--up"), QStringLiteral("y")});
  ASSERT_FALSE(commandLine.exitNow) << commandLine.text.toStdString();

  MainWindow window;
  window.show();
  QSignalSpy shown(&window, &MainWindow::modelShown);
  startStudio(window, commandLine.options);
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs));

  ASSERT_TRUE(window.hasModel());
  EXPECT_EQ(window.model()->name, QStringLiteral("kitten.off"));
  EXPECT_EQ(window.model()->sourcePath, kitten);
  EXPECT_TRUE(window.upDirection().isApprox(core::Vec3::UnitY()));
  const core::Result<core::LoadedMesh> direct = core::loadMesh(kitten.toStdString());
  ASSERT_TRUE(direct.ok());
  EXPECT_EQ(window.model()->mesh->faceCount(), direct->mesh.faceCount());
  EXPECT_TRUE(window.viewer()->hasMesh());
  EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("kitten.off")));
  // The status bar names the file and counts its triangles.
  QStringList labels;
  for (const QLabel* label : window.statusBar()->findChildren<QLabel*>()) labels << label->text();
  const QString status = labels.join(QLatin1Char('|'));
  EXPECT_TRUE(status.contains(QStringLiteral("kitten.off"))) << status.toStdString();
  EXPECT_TRUE(status.contains(QLocale().toString(static_cast<qulonglong>(direct->mesh.faceCount()))))
      << status.toStdString();
}

TEST(StudioStartup, WithoutArgumentsNothingIsForcedAndUpIsUnset) {
  const StudioCommandLine commandLine = parseStudioCommandLine({QStringLiteral("multidir-studio")});
  EXPECT_FALSE(commandLine.exitNow);
  EXPECT_TRUE(commandLine.options.modelPath.isEmpty());
  EXPECT_FALSE(commandLine.options.up.has_value());
  EXPECT_TRUE(commandLine.options.screenshotPath.isEmpty());
}

TEST(StudioStartup, UnreadableUpDirectionIsAUsageError) {
  const StudioCommandLine commandLine = parseStudioCommandLine(
      {QStringLiteral("multidir-studio"), QStringLiteral("model.off"), QStringLiteral("--up"), QStringLiteral("sideways")});
  EXPECT_TRUE(commandLine.exitNow);
  EXPECT_EQ(commandLine.exitCode, 2);
  EXPECT_TRUE(commandLine.text.contains(QStringLiteral("--up"))) << commandLine.text.toStdString();
}

TEST(StudioStartup, TwoModelsAreAUsageError) {
  const StudioCommandLine commandLine =
      parseStudioCommandLine({QStringLiteral("multidir-studio"), QStringLiteral("a.off"), QStringLiteral("b.off")});
  EXPECT_TRUE(commandLine.exitNow);
  EXPECT_EQ(commandLine.exitCode, 2);
}

TEST(StudioWindow, DefectiveFileKeepsTheCurrentModelAndReportsTheError) {
  MainWindow window;
  window.show();
  QSignalSpy shown(&window, &MainWindow::modelShown);
  startStudio(window, StudioOptions{});
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs));
  const QString before = window.model()->name;
  const std::size_t facesBefore = window.model()->mesh->faceCount();

  QSignalSpy failed(&window, &MainWindow::loadFailed);
  window.openFile(shared("defective/halftunnel-open.off"));
  EXPECT_TRUE(window.isLoading());
  ASSERT_TRUE(failed.wait(kLoadTimeoutMs));
  EXPECT_FALSE(window.isLoading());

  ASSERT_TRUE(window.hasModel());
  EXPECT_EQ(window.model()->name, before);
  EXPECT_EQ(window.model()->mesh->faceCount(), facesBefore);
  EXPECT_TRUE(window.viewer()->hasMesh());
  const QString status = window.statusBar()->currentMessage();
  EXPECT_TRUE(status.contains(QStringLiteral("halftunnel-open.off"))) << status.toStdString();
  EXPECT_EQ(failed.front().front().toString(), status);
  // The message box is shown without blocking the window.
  auto* box = window.findChild<QMessageBox*>(QStringLiteral("loadErrorBox"));
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->isVisible());
  EXPECT_FALSE(box->isModal());
  // A translated headline for the kind of defect, core's detail below it, and what is still open.
  EXPECT_EQ(box->text(), errorHeadline(core::ErrorCode::OpenBoundary));
  EXPECT_TRUE(box->informativeText().contains(QStringLiteral("halftunnel-open.off")))
      << box->informativeText().toStdString();
  EXPECT_TRUE(box->informativeText().contains(before)) << box->informativeText().toStdString();
  box->close();
}

TEST(StudioWindow, MissingFileIsReportedAndNothingIsLost) {
  MainWindow window;
  window.show();
  QSignalSpy failed(&window, &MainWindow::loadFailed);
  window.openFile(QDir::temp().filePath(QStringLiteral("multidir-no-such-model.stl")));
  ASSERT_TRUE(failed.wait(kLoadTimeoutMs));
  EXPECT_FALSE(window.hasModel());
  EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("multidir-no-such-model.stl")));
}

TEST(StudioWindow, SamplesMenuHasOneEntryPerSample) {
  MainWindow window;
  for (const core::samples::SampleInfo& info : core::samples::catalogue()) {
    EXPECT_NE(window.findChild<QAction*>(QStringLiteral("sample-") + QString::fromStdString(info.id)), nullptr)
        << info.id;
  }
}

TEST(StudioStartup, ScreenshotShowsTheModelInTheWindow) {
  const QString path =
      QDir(QString::fromStdString(test::scratchDirectory("ScreenshotShowsTheModel"))).filePath(QStringLiteral("shot.png"));
  MainWindow window;
  window.resize(900, 700);
  window.show();
  startStudio(window, StudioOptions{});
  QString error;
  ASSERT_EQ(saveScreenshotWhenReady(window, path, &error), 0) << error.toStdString();
  QImage shot(path);
  ASSERT_FALSE(shot.isNull());
  EXPECT_EQ(shot.size(), window.size() * window.devicePixelRatio());
  EXPECT_GT(test::census(shot).modelFraction, 0.01);
}

}  // namespace
}  // namespace multidir::ui
