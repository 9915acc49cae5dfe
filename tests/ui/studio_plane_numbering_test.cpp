// One plane numbering and one angle convention in every panel (issue 11, item 14): the Edit plan table lists
// planes in printing order, plane k under region k + 1 as the Plan panel numbers regions; an azimuth reads the
// same in the Plan and Edit plan panels; and a tilt never changes the offset field without saying so.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QTest>
#include <cmath>

#include "ui/edit/plan_editor.h"
#include "ui/edit/plane_numbering.h"
#include "ui/main_window.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/plane_edit_panel.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

constexpr int kAnglesColumn = 4;  // the Plan panel's "Machine angles"

QString number(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

void showSearchedSnowman(MainWindow& window) {
  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("snowman")));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  ASSERT_GE(window.plan()->plan->clippingPlanes.size(), 2u);
}

bool settle(const PlanEditor& editor) {
  return test::waitUntil([&editor] { return !editor.isEvaluating(); }, 60000);
}

TEST(StudioPlaneNumbering, EditPlanListsPlanesInPrintingOrderUnderTheRegionsTheyCarry) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showSearchedSnowman(window));
  const core::Decomposition& plan = *window.plan()->plan;
  QTableWidget* planes = window.planeEditPanel()->planeTable();
  ASSERT_EQ(planes->rowCount(), static_cast<int>(plan.clippingPlanes.size()));
  for (int row = 0; row < planes->rowCount(); ++row) {
    // Plane k (row k - 1) is the base of region k + 1 (the Plan panel's row k).
    const core::Region& carried = plan.regions[static_cast<std::size_t>(row + 1)];
    ASSERT_TRUE(carried.basePlane.has_value());
    EXPECT_EQ(planes->item(row, 0)->text(), QString::number(row + 1));
    EXPECT_EQ(planes->item(row, 2)->text(), number(carried.basePlane->offset, 2)) << "plane " << row + 1;
    EXPECT_EQ(window.planPanel()->regionTable()->item(row + 1, 0)->text(), QString::number(row + 2));
  }
}

TEST(StudioPlaneNumbering, AnAzimuthReadsTheSameInThePlanAndEditPlanPanels) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showSearchedSnowman(window));
  PlaneEditPanel& panel = *window.planeEditPanel();
  const int count = static_cast<int>(window.plan()->plan->clippingPlanes.size());
  // The top plane (cut first: the base of the region printed last) turned towards -100 degrees.
  panel.planeTable()->selectRow(planeNumber(0, count) - 1);
  ASSERT_EQ(window.planEditor()->selectedPlane(), 0);
  panel.tiltBox()->setValue(12.0);
  panel.azimuthBox()->setValue(-100.0);
  ASSERT_TRUE(settle(*window.planEditor()));
  ASSERT_TRUE(panel.refusalText().isEmpty()) << panel.refusalText().toStdString();

  const double azimuth = panel.azimuthBox()->value();
  EXPECT_NEAR(azimuth, -100.0, 0.05);
  const QString angles = window.planPanel()->regionTable()->item(count, kAnglesColumn)->text();
  EXPECT_TRUE(angles.contains(QStringLiteral("azimuth %1°").arg(number(azimuth, 1)))) << angles.toStdString();
}

// A tilt turns the plane about the middle of its cut, which moves its offset (measured from the origin along
// the normal): the offset field then shows the new value and a note under it says from what to what; a tilt
// that keeps the offset shows no note. Either way the field never changes silently.
TEST(StudioPlaneNumbering, TiltingAPlaneChangesItsOffsetFieldOnlyWithANoteSayingFromWhatToWhat) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showSearchedSnowman(window));
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  PlaneEditPanel& panel = *window.planeEditPanel();
  auto* note = panel.findChild<QLabel*>(QStringLiteral("offsetFollowsTilt"));
  ASSERT_NE(note, nullptr) << "nothing says that a tilt moves the offset";
  const int count = static_cast<int>(window.plan()->plan->clippingPlanes.size());
  // The first plane and tilt core accepts (most tilts of a searched plane cut into another region).
  bool tilted = false;
  double before = 0.0;
  for (int plane = 0; plane < count && !tilted; ++plane) {
    panel.planeTable()->selectRow(planeNumber(plane, count) - 1);
    ASSERT_TRUE(settle(*window.planEditor()));
    EXPECT_FALSE(note->isVisibleTo(&panel)) << "no tilt yet";
    for (double delta : {-3.0, 3.0, -6.0, 6.0}) {
      before = panel.offsetBox()->value();
      const double tilt = panel.tiltBox()->value();
      if (tilt + delta < 0.0) continue;
      panel.tiltBox()->setValue(tilt + delta);
      ASSERT_TRUE(settle(*window.planEditor()));
      if (panel.refusalText().isEmpty()) {
        tilted = true;
        break;
      }
    }
  }
  ASSERT_TRUE(tilted) << "no plane of the snowman's plan could be tilted by 3 or 6 degrees";
  const double after = panel.offsetBox()->value();
  const bool moved = number(after, 2) != number(before, 2);
  EXPECT_EQ(note->isVisibleTo(&panel), moved) << "offset " << before << " -> " << after;
  if (moved) {
    EXPECT_TRUE(note->text().contains(number(before, 2)) && note->text().contains(number(after, 2)))
        << note->text().toStdString();
  }

  // Typing an offset is no tilt: the note goes.
  panel.offsetBox()->setValue(after + 0.5);
  ASSERT_TRUE(settle(*window.planEditor()));
  EXPECT_FALSE(note->isVisibleTo(&panel));
}

}  // namespace
}  // namespace multidir::ui
