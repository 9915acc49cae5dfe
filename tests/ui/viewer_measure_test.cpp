// The measuring tool (View > Measure distance): two clicks on the model give both points in the model's
// coordinates and the distance between them, drawn as a line with its length; Esc leaves the tool.
#include <gtest/gtest.h>

#include <QAction>
#include <QImage>
#include <QSignalSpy>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <optional>

#include "support/primitives.h"
#include "ui/main_window.h"
#include "ui/picture_census.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"
#include "ui/viewer/plan_geometry.h"

namespace multidir::ui {
namespace {

// A box 40 x 20 x 10 mm, not at the origin, so a point given in the wrong frame is seen.
const core::Vec3 kBoxMin(12.0, -7.0, 3.0);
const core::Vec3 kBoxMax(52.0, 13.0, 13.0);

// The viewer shows the box from the front, orthographic, so every click on its front face (y = kBoxMin.y)
// lands where the picture shows it.
void showBox(MeshViewerWidget& viewer) {
  viewer.resize(800, 600);
  viewer.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewer));
  viewer.setMesh(test::makeBox(kBoxMin, kBoxMax), core::Vec3::UnitZ());
  viewer.setStandardView(StandardView::Front);
  viewer.setOrthographic(true);
  viewer.grabFramebuffer();  // the framing is applied on the first frame
}

// Clicks (press and release without moving) at the pixel where `point` is drawn.
void clickAt(MeshViewerWidget& viewer, const core::Vec3& point) {
  const std::optional<QPointF> at = viewer.widgetPositionOf(point);
  ASSERT_TRUE(at.has_value());
  QTest::mouseClick(&viewer, Qt::LeftButton, Qt::NoModifier, at->toPoint());
}

// Half a pixel of this view, in mm: the box (40 mm) fills well over 200 pixels.
constexpr double kPickToleranceMm = 0.2;

void expectNear(const core::Vec3& actual, const core::Vec3& expected) {
  EXPECT_LT((actual - expected).norm(), kPickToleranceMm)
      << "picked (" << actual.x() << ", " << actual.y() << ", " << actual.z() << ")";
}

TEST(StudioMeasure, TwoClicksOnTheModelGiveBothPointsAndTheirDistance) {
  MeshViewerWidget viewer;
  ASSERT_NO_FATAL_FAILURE(showBox(viewer));
  viewer.setMeasuring(true);
  const core::Vec3 a(17.0, kBoxMin.y(), 5.0);
  const core::Vec3 b(47.0, kBoxMin.y(), 11.0);
  ASSERT_NO_FATAL_FAILURE(clickAt(viewer, a));
  ASSERT_TRUE(viewer.measurement().first.has_value());
  EXPECT_FALSE(viewer.measurement().second.has_value());
  expectNear(*viewer.measurement().first, a);
  ASSERT_NO_FATAL_FAILURE(clickAt(viewer, b));
  ASSERT_TRUE(viewer.measurement().complete());
  expectNear(*viewer.measurement().second, b);
  // |(30, 0, 6)| = 30.594 mm.
  EXPECT_NEAR(*viewer.measurement().distanceMm(), std::hypot(30.0, 6.0), 2 * kPickToleranceMm);
  EXPECT_EQ(viewer.measureMarkersShown(), 2);
  EXPECT_TRUE(viewer.measureLineShown());
}

TEST(StudioMeasure, TheLineAndItsLabelAreDrawn) {
  MeshViewerWidget viewer;
  ASSERT_NO_FATAL_FAILURE(showBox(viewer));
  const QColor cyan(51, 242, 242);
  EXPECT_LT(test::colourFraction(viewer.grabFramebuffer(), cyan, 0.99), 0.0001);
  viewer.setMeasuring(true);
  ASSERT_NO_FATAL_FAILURE(clickAt(viewer, core::Vec3(17.0, kBoxMin.y(), 8.0)));
  ASSERT_NO_FATAL_FAILURE(clickAt(viewer, core::Vec3(47.0, kBoxMin.y(), 8.0)));
  EXPECT_GT(test::colourFraction(viewer.grabFramebuffer(), cyan, 0.99), 0.001);
}

TEST(StudioMeasure, AClickBesideTheModelPicksNothing) {
  MeshViewerWidget viewer;
  ASSERT_NO_FATAL_FAILURE(showBox(viewer));
  viewer.setMeasuring(true);
  QTest::mouseClick(&viewer, Qt::LeftButton, Qt::NoModifier, QPoint(5, 5));
  EXPECT_FALSE(viewer.measurement().first.has_value());
  EXPECT_EQ(viewer.measureMarkersShown(), 0);
}

TEST(StudioMeasure, AThirdClickStartsANewMeasurement) {
  MeshViewerWidget viewer;
  ASSERT_NO_FATAL_FAILURE(showBox(viewer));
  viewer.setMeasuring(true);
  const core::Vec3 c(30.0, kBoxMin.y(), 9.0);
  ASSERT_NO_FATAL_FAILURE(clickAt(viewer, core::Vec3(17.0, kBoxMin.y(), 5.0)));
  ASSERT_NO_FATAL_FAILURE(clickAt(viewer, core::Vec3(47.0, kBoxMin.y(), 5.0)));
  ASSERT_NO_FATAL_FAILURE(clickAt(viewer, c));
  ASSERT_TRUE(viewer.measurement().first.has_value());
  expectNear(*viewer.measurement().first, c);
  EXPECT_FALSE(viewer.measurement().second.has_value());
  EXPECT_EQ(viewer.measureMarkersShown(), 1);
}

TEST(StudioMeasure, EscLeavesMeasuringFromTheViewMenu) {
  MainWindow window;
  test::showDefaultSample(window, QSize(1200, 800));
  QAction* measure = window.findChild<QAction*>(QStringLiteral("measureDistance"));
  ASSERT_NE(measure, nullptr);
  MeshViewerWidget* viewer = window.viewer();
  measure->trigger();
  EXPECT_TRUE(viewer->isMeasuring());
  viewer->grabFramebuffer();
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, viewer->rect().center());
  EXPECT_TRUE(viewer->measurement().first.has_value()) << "the default sample fills the view's middle";
  viewer->setFocus();
  QTest::keyClick(viewer, Qt::Key_Escape);
  EXPECT_FALSE(viewer->isMeasuring());
  EXPECT_FALSE(measure->isChecked());
  EXPECT_FALSE(viewer->measurement().first.has_value());
  EXPECT_EQ(viewer->measureMarkersShown(), 0);
}

// The distance from `p` to the triangle (a, b, c) (Ericson, "Real-Time Collision Detection", 5.1.5).
double distanceToTriangle(const core::Vec3& p, const core::Vec3& a, const core::Vec3& b, const core::Vec3& c) {
  const core::Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const core::Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const core::Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denominator = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).norm();
}

double distanceToSurface(const core::Vec3& p, const core::TriangleMesh& mesh) {
  double nearest = 1e300;
  for (const core::Triangle& t : mesh.triangles)
    nearest = std::min(nearest, distanceToTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
  return nearest;
}

// In the exploded plan view a region is drawn away from where it is in the model; the picked point is still
// given where it is on the model (its region's surface), not where it is drawn.
TEST(StudioMeasure, PickedPointsAreInTheModelsFrameInTheExplodedPlanView) {
  MainWindow window;
  test::showDefaultSample(window, QSize(1200, 800));
  const SearchRun run = test::runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  ASSERT_GE(run.plan->regions.size(), 2u);
  MeshViewerWidget* viewer = window.viewer();
  constexpr double kExplodeMm = 30.0;
  viewer->setExplodeDistance(kExplodeMm);
  viewer->setStandardView(StandardView::Front);
  viewer->grabFramebuffer();
  // The middle of the last region, where it is drawn: moved by its explode offset.
  const core::Region& last = run.plan->regions.back();
  core::Vec3 middle = core::Vec3::Zero();
  for (const core::Vec3& v : last.mesh.vertices) middle += v;
  middle /= static_cast<double>(last.mesh.vertices.size());
  const core::Vec3 offset = explodeOffsets(*run.plan, kExplodeMm).back();
  ASSERT_GT(offset.norm(), 1.0);
  const std::optional<QPointF> drawn = viewer->widgetPositionOf(middle + offset);
  ASSERT_TRUE(drawn.has_value());
  const std::optional<core::Vec3> picked = viewer->modelPointAt(*drawn);
  ASSERT_TRUE(picked.has_value());
  double nearest = 1e300;
  for (const core::Region& region : run.plan->regions) nearest = std::min(nearest, distanceToSurface(*picked, region.mesh));
  EXPECT_LT(nearest, 0.01) << "the picked point is " << nearest << " mm from every region's surface";
}

}  // namespace
}  // namespace multidir::ui
