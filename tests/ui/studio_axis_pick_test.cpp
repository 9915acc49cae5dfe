// Picking the 4-DOF rotation axis by clicking two points on the platform in the 3D view.
#include <gtest/gtest.h>

#include <QImage>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <cmath>

#include "multidir/core/common/units.h"
#include "ui/document/studio_document.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/axis_picker.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

void showDefaultSample(MainWindow& window) { test::showDefaultSample(window, QSize(1200, 850)); }

void chooseRotaryMachine(MainWindow& window) {
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  machine.rotationAxis = core::Vec3::UnitX();
  window.machinePanel()->setMachineSpec(machine);
}

QPushButton* pickButton(const MainWindow& window) {
  return window.machinePanel()->findChild<QPushButton*>(QStringLiteral("pickAxisOnPlatform"));
}

// Where a point of the platform appears in the view, with the camera as the last frame drew it.
QPoint onScreen(MeshViewerWidget* viewer, const core::Vec3& point) {
  viewer->grabFramebuffer();
  const std::optional<QPointF> position = viewer->widgetPositionOf(point);
  EXPECT_TRUE(position.has_value());
  return position ? position->toPoint() : QPoint();
}

double angleDegrees(const core::Vec3& a, const core::Vec3& b) {
  return core::radToDeg(std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)));
}

QString status(const MainWindow& window) { return window.statusBar()->currentMessage(); }

TEST(StudioAxisPick, TwoClicksOnThePlatformTypeTheAxisIntoTheMachinePanel) {
  MainWindow window;
  showDefaultSample(window);
  chooseRotaryMachine(window);
  QPushButton* pick = pickButton(window);
  ASSERT_NE(pick, nullptr);
  ASSERT_TRUE(pick->isEnabled());
  pick->click();
  MeshViewerWidget* viewer = window.viewer();
  EXPECT_TRUE(viewer->isPlatformPicking());
  EXPECT_TRUE(status(window).contains(QStringLiteral("first point"))) << status(window).toStdString();

  // Two points on the platform, half its radius either side of the centre, along a direction 30 degrees
  // from X.
  const PlatformDisc disc = viewer->platform();
  const core::Vec3 expected(std::cos(core::degToRad(30.0)), std::sin(core::degToRad(30.0)), 0.0);
  const core::Vec3 first = disc.center - 0.5 * disc.radiusMm * expected;
  const core::Vec3 second = disc.center + 0.5 * disc.radiusMm * expected;
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, onScreen(viewer, first));
  EXPECT_EQ(viewer->pickMarkersShown(), 1u);
  EXPECT_TRUE(status(window).contains(QStringLiteral("second point"))) << status(window).toStdString();

  QSignalSpy picked(window.axisPicker(), &AxisPicker::axisPicked);
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, onScreen(viewer, second));
  ASSERT_EQ(picked.count(), 1);
  EXPECT_FALSE(viewer->isPlatformPicking());
  EXPECT_FALSE(pick->isChecked());
  EXPECT_EQ(viewer->pickMarkersShown(), 0u);

  // The axis is typed into the panel (x,y,z), read back as the machine's, and drawn.
  const QString text = window.machinePanel()->findChild<QLineEdit*>(QStringLiteral("rotationAxis"))->text();
  EXPECT_EQ(text.count(QLatin1Char(',')), 2) << text.toStdString();
  const std::optional<core::Vec3> axis = window.machinePanel()->rotationAxis();
  ASSERT_TRUE(axis.has_value()) << text.toStdString();
  EXPECT_LT(angleDegrees(*axis, expected), 2.0) << text.toStdString();
  EXPECT_TRUE(window.machinePanel()->errorText().isEmpty()) << window.machinePanel()->errorText().toStdString();
  EXPECT_LT(angleDegrees(window.machinePanel()->machineSpec(window.upDirection()).rotationAxis, expected), 2.0);
  EXPECT_TRUE(viewer->rotationAxisShown());
}

TEST(StudioAxisPick, ClickBesideThePlatformIsRefusedAndPickingGoesOn) {
  MainWindow window;
  showDefaultSample(window);
  chooseRotaryMachine(window);
  pickButton(window)->click();
  MeshViewerWidget* viewer = window.viewer();
  viewer->grabFramebuffer();
  // The top left corner shows the background above the horizon: no platform there.
  const QPoint corner(viewer->width() / 20, viewer->height() / 20);
  EXPECT_FALSE(viewer->platformPointAt(corner).has_value());
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, corner);
  EXPECT_TRUE(status(window).contains(QStringLiteral("missed"))) << status(window).toStdString();
  EXPECT_TRUE(viewer->isPlatformPicking());
  EXPECT_EQ(viewer->pickMarkersShown(), 0u);
}

TEST(StudioAxisPick, SecondPointOnTheFirstIsRefused) {
  MainWindow window;
  showDefaultSample(window);
  chooseRotaryMachine(window);
  const QString before = window.machinePanel()->findChild<QLineEdit*>(QStringLiteral("rotationAxis"))->text();
  pickButton(window)->click();
  MeshViewerWidget* viewer = window.viewer();
  const QPoint point = onScreen(viewer, viewer->platform().center);
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, point);
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, point);
  EXPECT_TRUE(status(window).contains(QStringLiteral("1 mm"))) << status(window).toStdString();
  EXPECT_TRUE(viewer->isPlatformPicking());
  EXPECT_EQ(viewer->pickMarkersShown(), 1u);
  EXPECT_EQ(window.machinePanel()->findChild<QLineEdit*>(QStringLiteral("rotationAxis"))->text(), before);
}

TEST(StudioAxisPick, DragWhilePickingTurnsTheViewAndPicksNothing) {
  MainWindow window;
  showDefaultSample(window);
  chooseRotaryMachine(window);
  pickButton(window)->click();
  MeshViewerWidget* viewer = window.viewer();
  const QImage start = viewer->grabFramebuffer();
  const QPoint from = onScreen(viewer, viewer->platform().center);
  QTest::mousePress(viewer, Qt::LeftButton, Qt::NoModifier, from);
  for (int step = 1; step <= 8; ++step) QTest::mouseMove(viewer, from + QPoint(12 * step, 0));
  QTest::mouseRelease(viewer, Qt::LeftButton, Qt::NoModifier, from + QPoint(96, 0));
  EXPECT_NE(viewer->grabFramebuffer(), start) << "the drag did not turn the view";
  EXPECT_EQ(viewer->pickMarkersShown(), 0u);
  EXPECT_TRUE(viewer->isPlatformPicking());
  EXPECT_TRUE(status(window).contains(QStringLiteral("first point"))) << status(window).toStdString();
}

TEST(StudioAxisPick, EscOrTheButtonAgainCancels) {
  MainWindow window;
  showDefaultSample(window);
  chooseRotaryMachine(window);
  QPushButton* pick = pickButton(window);
  MeshViewerWidget* viewer = window.viewer();
  pick->click();
  QTest::mouseClick(viewer, Qt::LeftButton, Qt::NoModifier, onScreen(viewer, viewer->platform().center));
  ASSERT_EQ(viewer->pickMarkersShown(), 1u);
  QTest::keyClick(viewer, Qt::Key_Escape);
  EXPECT_FALSE(viewer->isPlatformPicking());
  EXPECT_FALSE(pick->isChecked());
  EXPECT_EQ(viewer->pickMarkersShown(), 0u);
  EXPECT_TRUE(status(window).contains(QStringLiteral("cancelled"))) << status(window).toStdString();

  pick->click();
  EXPECT_TRUE(viewer->isPlatformPicking());
  pick->click();
  EXPECT_FALSE(viewer->isPlatformPicking());
  EXPECT_FALSE(window.axisPicker()->isActive());
}

TEST(StudioAxisPick, ButtonIsEnabledForARotaryPlatformUnderAModelOnly) {
  MainWindow window;
  chooseRotaryMachine(window);
  EXPECT_FALSE(pickButton(window)->isEnabled()) << "no model, so no platform to click on";
  showDefaultSample(window);
  EXPECT_TRUE(pickButton(window)->isEnabled());

  // Another machine kind ends picking.
  pickButton(window)->click();
  ASSERT_TRUE(window.viewer()->isPlatformPicking());
  core::MachineSpec arm;
  arm.kind = core::MachineKind::TiltRotate;
  window.machinePanel()->setMachineSpec(arm);
  EXPECT_FALSE(pickButton(window)->isEnabled());
  EXPECT_FALSE(pickButton(window)->isChecked());
  EXPECT_FALSE(window.viewer()->isPlatformPicking());
}

TEST(StudioAxisPick, PickedAxisIsTypedWithFourDecimalsAndStaysValidUnderATiltedUp) {
  StudioDocument document;
  MachinePanel panel(&document);
  core::MachineSpec machine;
  machine.kind = core::MachineKind::RotaryPlatform;
  panel.setMachineSpec(machine);
  auto* field = panel.findChild<QLineEdit*>(QStringLiteral("rotationAxis"));
  QSignalSpy changed(&panel, &MachinePanel::machineChanged);
  panel.setRotationAxis(core::Vec3(std::sqrt(0.75), -0.5, 0.0), core::Vec3::UnitZ());
  EXPECT_EQ(field->text(), QStringLiteral("0.8660,-0.5000,0.0000"));
  EXPECT_GE(changed.count(), 1);
  EXPECT_TRUE(panel.validateFor(core::Vec3::UnitZ())) << panel.errorText().toStdString();

  // Four decimals would leave this axis 4e-5 out of the platform plane, which validate() refuses.
  const core::Vec3 up(0, 0.6, 0.8);
  const core::Vec3 axis = up.cross(core::Vec3(0.31, 0.77, 0.13)).normalized();
  panel.setRotationAxis(axis, up);
  EXPECT_TRUE(panel.validateFor(up)) << field->text().toStdString() << ": " << panel.errorText().toStdString();
  ASSERT_TRUE(panel.rotationAxis().has_value());
  EXPECT_TRUE(panel.rotationAxis()->isApprox(axis, 1e-6)) << field->text().toStdString();
}

}  // namespace
}  // namespace multidir::ui
