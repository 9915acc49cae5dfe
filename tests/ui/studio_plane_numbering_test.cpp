// One plane numbering and one angle convention in every panel (issue 11, item 14): the Edit plan table lists
// planes in printing order, plane k under region k + 1 as the Plan panel numbers regions; an azimuth reads the
// same in the Plan and Edit plan panels.
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

}  // namespace
}  // namespace multidir::ui
