// The 3D view's standard views, its orthographic toggle, the axes marker of an empty session and the hint
// an empty view shows: what a person sees and what the View menu and its shortcuts do.
#include <gtest/gtest.h>

#include <QAction>
#include <QImage>
#include <QTest>
#include <cmath>
#include <string>
#include <optional>

#include "support/primitives.h"
#include "ui/main_window.h"
#include "ui/picture_census.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

void showDefaultSample(MainWindow& window) { test::showDefaultSample(window, QSize(1200, 800)); }

QAction* action(const MainWindow& window, const char* name) {
  return window.findChild<QAction*>(QString::fromLatin1(name));
}

void expectDirection(const core::Vec3& actual, const core::Vec3& expected) {
  EXPECT_GT(actual.dot(expected), 0.999) << "looks along (" << actual.x() << ", " << actual.y() << ", " << actual.z()
                                          << ")";
}

TEST(StudioStandardViews, EachViewLooksAtTheModelFromItsSideRelativeToUp) {
  MainWindow window;
  showDefaultSample(window);
  MeshViewerWidget* viewer = window.viewer();
  const struct {
    const char* action;
    core::Vec3 looksAlong;
    core::Vec3 screenUp;
  } views[] = {
      {"viewFront", core::Vec3::UnitY(), core::Vec3::UnitZ()},  {"viewBack", -core::Vec3::UnitY(), core::Vec3::UnitZ()},
      {"viewRight", -core::Vec3::UnitX(), core::Vec3::UnitZ()}, {"viewLeft", core::Vec3::UnitX(), core::Vec3::UnitZ()},
      {"viewTop", -core::Vec3::UnitZ(), core::Vec3::UnitY()},   {"viewBottom", core::Vec3::UnitZ(), -core::Vec3::UnitY()},
  };
  for (const auto& view : views) {
    SCOPED_TRACE(view.action);
    QAction* trigger = action(window, view.action);
    ASSERT_NE(trigger, nullptr);
    trigger->trigger();
    const QImage picture = viewer->grabFramebuffer();
    expectDirection(viewer->cameraDirection(), view.looksAlong);
    expectDirection(viewer->cameraUp(), view.screenUp);
    // From below, the platform covers the model's bottom.
    if (std::string(view.action) != "viewBottom") {
      EXPECT_GT(test::census(picture).modelFraction, 0.02) << "the model left the view";
    }
  }
  action(window, "viewIso")->trigger();
  viewer->grabFramebuffer();
  // From the front (-Y), the right (+X) and above (+Z).
  expectDirection(viewer->cameraDirection(), -core::Vec3(1.0, -1.0, 1.0).normalized());
}

TEST(StudioStandardViews, TopFollowsTheUpDirection) {
  MainWindow window;
  showDefaultSample(window);
  window.setUpDirection(core::Vec3::UnitX());
  action(window, "viewTop")->trigger();
  window.viewer()->grabFramebuffer();
  expectDirection(window.viewer()->cameraDirection(), -core::Vec3::UnitX());
}

TEST(StudioStandardViews, KeypadAndDigitShortcutsSwitchViews) {
  MainWindow window;
  showDefaultSample(window);
  MeshViewerWidget* viewer = window.viewer();
  window.activateWindow();  // shortcuts reach the active window only
  ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
  viewer->setFocus();
  QTest::keyClick(viewer, Qt::Key_7);
  viewer->grabFramebuffer();
  expectDirection(viewer->cameraDirection(), -core::Vec3::UnitZ());
  QTest::keyClick(viewer, Qt::Key_1, Qt::KeypadModifier);
  viewer->grabFramebuffer();
  expectDirection(viewer->cameraDirection(), core::Vec3::UnitY());
  QTest::keyClick(viewer, Qt::Key_7, Qt::ControlModifier);
  viewer->grabFramebuffer();
  expectDirection(viewer->cameraDirection(), core::Vec3::UnitZ());
}

// The rows of the model's shade in the column through `point` (its middle, as the view shows it).
int modelRowsAt(const MeshViewerWidget& viewer, const QImage& picture, const core::Vec3& point) {
  const std::optional<QPointF> at = viewer.widgetPositionOf(point);
  if (!at) return 0;
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  const int x = static_cast<int>(std::lround(at->x() * image.devicePixelRatio()));
  int rows = 0;
  for (int y = 0; y < image.height(); ++y)
    if (test::isModelShade(image.pixel(x, y), y, image.height())) ++rows;
  return rows;
}

// Two equal cubes, one 100 mm nearer the camera than the other, side by side: seen from the front in a
// parallel projection they are drawn equally tall; in perspective the nearer is drawn taller.
TEST(StudioStandardViews, OrthographicDrawsEqualCubesEquallyTallWhateverTheirDepth) {
  MeshViewerWidget viewer;
  viewer.resize(800, 600);
  viewer.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewer));
  core::TriangleMesh cubes = test::makeBox(core::Vec3(-40.0, -60.0, 0.0), core::Vec3(-20.0, -40.0, 20.0));
  const core::TriangleMesh far = test::makeBox(core::Vec3(20.0, 40.0, 0.0), core::Vec3(40.0, 60.0, 20.0));
  const auto base = static_cast<std::int32_t>(cubes.vertices.size());
  cubes.vertices.insert(cubes.vertices.end(), far.vertices.begin(), far.vertices.end());
  for (const core::Triangle& t : far.triangles) cubes.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  cubes.resetOrigins();
  viewer.setMesh(cubes, core::Vec3::UnitZ());
  viewer.setStandardView(StandardView::Front);
  const core::Vec3 nearFront(-30.0, -60.0, 10.0);
  const core::Vec3 farFront(30.0, 40.0, 10.0);

  const QImage perspective = viewer.grabFramebuffer();
  const int nearRows = modelRowsAt(viewer, perspective, nearFront);
  const int farRows = modelRowsAt(viewer, perspective, farFront);
  ASSERT_GT(farRows, 20);
  EXPECT_GT(nearRows, farRows + farRows / 20) << "perspective: near " << nearRows << ", far " << farRows;

  viewer.setOrthographic(true);
  EXPECT_TRUE(viewer.isOrthographic());
  const QImage parallel = viewer.grabFramebuffer();
  const int nearParallel = modelRowsAt(viewer, parallel, nearFront);
  const int farParallel = modelRowsAt(viewer, parallel, farFront);
  ASSERT_GT(farParallel, 20);
  EXPECT_LE(std::abs(nearParallel - farParallel), 2) << "parallel: near " << nearParallel << ", far " << farParallel;
  // The framing stays: the cubes keep about their size on screen.
  EXPECT_NEAR(double(farParallel) / farRows, 1.0, 0.3);
}

TEST(StudioStandardViews, OrthographicActionTogglesTheProjection) {
  MainWindow window;
  showDefaultSample(window);
  QAction* orthographic = action(window, "orthographicView");
  ASSERT_NE(orthographic, nullptr);
  const QImage before = window.viewer()->grabFramebuffer();
  window.activateWindow();  // shortcuts reach the active window only
  ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
  orthographic->trigger();
  EXPECT_TRUE(window.viewer()->isOrthographic());
  const QImage after = window.viewer()->grabFramebuffer();
  EXPECT_NE(before, after);
  const double coverBefore = test::census(before).modelFraction;
  EXPECT_NEAR(test::census(after).modelFraction, coverBefore, 0.3 * coverBefore);
  QTest::keyClick(window.viewer(), Qt::Key_5);
  EXPECT_FALSE(window.viewer()->isOrthographic());
  EXPECT_FALSE(orthographic->isChecked());
}

// The axes marker (vtkAxesActor, bottom left) draws X red, Y green, Z blue. The mean row of `axis`'s pixels in
// the marker's corner (rows grow downwards); -1 when it is not drawn.
double meanAxisRow(const QImage& picture, const QColor& axis) {
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  const QRect corner(0, image.height() - image.height() / 4, image.width() / 4, image.height() / 4);
  double rows = 0.0;
  int count = 0;
  for (int y = corner.top(); y <= corner.bottom(); ++y)
    for (int x = corner.left(); x <= corner.right(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (std::abs(c.red() - axis.red()) < 80 && std::abs(c.green() - axis.green()) < 80 &&
          std::abs(c.blue() - axis.blue()) < 80) {
        rows += y;
        ++count;
      }
    }
  return count < 10 ? -1.0 : rows / count;
}

const QColor kMarkerX(220, 0, 0);
const QColor kMarkerY(0, 200, 0);
const QColor kMarkerZ(0, 0, 220);

// The empty session's Up is +Z: the marker shows Z pointing up on screen (VTK's own default camera shows Y up).
TEST(StudioStandardViews, EmptySessionAxesMarkerShowsUpUp) {
  MeshViewerWidget viewer;
  viewer.resize(800, 600);
  viewer.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewer));
  const QImage zUp = viewer.grabFramebuffer();
  // The camera looks a little down: what points up on screen is Z, tilted towards the viewer.
  EXPECT_GT(viewer.cameraUp().dot(core::Vec3::UnitZ()), 0.9);
  const double zRow = meanAxisRow(zUp, kMarkerZ);
  ASSERT_GE(zRow, 0.0) << "no Z axis drawn";
  EXPECT_LT(zRow, meanAxisRow(zUp, kMarkerX) - 10.0);
  EXPECT_LT(zRow, meanAxisRow(zUp, kMarkerY) - 10.0);

  viewer.setEmptyUp(core::Vec3::UnitX());
  const QImage xUp = viewer.grabFramebuffer();
  EXPECT_GT(viewer.cameraUp().dot(core::Vec3::UnitX()), 0.9);
  const double xRow = meanAxisRow(xUp, kMarkerX);
  ASSERT_GE(xRow, 0.0) << "no X axis drawn";
  EXPECT_LT(xRow, meanAxisRow(xUp, kMarkerY) - 10.0);
  EXPECT_LT(xRow, meanAxisRow(xUp, kMarkerZ) - 10.0);
}

// In the studio, an empty session's marker follows the Up box.
TEST(StudioStandardViews, EmptySessionAxesMarkerFollowsTheUpBox) {
  MainWindow window;
  window.resize(1200, 800);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_FALSE(window.hasModel());
  window.setUpDirection(-core::Vec3::UnitY());
  window.viewer()->grabFramebuffer();
  EXPECT_GT(window.viewer()->cameraUp().dot(-core::Vec3::UnitY()), 0.9);
}

TEST(StudioStandardViews, EmptyViewShowsTheOpenHintUntilAModelIsShown) {
  MeshViewerWidget viewer;
  viewer.resize(640, 480);
  viewer.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewer));
  EXPECT_TRUE(viewer.isEmptyHintShown());
  EXPECT_TRUE(viewer.emptyHintText().contains(QStringLiteral("Ctrl+O"))) << viewer.emptyHintText().toStdString();
  EXPECT_TRUE(viewer.emptyHintText().contains(QStringLiteral("Samples")));
  viewer.setMesh(test::makeBox(core::Vec3::Zero(), core::Vec3(10.0, 10.0, 10.0)), core::Vec3::UnitZ());
  EXPECT_FALSE(viewer.isEmptyHintShown());
  viewer.clear();
  EXPECT_TRUE(viewer.isEmptyHintShown());
}

}  // namespace
}  // namespace multidir::ui
