// The mouse wheel over the studio's fields: a field changes only when it has the keyboard focus, so a wheel
// turned to scroll a dock scrolls it (issue 29: the Search dock's min region height went 2 -> 6 on the way).
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QTest>
#include <QWheelEvent>

#include "ui/main_window.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

class StudioWheel : public ::testing::Test {
 protected:
  void SetUp() override {
    test::resetStudioSettings();
    m_window.resize(1200, 800);
    m_window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&m_window));
  }
  void TearDown() override { test::resetStudioSettings(); }

  // One notch of the wheel, away from the user, over the middle of `widget`.
  static void turnWheelOver(QWidget* widget) {
    const QPointF centre = QRectF(widget->rect()).center();
    QWheelEvent wheel(centre, widget->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &wheel);
    QTest::qWait(20);
  }

  MainWindow m_window;
};

TEST_F(StudioWheel, AWheelOverTheMinRegionHeightWithoutFocusLeavesItAsItWas) {
  auto* field = m_window.findChild<QDoubleSpinBox*>(QStringLiteral("minRegionHeight"));
  ASSERT_NE(field, nullptr);
  m_window.viewer()->setFocus();
  ASSERT_FALSE(field->hasFocus());
  const double before = field->value();
  turnWheelOver(field);
  EXPECT_EQ(field->value(), before);
  EXPECT_FALSE(field->hasFocus());
}

TEST_F(StudioWheel, AWheelOverTheMinRegionHeightWithFocusChangesIt) {
  auto* field = m_window.findChild<QDoubleSpinBox*>(QStringLiteral("minRegionHeight"));
  ASSERT_NE(field, nullptr);
  for (QWidget* w = field; w != nullptr; w = w->parentWidget())
    if (auto* dock = qobject_cast<QDockWidget*>(w)) dock->raise();  // tabbed docks: show the Search dock
  m_window.activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(&m_window));
  field->setFocus(Qt::TabFocusReason);
  ASSERT_TRUE(QTest::qWaitFor([&] { return field->hasFocus(); }, 2000));
  const double before = field->value();
  turnWheelOver(field);
  EXPECT_GT(field->value(), before);
}

TEST_F(StudioWheel, EveryFieldOfTheWindowTakesTheFocusOnlyByClickOrTab) {
  // A wheel that gave a field the focus would then change it: no spin box or combo box may take it by wheel.
  for (QWidget* field : m_window.findChildren<QWidget*>()) {
    if (!qobject_cast<QAbstractSpinBox*>(field) && !qobject_cast<QComboBox*>(field)) continue;
    EXPECT_FALSE(field->focusPolicy() & Qt::WheelFocus & ~Qt::StrongFocus)
        << field->objectName().toStdString() << " takes the focus by wheel";
  }
}

}  // namespace
}  // namespace multidir::ui
