// The 3D view, checked by its pixels under Xvfb (Mesa): what a person would see.
#include <gtest/gtest.h>

#include <QImage>
#include <algorithm>
#include <QTest>
#include <QWheelEvent>

#include "multidir/core/samples/samples.h"
#include "support/test_models.h"
#include "ui/main_window.h"
#include "ui/picture_census.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

void showDefaultSample(MainWindow& window) { test::showDefaultSample(window, QSize(1000, 760)); }

TEST(StudioViewer, EmptyViewShowsBackgroundButNoModel) {
  MeshViewerWidget viewer;
  viewer.resize(640, 480);
  viewer.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewer));
  const QImage picture = viewer.grabFramebuffer();
  ASSERT_FALSE(picture.isNull());
  const test::PictureCensus whole = test::census(picture);
  EXPECT_LT(whole.modelFraction, 0.001);
  // Everything but the axes marker in the corner is background.
  EXPECT_GT(whole.backgroundFraction, 0.95);
  EXPECT_GT(test::census(picture, test::centreOf(picture)).backgroundFraction, 0.99);
}

TEST(StudioViewer, DefaultSampleIsDrawnInTheMiddleOfTheView) {
  MainWindow window;
  showDefaultSample(window);
  ASSERT_TRUE(window.viewer()->hasMesh());

  const QImage picture = window.viewer()->grabFramebuffer();
  ASSERT_FALSE(picture.isNull());
  ASSERT_GT(picture.width(), 400);
  const test::PictureCensus whole = test::census(picture);
  EXPECT_GT(whole.modelFraction, 0.02) << "too few pixels in the model's shade";
  const test::PictureCensus centre = test::census(picture, test::centreOf(picture));
  EXPECT_LT(centre.backgroundFraction, 0.2) << "the centre of the view is background";
}

TEST(StudioViewer, PlatformIsDrawnUnderTheModel) {
  MainWindow window;
  showDefaultSample(window);
  const QImage picture = window.viewer()->grabFramebuffer();
  ASSERT_FALSE(picture.isNull());
  // The sample stands on +Z, which is up on screen: below the lowest model pixel of the middle column
  // come platform pixels (neither background nor model shade).
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  const int x = image.width() / 2;
  int lowestModelRow = -1;
  for (int y = 0; y < image.height(); ++y) {
    if (test::isModelShade(image.pixel(x, y), y, image.height())) lowestModelRow = y;
  }
  ASSERT_GE(lowestModelRow, 0) << "no model in the middle column";
  int platformRows = 0;
  const int below = std::min(image.height(), lowestModelRow + 1 + image.height() / 10);
  for (int y = lowestModelRow + 1; y < below; ++y) {
    const QRgb pixel = image.pixel(x, y);
    if (!test::isBackground(pixel, y, image.height()) && !test::isModelShade(pixel, y, image.height())) ++platformRows;
  }
  EXPECT_GT(platformRows, image.height() / 25);
}

TEST(StudioViewer, ChangingTheUpDirectionRedrawsTheView) {
  MainWindow window;
  showDefaultSample(window);
  const QImage before = window.viewer()->grabFramebuffer();
  window.setUpDirection(core::Vec3::UnitX());
  EXPECT_TRUE(window.upDirection().isApprox(core::Vec3::UnitX()));
  const QImage after = window.viewer()->grabFramebuffer();
  ASSERT_EQ(before.size(), after.size());
  EXPECT_NE(before, after);
  EXPECT_GT(test::census(after).modelFraction, 0.02);
}

TEST(StudioViewer, LeftDragOrbitsAndWheelZooms) {
  MainWindow window;
  showDefaultSample(window);
  MeshViewerWidget* viewer = window.viewer();
  const QImage start = viewer->grabFramebuffer();
  const QPoint centre = viewer->rect().center();

  QTest::mousePress(viewer, Qt::LeftButton, Qt::NoModifier, centre);
  for (int step = 1; step <= 10; ++step) QTest::mouseMove(viewer, centre + QPoint(15 * step, 0));
  QTest::mouseRelease(viewer, Qt::LeftButton, Qt::NoModifier, centre + QPoint(150, 0));
  const QImage orbited = viewer->grabFramebuffer();
  EXPECT_NE(start, orbited);

  // Zooming in makes the model cover more of the view.
  const double coverBefore = test::census(orbited).modelFraction;
  for (int notch = 0; notch < 3; ++notch) {
    QWheelEvent wheel(QPointF(centre), viewer->mapToGlobal(QPointF(centre)), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(viewer, &wheel);
  }
  EXPECT_GT(test::census(viewer->grabFramebuffer()).modelFraction, 1.1 * coverBefore);

  // Fit view brings the first framing back.
  viewer->fitView();
  const double coverFitted = test::census(viewer->grabFramebuffer()).modelFraction;
  EXPECT_NEAR(coverFitted, test::census(start).modelFraction, 0.01);
}

}  // namespace
}  // namespace multidir::ui
