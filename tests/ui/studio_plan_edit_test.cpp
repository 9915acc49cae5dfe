// Editing a searched plan in the studio: planes moved, tilted, added and deleted from the Edit plan panel,
// rebuilt off the GUI thread, undone and redone exactly; edits core refuses leave everything as it was.
#include <gtest/gtest.h>

#include <QAction>
#include <QSignalSpy>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>
#include <QWindow>

#include "support/test_models.h"
#include "ui/edit/plan_editor.h"
#include "ui/edit/plane_numbering.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/plan_panel.h"
#include "ui/panels/plane_edit_panel.h"
#include "ui/panels/search_panel.h"
#include "ui/project/project_session.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

constexpr int kEvaluationTimeoutMs = 60000;

// The snowman, searched: a plan with planes, shown. With the quick search's settings each of its three
// clipping planes is as low as Criterion III allows, so moving one down cuts the platform region. The window
// stays hidden: nothing here depends on pictures, and a software-rendered frame after every edit would make
// up most of the test's time.
void showSearchedSnowman(MainWindow& window) {
  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("snowman")));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  ASSERT_TRUE(window.plan() && window.plan()->plan);
  ASSERT_GE(window.plan()->plan->clippingPlanes.size(), 2u) << "the snowman's plan should have planes to edit";
  ASSERT_TRUE(window.planEditor()->canEdit());
}

// Lets the background evaluation finish (the event loop runs meanwhile).
bool settle(const PlanEditor& editor) {
  QElapsedTimer timer;
  timer.start();
  while (editor.isEvaluating() && timer.elapsed() < kEvaluationTimeoutMs) QTest::qWait(5);
  QTest::qWait(1);
  return !editor.isEvaluating();
}

std::shared_ptr<const core::Decomposition> shownPlan(const MainWindow& window) {
  return window.plan() ? window.plan()->plan : nullptr;
}

void expectSamePlanes(const std::vector<core::Plane>& actual, const std::vector<core::Plane>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual[i].normal, expected[i].normal) << "plane " << i + 1;
    EXPECT_EQ(actual[i].offset, expected[i].offset) << "plane " << i + 1;
  }
}

// The number the studio shows for plane `plane` (0-based, clipping order) of the plan being edited: its
// number in printing order.
int numberOf(const MainWindow& window, int plane) {
  return planeNumber(plane, static_cast<int>(window.planEditor()->state().planes.size()));
}

// Selects plane `plane` (0-based, clipping order) in the Edit plan table, which lists planes in printing order.
void selectPlaneInTable(const MainWindow& window, int plane) {
  window.planeEditPanel()->planeTable()->selectRow(numberOf(window, plane) - 1);
}

// Selects plane `plane` in the Edit plan panel and presses its offset slider, as the mouse does when a drag
// begins; setSliderDown(false) releases it.
QSlider* pressOffsetSlider(const MainWindow& window, int plane) {
  PlaneEditPanel& panel = *window.planeEditPanel();
  selectPlaneInTable(window, plane);
  QSlider* slider = panel.offsetSlider();
  slider->setSliderDown(true);
  return slider;
}

QAction* action(const MainWindow& window, const char* name) {
  return window.findChild<QAction*>(QString::fromLatin1(name));
}

TEST(StudioPlanEdit, MovingAPlaneChangesJgAndTheRegionsAndUndoRestoresTheExactPlan) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlanEditor& editor = *window.planEditor();
  PlaneEditPanel& panel = *window.planeEditPanel();

  selectPlaneInTable(window, 0);
  ASSERT_EQ(editor.selectedPlane(), 0);
  const QString jgBefore = panel.jgText();
  panel.offsetBox()->setValue(searched->clippingPlanes[0].offset + 5.0);  // typed: one edit
  ASSERT_TRUE(settle(editor));

  const std::shared_ptr<const core::Decomposition> moved = shownPlan(window);
  ASSERT_NE(moved, searched);
  // The offset box counts in 0.01 mm; a polished plan's offsets are not on that grid.
  EXPECT_NEAR(moved->clippingPlanes[0].offset, searched->clippingPlanes[0].offset + 5.0, 0.005);
  EXPECT_GT(std::abs(moved->jgAfterMm2 - searched->jgAfterMm2), 1.0);
  ASSERT_EQ(moved->regions.size(), searched->regions.size());
  const std::size_t cutByFirst = moved->regions.size() - 1;  // plane 1 cut off the region printed last
  EXPECT_NE(moved->regions[cutByFirst].mesh.triangles.size(), searched->regions[cutByFirst].mesh.triangles.size());
  EXPECT_NE(panel.jgText(), jgBefore);
  EXPECT_EQ(window.undoStack()->count(), 1);
  EXPECT_EQ(action(window, "undo")->text(), QStringLiteral("&Undo Move plane %1").arg(numberOf(window, 0)));

  action(window, "undo")->trigger();
  ASSERT_TRUE(settle(editor));
  const std::shared_ptr<const core::Decomposition> undone = shownPlan(window);
  expectSamePlanes(undone->clippingPlanes, searched->clippingPlanes);
  EXPECT_NEAR(undone->jgAfterMm2, searched->jgAfterMm2, 1e-9);
  EXPECT_EQ(undone->regions.size(), searched->regions.size());
  EXPECT_NEAR(panel.offsetBox()->value(), searched->clippingPlanes[0].offset, 0.005);

  action(window, "redo")->trigger();
  ASSERT_TRUE(settle(editor));
  expectSamePlanes(shownPlan(window)->clippingPlanes, moved->clippingPlanes);
  EXPECT_NEAR(shownPlan(window)->jgAfterMm2, moved->jgAfterMm2, 1e-9);
}

TEST(StudioPlanEdit, TheSearchAndPlanPanelsShowTheEditedPlansJg) {
  MainWindow window;
  showSearchedSnowman(window);
  window.planEditor()->movePlane(0, shownPlan(window)->clippingPlanes[0].offset + 5.0);
  ASSERT_TRUE(settle(*window.planEditor()));
  const QString jg = QLocale().toString(shownPlan(window)->jgAfterMm2, 'f', 1);
  const QString summary = window.planPanel()->findChild<QLabel*>(QStringLiteral("planSummary"))->text();
  EXPECT_TRUE(summary.contains(jg)) << summary.toStdString() << " lacks " << jg.toStdString();
  EXPECT_TRUE(window.searchPanel()->readoutText().contains(jg)) << window.searchPanel()->readoutText().toStdString();
  EXPECT_TRUE(window.searchPanel()->noticeText().contains(jg)) << window.searchPanel()->noticeText().toStdString();
}

TEST(StudioPlanEdit, APlanOpenedWithoutItsModelIsShownButCannotBeEdited) {
  MainWindow window;
  showSearchedSnowman(window);
  const QString folder =
      QString::fromStdString(test::scratchDirectory("StudioPlanEditNoModel")) + QStringLiteral("/plan");
  QString error;
  ASSERT_TRUE(window.exportPlan(folder, &error)) << error.toStdString();

  MainWindow other;
  ASSERT_NO_FATAL_FAILURE(test::openPlanFolder(other, folder));  // a sample's plan names no model file
  EXPECT_TRUE(other.planEditor()->hasPlan());
  EXPECT_FALSE(other.planEditor()->canEdit());
  EXPECT_FALSE(other.planeEditPanel()->findChild<QPushButton*>(QStringLiteral("addPlane"))->isEnabled());
  EXPECT_TRUE(other.planeEditPanel()
                  ->findChild<QLabel*>(QStringLiteral("editHint"))
                  ->text()
                  .contains(QStringLiteral("without its model")));
}

TEST(StudioPlanEdit, UndoOfAStateNoLongerCachedRebuildsTheSamePlan) {
  MainWindow window;
  showSearchedSnowman(window);
  PlanEditor& editor = *window.planEditor();
  const std::vector<core::Plane> start = shownPlan(window)->clippingPlanes;
  // More steps than the editor keeps plans for: going back to the first one rebuilds it in the background.
  std::vector<double> jgAfterStep;
  for (int step = 1; step <= 10; ++step) {
    editor.movePlane(0, start[0].offset + 0.5 * step);
    ASSERT_TRUE(settle(editor));
    jgAfterStep.push_back(shownPlan(window)->jgAfterMm2);
  }
  ASSERT_EQ(window.undoStack()->count(), 10);
  window.undoStack()->setIndex(1);
  ASSERT_TRUE(settle(editor));
  EXPECT_NEAR(shownPlan(window)->clippingPlanes[0].offset, start[0].offset + 0.5, 1e-3);
  EXPECT_NEAR(shownPlan(window)->jgAfterMm2, jgAfterStep[0], 1e-9);
  window.undoStack()->setIndex(0);
  ASSERT_TRUE(settle(editor));
  expectSamePlanes(shownPlan(window)->clippingPlanes, start);
}

TEST(StudioPlanEdit, DeletingAPlaneGivesOneRegionFewerAndUndoBringsItBack) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlaneEditPanel& panel = *window.planeEditPanel();
  selectPlaneInTable(window, 1);
  panel.findChild<QPushButton*>(QStringLiteral("deletePlane"))->click();
  ASSERT_TRUE(settle(*window.planEditor()));

  EXPECT_EQ(shownPlan(window)->regions.size(), searched->regions.size() - 1);
  EXPECT_EQ(window.planPanel()->regionTable()->rowCount(), static_cast<int>(searched->regions.size()) - 1);
  EXPECT_EQ(panel.planeTable()->rowCount(), static_cast<int>(searched->clippingPlanes.size()) - 1);
  EXPECT_EQ(action(window, "undo")->text(),
            QStringLiteral("&Undo Delete plane %1").arg(planeNumber(1, static_cast<int>(searched->clippingPlanes.size()))));

  window.undoStack()->undo();
  ASSERT_TRUE(settle(*window.planEditor()));
  EXPECT_EQ(shownPlan(window)->regions.size(), searched->regions.size());
  expectSamePlanes(shownPlan(window)->clippingPlanes, searched->clippingPlanes);
  // The plane deleted is selected again, as it was.
  EXPECT_EQ(window.planEditor()->selectedPlane(), 1);
}

TEST(StudioPlanEdit, DeleteKeyInThePlanesTableDeletesTheSelectedPlane) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlaneEditPanel& panel = *window.planeEditPanel();
  window.show();  // key events go to a shown, active window (shortcuts and focus need it)
  window.activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
  selectPlaneInTable(window, 1);
  panel.planeTable()->setFocus();
  QTest::keyClick(panel.planeTable(), Qt::Key_Delete);
  ASSERT_TRUE(settle(*window.planEditor()));
  EXPECT_EQ(shownPlan(window)->clippingPlanes.size(), searched->clippingPlanes.size() - 1);
  EXPECT_EQ(panel.planeTable()->rowCount(), static_cast<int>(searched->clippingPlanes.size()) - 1);
  EXPECT_EQ(window.undoStack()->count(), 1);
}

// The double-click goes through the window (QTest's QWindow overload), as the platform delivers one: a
// double-click event sent to the table's viewport directly never reached cellDoubleClicked under Xvfb.
TEST(StudioPlanEdit, DoubleClickOnAPlanesOffsetPutsTheCursorInItsOffset) {
  MainWindow window;
  showSearchedSnowman(window);
  PlaneEditPanel& panel = *window.planeEditPanel();
  window.show();
  window.activateWindow();  // focus moves only inside the active window
  ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
  window.findChild<QDockWidget*>(QStringLiteral("editPlanDock"))->raise();
  QTableWidget* table = panel.planeTable();
  table->clearSelection();
  QTest::qWait(20);
  const QRect cell = table->visualRect(table->model()->index(numberOf(window, 1) - 1, 2));
  ASSERT_FALSE(cell.isEmpty());
  QSignalSpy dbl(table, &QTableWidget::cellDoubleClicked);
  // Through the window, as the platform delivers a real double-click: QGuiApplication makes the double-click
  // event from two presses close in time and place (a double-click sent to the widget itself never arrives).
  QWindow* handle = window.windowHandle();
  ASSERT_NE(handle, nullptr);
  const QPoint inWindow = table->viewport()->mapTo(&window, cell.center());
  QTest::mouseDClick(handle, Qt::LeftButton, Qt::NoModifier, inWindow);
  EXPECT_EQ(dbl.size(), 1) << "the double-click did not reach the planes table";
  EXPECT_EQ(window.planEditor()->selectedPlane(), 1);
  ASSERT_TRUE(test::waitUntil([&panel] { return panel.offsetBox()->hasFocus(); }, 2000))
      << "the double-click did not start editing the plane's offset";
}

TEST(StudioPlanEdit, AddingAPlaneGivesOneRegionMore) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlaneEditPanel& panel = *window.planeEditPanel();
  selectPlaneInTable(window, 0);
  panel.findChild<QPushButton*>(QStringLiteral("addPlane"))->click();
  ASSERT_TRUE(settle(*window.planEditor()));

  EXPECT_TRUE(panel.refusalText().isEmpty()) << panel.refusalText().toStdString();
  EXPECT_EQ(shownPlan(window)->regions.size(), searched->regions.size() + 1);
  EXPECT_EQ(panel.planeTable()->rowCount(), static_cast<int>(searched->clippingPlanes.size()) + 1);
  // The new plane is parallel to the selected one, above it, and becomes the selected one.
  EXPECT_EQ(window.planEditor()->selectedPlane(), 0);
  const core::Plane& added = shownPlan(window)->clippingPlanes[0];
  EXPECT_EQ(added.normal, searched->clippingPlanes[0].normal);
  EXPECT_GT(added.offset, searched->clippingPlanes[0].offset);
  EXPECT_EQ(action(window, "undo")->text(), QStringLiteral("&Undo Add plane %1").arg(numberOf(window, 0)));
}

TEST(StudioPlanEdit, APlaneMovedThroughThePlatformRegionIsRefusedAndNothingChanges) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlanEditor& editor = *window.planEditor();
  PlaneEditPanel& panel = *window.planeEditPanel();
  selectPlaneInTable(window, 0);
  panel.offsetBox()->setValue(searched->clippingPlanes[0].offset - 10.0);
  ASSERT_TRUE(settle(editor));

  EXPECT_EQ(shownPlan(window), searched);
  EXPECT_EQ(window.undoStack()->count(), 0);
  EXPECT_FALSE(action(window, "undo")->isEnabled());
  // Said where the person is looking, naming the plane and what to do, and in the status bar.
  const QString message = panel.refusalText();
  EXPECT_TRUE(message.contains(QStringLiteral("Plane %1").arg(numberOf(window, 0)))) << message.toStdString();
  EXPECT_TRUE(message.contains(QStringLiteral("platform region"))) << message.toStdString();
  EXPECT_TRUE(panel.findChild<QWidget*>(QStringLiteral("editRefusal"))->isVisibleTo(&panel));
  EXPECT_EQ(window.statusBar()->currentMessage(), message);
  // The controls show the plan shown again.
  EXPECT_NEAR(panel.offsetBox()->value(), searched->clippingPlanes[0].offset, 0.01);
  EXPECT_DOUBLE_EQ(editor.state().planes[0].offset, searched->clippingPlanes[0].offset);

  // The next accepted edit clears the message.
  panel.offsetBox()->setValue(searched->clippingPlanes[0].offset + 2.0);
  ASSERT_TRUE(settle(editor));
  EXPECT_TRUE(panel.refusalText().isEmpty());
  EXPECT_TRUE(window.statusBar()->currentMessage().isEmpty());
  EXPECT_EQ(window.undoStack()->count(), 1);
}

TEST(StudioPlanEdit, ADragOfSeveralStepsIsOneUndoStep) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlanEditor& editor = *window.planEditor();
  QSlider* slider = pressOffsetSlider(window, 1);
  const int start = slider->value();
  ASSERT_LT(start + 60, slider->maximum());

  for (int step = 1; step <= 3; ++step) {
    slider->setValue(start + 20 * step);
    ASSERT_TRUE(settle(editor));
    // The live result is shown while dragging.
    EXPECT_NE(shownPlan(window)->clippingPlanes[1].offset, searched->clippingPlanes[1].offset) << "step " << step;
  }
  slider->setSliderDown(false);  // released
  ASSERT_TRUE(settle(editor));

  EXPECT_EQ(window.undoStack()->count(), 1);
  EXPECT_EQ(window.undoStack()->undoText(), QStringLiteral("Move plane %1").arg(numberOf(window, 1)));
  const double dragged = shownPlan(window)->clippingPlanes[1].offset;
  EXPECT_GT(dragged, searched->clippingPlanes[1].offset);
  window.undoStack()->undo();
  ASSERT_TRUE(settle(editor));
  expectSamePlanes(shownPlan(window)->clippingPlanes, searched->clippingPlanes);
}

TEST(StudioPlanEdit, ADragReleasedWhereCoreRefusesKeepsItsLastAcceptedStep) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlanEditor& editor = *window.planEditor();
  PlaneEditPanel& panel = *window.planeEditPanel();
  QSlider* slider = pressOffsetSlider(window, 0);
  const int start = slider->value();

  slider->setValue(start + 20);  // up: accepted
  ASSERT_TRUE(settle(editor));
  const double accepted = shownPlan(window)->clippingPlanes[0].offset;
  slider->setValue(0);  // to the bottom of the model: through the platform region
  ASSERT_TRUE(settle(editor));
  EXPECT_FALSE(panel.refusalText().isEmpty());
  EXPECT_EQ(slider->value(), 0) << "the slider stays under the mouse while the drag goes on";
  slider->setSliderDown(false);
  ASSERT_TRUE(settle(editor));

  EXPECT_DOUBLE_EQ(shownPlan(window)->clippingPlanes[0].offset, accepted);
  EXPECT_DOUBLE_EQ(editor.state().planes[0].offset, accepted);
  EXPECT_NEAR(panel.offsetBox()->value(), accepted, 0.005);
  EXPECT_GT(slider->value(), start);
  EXPECT_EQ(window.undoStack()->count(), 1);
  window.undoStack()->undo();
  expectSamePlanes(shownPlan(window)->clippingPlanes, searched->clippingPlanes);
}

TEST(StudioPlanEdit, TiltingAPlaneTurnsItAboutItsCutAndIsOneStep) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlaneEditPanel& panel = *window.planeEditPanel();
  // The first plane and tilt (a few degrees less, then more) that core accepts: most tilts of a searched plane
  // make it cut the platform region or leave a piece below it floating, which is refused.
  int row = -1;
  double wanted = 0.0;
  for (int r = 0; r < static_cast<int>(searched->clippingPlanes.size()) && row < 0; ++r) {
    selectPlaneInTable(window, r);
    const double tilt = panel.tiltBox()->value();
    for (const double delta : {-3.0, 3.0, -1.0, 1.0}) {
      panel.tiltBox()->setValue(tilt + delta);
      ASSERT_TRUE(settle(*window.planEditor()));
      if (panel.refusalText().isEmpty()) {
        row = r;
        wanted = tilt + delta;
        break;
      }
    }
  }
  ASSERT_GE(row, 0) << "no plane of the snowman's plan could be tilted by 1 to 3 degrees";

  const core::Plane& tilted = shownPlan(window)->clippingPlanes[static_cast<std::size_t>(row)];
  const core::MachineAngles angles = core::machineAnglesFor(window.planEditor()->machine(), tilted.normal);
  EXPECT_NEAR(angles.tiltDegrees, wanted, 0.05);
  EXPECT_NEAR(panel.tiltBox()->value(), wanted, 0.05);
  EXPECT_EQ(window.undoStack()->count(), 1) << "refused tilts leave no undo step";
  EXPECT_EQ(window.undoStack()->undoText(), QStringLiteral("Tilt plane %1").arg(numberOf(window, row)));
  // It turned about the centre of its cut, which therefore stays on it.
  EXPECT_LT(std::abs(tilted.offset - searched->clippingPlanes[static_cast<std::size_t>(row)].offset), 5.0);
}

TEST(StudioPlanEdit, OnARotaryMachineAPlaneTurnsInWholeStepsOfThePlatform) {
  MainWindow window;
  core::MachineSpec rotary;
  rotary.kind = core::MachineKind::RotaryPlatform;
  rotary.rotationAxis = core::Vec3::UnitX();
  window.machinePanel()->setMachineSpec(rotary);
  showSearchedSnowman(window);
  PlaneEditPanel& panel = *window.planeEditPanel();
  EXPECT_TRUE(panel.rotaryBox()->isVisibleTo(&panel));
  EXPECT_FALSE(panel.tiltBox()->isVisibleTo(&panel));
  selectPlaneInTable(window, 0);
  const double angle = panel.rotaryBox()->value();
  // Typed between two steps of 1°: the plane turns to the nearest step.
  panel.rotaryBox()->setValue(angle > 0.0 ? angle - 4.6 : angle + 4.6);
  ASSERT_TRUE(settle(*window.planEditor()));

  ASSERT_TRUE(panel.refusalText().isEmpty()) << panel.refusalText().toStdString();
  const core::MachineSpec& machine = window.planEditor()->machine();
  const core::Vec3& normal = shownPlan(window)->clippingPlanes[0].normal;
  EXPECT_TRUE(core::isRealizable(machine, normal));
  EXPECT_NEAR(core::machineAnglesFor(machine, normal).rotaryDegrees, angle > 0.0 ? angle - 5.0 : angle + 5.0, 1e-9);
  EXPECT_NEAR(panel.rotaryBox()->value(), angle > 0.0 ? angle - 5.0 : angle + 5.0, 1e-9);
  EXPECT_EQ(window.undoStack()->undoText(), QStringLiteral("Tilt plane %1").arg(numberOf(window, 0)));
}

TEST(StudioPlanEdit, OnlyTheLatestOfManyQuickEditsIsEvaluatedAndShown) {
  MainWindow window;
  showSearchedSnowman(window);
  PlanEditor& editor = *window.planEditor();
  const double offset = shownPlan(window)->clippingPlanes[0].offset;
  const int before = editor.evaluationJob()->evaluationsStarted();
  // Twenty edits before the event loop runs once: one evaluation starts, the others replace each other
  // while they wait, and only the last is shown.
  for (int step = 1; step <= 20; ++step) editor.movePlane(0, offset + 0.25 * step);
  ASSERT_TRUE(settle(editor));
  EXPECT_LE(editor.evaluationJob()->evaluationsStarted() - before, 2);
  EXPECT_DOUBLE_EQ(shownPlan(window)->clippingPlanes[0].offset, offset + 5.0);
  EXPECT_EQ(window.undoStack()->count(), 1);
}

TEST(StudioPlanEdit, SelectingAPlaneHighlightsItsDiscInTheView) {
  MainWindow window;
  showSearchedSnowman(window);
  EXPECT_EQ(window.viewer()->selectedPlane(), -1);
  selectPlaneInTable(window, 1);
  EXPECT_EQ(window.planEditor()->selectedPlane(), 1);
  EXPECT_EQ(window.viewer()->selectedPlane(), 1);
  // Shown although the clipping planes are hidden.
  window.planPanel()->setClippingPlanesShown(false);
  EXPECT_TRUE(window.viewer()->selectedPlaneShown());
  window.planeEditPanel()->planeTable()->clearSelection();
  EXPECT_EQ(window.viewer()->selectedPlane(), -1);
  EXPECT_FALSE(window.viewer()->selectedPlaneShown());
}

TEST(StudioPlanEdit, ANewSearchIsOneUndoStepAndUndoBringsTheEditedPlanBack) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> searched = shownPlan(window);
  PlanEditor& editor = *window.planEditor();
  editor.movePlane(0, searched->clippingPlanes[0].offset + 2.0);
  ASSERT_TRUE(settle(editor));
  const std::shared_ptr<const core::Decomposition> edited = shownPlan(window);
  ASSERT_NE(edited, searched);
  ASSERT_EQ(window.undoStack()->count(), 1);

  ASSERT_TRUE(test::runQuickSearch(window).plan);
  ASSERT_TRUE(settle(editor));
  expectSamePlanes(shownPlan(window)->clippingPlanes, searched->clippingPlanes);  // the same search again
  EXPECT_EQ(window.undoStack()->count(), 2);
  ASSERT_TRUE(action(window, "undo")->isEnabled());
  EXPECT_EQ(action(window, "undo")->text(), QStringLiteral("&Undo New search"));

  action(window, "undo")->trigger();
  ASSERT_TRUE(settle(editor));
  EXPECT_EQ(shownPlan(window), edited) << "Undo should show the edited plan the search replaced";
  EXPECT_EQ(editor.plan(), edited);
  EXPECT_TRUE(editor.isEdited());
  EXPECT_TRUE(window.viewer()->hasPlan());

  // The edit under it is still there to undo, back to the first search's plan.
  action(window, "undo")->trigger();
  ASSERT_TRUE(settle(editor));
  expectSamePlanes(shownPlan(window)->clippingPlanes, searched->clippingPlanes);
  EXPECT_NEAR(shownPlan(window)->jgAfterMm2, searched->jgAfterMm2, 1e-9);
}

TEST(StudioPlanEdit, SearchRunOverAnEditedUnsavedPlanAsksFirst) {
  MainWindow window;
  showSearchedSnowman(window);
  PlanEditor& editor = *window.planEditor();
  editor.movePlane(0, shownPlan(window)->clippingPlanes[0].offset + 2.0);
  ASSERT_TRUE(settle(editor));
  const std::shared_ptr<const core::Decomposition> edited = shownPlan(window);
  ASSERT_TRUE(window.projectSession()->isModified());

  action(window, "runSearch")->trigger();
  QMessageBox* box = test::waitForMessageBox(window, QStringLiteral("replaceEditedPlanBox"));
  ASSERT_NE(box, nullptr) << "Search > Run over an edited plan that is not saved should ask first";
  EXPECT_FALSE(window.isSearching());
  box->button(QMessageBox::Cancel)->click();
  QTest::qWait(50);
  EXPECT_FALSE(window.isSearching());
  EXPECT_EQ(shownPlan(window), edited);

  QSignalSpy finished(&window, &MainWindow::searchFinished);
  action(window, "runSearch")->trigger();
  box = test::waitForMessageBox(window, QStringLiteral("replaceEditedPlanBox"));
  ASSERT_NE(box, nullptr);
  box->findChild<QPushButton*>(QStringLiteral("searchAnyway"))->click();
  ASSERT_TRUE(test::waitUntil([&window] { return window.isSearching() || !window.searchPanel()->noticeText().isEmpty(); }));
  ASSERT_TRUE(finished.wait(test::kSearchTimeoutMs));
  ASSERT_TRUE(settle(editor));
  EXPECT_NE(shownPlan(window), edited);
}

TEST(StudioPlanEdit, ACancelledSearchWorseThanThePlanShownKeepsThePlanShownAndSaysSo) {
  MainWindow window;
  showSearchedSnowman(window);
  const std::shared_ptr<const core::Decomposition> kept = shownPlan(window);
  window.searchPanel()->setSearchOptions(test::longSearchOptions());
  QSignalSpy finished(&window, &MainWindow::searchFinished);
  ASSERT_TRUE(window.runSearch());
  window.cancelSearch();  // at once: its best plan so far is far from the finished search's
  ASSERT_TRUE(finished.wait(test::kSearchTimeoutMs));
  const SearchRun cancelled = finished.front().front().value<SearchRun>();
  ASSERT_TRUE(cancelled.plan && cancelled.plan->cancelled);
  ASSERT_GT(cancelled.plan->jgAfterMm2, kept->jgAfterMm2) << "the cancelled search should have found less";

  EXPECT_EQ(shownPlan(window), kept);
  EXPECT_EQ(window.planEditor()->plan(), kept);
  EXPECT_TRUE(window.searchPanel()->noticeText().contains(QStringLiteral("which is kept")))
      << window.searchPanel()->noticeText().toStdString();
  EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("which is kept")));
}

TEST(StudioPlanEdit, ANewModelEndsEditing) {
  MainWindow window;
  showSearchedSnowman(window);
  window.planEditor()->movePlane(0, shownPlan(window)->clippingPlanes[0].offset + 2.0);
  ASSERT_TRUE(settle(*window.planEditor()));
  ASSERT_EQ(window.undoStack()->count(), 1);

  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("mushroom")));
  EXPECT_EQ(window.undoStack()->count(), 0);
  EXPECT_FALSE(window.planEditor()->hasPlan());
  EXPECT_FALSE(window.planeEditPanel()->findChild<QPushButton*>(QStringLiteral("addPlane"))->isEnabled());
}

}  // namespace
}  // namespace multidir::ui
