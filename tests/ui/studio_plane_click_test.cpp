// Selecting a clipping plane by clicking its disc in the 3D view: the Edit plan panel and the highlight
// follow; clicks on no disc and drags that turn the view leave the selection as it was.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QImage>
#include <QTableWidget>
#include <QTest>
#include <cmath>
#include <optional>
#include <vector>

#include "multidir/core/common/units.h"
#include "ui/edit/plan_editor.h"
#include "ui/edit/plane_numbering.h"
#include "ui/main_window.h"
#include "ui/panels/plane_edit_panel.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"
#include "ui/viewer/plan_geometry.h"

namespace multidir::ui {
namespace {

// The snowman searched and shown with its clipping planes' discs; the planes' discs returned.
std::vector<PlaneDisc> showSearchedSnowmanWithPlanes(MainWindow& window) {
  test::showDefaultSample(window, QSize(1200, 850));
  if (!test::runQuickSearch(window).plan || !window.plan() || !window.plan()->plan) {
    ADD_FAILURE() << "the quick search gave no plan";
    return {};
  }
  auto* planes = window.findChild<QCheckBox*>(QStringLiteral("showPlanes"));
  if (planes == nullptr) {
    ADD_FAILURE() << "no Clipping planes check box";
    return {};
  }
  planes->setChecked(true);
  return planeDiscs(*window.plan()->plan);
}

// Where the centre of `disc` appears in the view, with the camera as the last frame drew it.
QPoint onScreen(MeshViewerWidget* viewer, const PlaneDisc& disc) {
  viewer->grabFramebuffer();
  const std::optional<QPointF> position = viewer->widgetPositionOf(disc.center);
  EXPECT_TRUE(position.has_value());
  return position ? position->toPoint() : QPoint();
}

// The plane (0-based, clipping order) selected in the Edit plan panel's plane list, -1 for none. The list
// shows planes in printing order: row r is plane number r + 1.
int panelSelection(const MainWindow& window) {
  const QList<QTableWidgetItem*> selected = window.planeEditPanel()->planeTable()->selectedItems();
  const int count = static_cast<int>(window.planEditor()->state().planes.size());
  return selected.isEmpty() ? -1 : planeIndexOfNumber(selected.front()->row() + 1, count);
}

// A point of the view where `disc` of plane `plane` is the disc in front: its centre, or else a point of
// one of a few rings around it (a steep disc in front may cover the centre of a lower one).
std::optional<QPoint> pointOnDisc(MeshViewerWidget* viewer, const PlaneDisc& disc, int plane) {
  viewer->grabFramebuffer();
  const core::Vec3 side = disc.normal.unitOrthogonal();
  const core::Vec3 across = disc.normal.cross(side);
  for (const double fraction : {0.0, 0.3, 0.55, 0.8}) {
    for (int step = 0; step < 16; ++step) {
      const double angle = step * 2.0 * core::kPi / 16.0;
      const core::Vec3 point =
          disc.center + fraction * disc.radiusMm * (std::cos(angle) * side + std::sin(angle) * across);
      const std::optional<QPointF> position = viewer->widgetPositionOf(point);
      // Well inside what this disc shows: the point and its neighbours a few pixels away all show it, so a
      // click is not decided by a disc's rim under the cursor.
      const auto showsPlane = [&](const QPoint& p) {
        return viewer->rect().contains(p) && viewer->clippingPlaneAt(QPointF(p)) == plane;
      };
      if (position) {
        const QPoint p = position->toPoint();
        if (showsPlane(p) && showsPlane(p + QPoint(2, 0)) && showsPlane(p - QPoint(2, 0)) &&
            showsPlane(p + QPoint(0, 2)) && showsPlane(p - QPoint(0, 2)))
          return p;
      }
      if (fraction == 0.0) break;
    }
  }
  return std::nullopt;
}

TEST(StudioPlaneClick, ClickOnADiscSelectsItsPlaneInThePanelAndTheView) {
  MainWindow window;
  const std::vector<PlaneDisc> discs = showSearchedSnowmanWithPlanes(window);
  ASSERT_GE(discs.size(), 2u) << "the snowman's plan should have planes to click";
  MeshViewerWidget* viewer = window.viewer();
  ASSERT_EQ(viewer->selectedPlane(), -1);
  // Every plane in turn, from the last, so each click changes the selection.
  for (int plane = static_cast<int>(discs.size()) - 1; plane >= 0; --plane) {
    const PlaneDisc& disc = discs[static_cast<std::size_t>(plane)];
    ASSERT_GT(disc.radiusMm, 0.0) << "plane " << plane + 1;
    // The centre shows some disc: this one, or one in front of it.
    EXPECT_GE(viewer->clippingPlaneAt(onScreen(viewer, disc)), 0) << "plane " << plane + 1;
    const std::optional<QPoint> point = pointOnDisc(viewer, disc, plane);
    ASSERT_TRUE(point.has_value()) << "no point of plane " << plane + 1 << "'s disc is in front";
    QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, *point);
    EXPECT_EQ(window.planEditor()->selectedPlane(), plane);
    EXPECT_EQ(panelSelection(window), plane);
    EXPECT_EQ(viewer->selectedPlane(), plane);
    EXPECT_TRUE(viewer->selectedPlaneShown()) << "plane " << plane + 1;
  }
}

TEST(StudioPlaneClick, ClickOnNoDiscLeavesTheSelection) {
  MainWindow window;
  const std::vector<PlaneDisc> discs = showSearchedSnowmanWithPlanes(window);
  ASSERT_FALSE(discs.empty());
  MeshViewerWidget* viewer = window.viewer();
  const std::optional<QPoint> point = pointOnDisc(viewer, discs.front(), 0);
  ASSERT_TRUE(point.has_value());
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, *point);
  ASSERT_EQ(viewer->selectedPlane(), 0);
  ASSERT_EQ(viewer->clippingPlaneAt(QPointF(viewer->width() / 20, viewer->height() / 20)), -1);
  // The top left corner shows the background: no disc there.
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, QPoint(viewer->width() / 20, viewer->height() / 20));
  EXPECT_EQ(window.planEditor()->selectedPlane(), 0);
  EXPECT_EQ(panelSelection(window), 0);
  EXPECT_EQ(viewer->selectedPlane(), 0);
}

TEST(StudioPlaneClick, DragFromADiscTurnsTheViewAndSelectsNothing) {
  MainWindow window;
  const std::vector<PlaneDisc> discs = showSearchedSnowmanWithPlanes(window);
  ASSERT_FALSE(discs.empty());
  MeshViewerWidget* viewer = window.viewer();
  const std::optional<QPoint> point = pointOnDisc(viewer, discs.front(), 0);
  ASSERT_TRUE(point.has_value());
  const QPoint from = *point;
  const QImage start = viewer->grabFramebuffer();
  QTest::mousePress(viewer, Qt::LeftButton, Qt::NoModifier, from);
  for (int step = 1; step <= 8; ++step) QTest::mouseMove(viewer, from + QPoint(12 * step, 0));
  // Released where it was pressed: only the way between tells a drag from a click.
  QTest::mouseRelease(viewer, Qt::LeftButton, Qt::NoModifier, from);
  EXPECT_NE(viewer->grabFramebuffer(), start) << "the drag did not turn the view";
  EXPECT_EQ(window.planEditor()->selectedPlane(), -1);
  EXPECT_EQ(panelSelection(window), -1);
  EXPECT_EQ(viewer->selectedPlane(), -1);
}

TEST(StudioPlaneClick, ClickOnADiscWithThePlanesHiddenSelectsNothing) {
  MainWindow window;
  const std::vector<PlaneDisc> discs = showSearchedSnowmanWithPlanes(window);
  ASSERT_FALSE(discs.empty());
  window.findChild<QCheckBox*>(QStringLiteral("showPlanes"))->setChecked(false);
  MeshViewerWidget* viewer = window.viewer();
  const QPoint centre = onScreen(viewer, discs.front());
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, centre);
  EXPECT_EQ(window.planEditor()->selectedPlane(), -1);
  EXPECT_EQ(viewer->selectedPlane(), -1);
}

}  // namespace
}  // namespace multidir::ui
