// The studio on a small screen (a 1280x720 projector, a 1366x768 laptop): the window fits, every dock tab,
// the status bar and every button can be reached, and E-STOP stays in view while a device is connected,
// whichever dock is raised and in every language.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QDockWidget>
#include <QImage>
#include <QPushButton>
#include <QScrollArea>
#include <QStatusBar>
#include <QTabBar>
#include <QTest>

#include "hardware/hardware_test_support.h"
#include "multidir/hardware/device_simulator.h"
#include "ui/device/connection_form.h"
#include "ui/device/device_link.h"
#include "ui/device/hardware_panel.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/studio_startup.h"

namespace multidir::ui {
namespace {

constexpr int kWaitMs = 5000;
const QSize kSmallScreens[] = {QSize(1280, 720), QSize(1366, 768)};

// `widget`'s rectangle in `window`'s coordinates.
QRect rectIn(const QWidget* widget, const QWidget* window) {
  return QRect(widget->mapTo(window, QPoint(0, 0)), widget->size());
}

// Shown, inside the window, and not clipped by any parent (a scroll area's viewport, a splitter).
bool whollyInView(const QWidget* widget, const QWidget* window) {
  return widget->isVisible() && window->rect().contains(rectIn(widget, window)) &&
         widget->visibleRegion() == QRegion(widget->rect());
}

// Pixels of `image` that are clearly red (the style shades the button's #c62828 into a gradient).
int redPixels(const QImage& image) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (c.red() > 170 && c.green() < 130 && c.blue() < 130) ++count;
    }
  return count;
}

void showAt(MainWindow& window, const QSize& size) {
  window.resize(size);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  QCoreApplication::processEvents();
}

TEST(StudioSmallScreen, WindowFitsAndEveryTabStatusBarAndButtonIsReachable) {
  for (const QSize& screen : kSmallScreens) {
    SCOPED_TRACE(QStringLiteral("%1x%2").arg(screen.width()).arg(screen.height()).toStdString());
    MainWindow window;
    ASSERT_NO_FATAL_FAILURE(showAt(window, screen));
    EXPECT_EQ(window.size(), screen) << "minimum size " << window.minimumSizeHint().width() << "x"
                                     << window.minimumSizeHint().height();
    EXPECT_TRUE(whollyInView(window.statusBar(), &window));

    int tabBars = 0;
    for (const QTabBar* bar : window.findChildren<QTabBar*>()) {
      if (bar->parentWidget() != &window || !bar->isVisible()) continue;  // the dock area's own tab bars
      ++tabBars;
      EXPECT_TRUE(whollyInView(bar, &window)) << "dock tab bar at " << rectIn(bar, &window).y();
    }
    EXPECT_GE(tabBars, 1);

    // Every dock in turn: each of its buttons is in view, or scrolls into view within its dock.
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
      dock->raise();
      QCoreApplication::processEvents();
      ASSERT_TRUE(dock->isVisible()) << dock->objectName().toStdString();
      for (QAbstractButton* button : dock->widget()->findChildren<QAbstractButton*>()) {
        if (!button->isVisibleTo(dock->widget())) continue;
        for (QWidget* up = button->parentWidget(); up; up = up->parentWidget())
          if (auto* scroll = qobject_cast<QScrollArea*>(up)) scroll->ensureWidgetVisible(button, 0, 0);
        QCoreApplication::processEvents();
        EXPECT_TRUE(whollyInView(button, &window))
            << dock->objectName().toStdString() << ": " << button->objectName().toStdString() << " \""
            << button->text().toStdString() << "\" at " << rectIn(button, &window).y() << " of "
            << window.height();
      }
    }
  }
}

class StudioEmergencyStop : public ::testing::TestWithParam<const char*> {
 protected:
  void TearDown() override { installTranslations(QStringLiteral("en")); }
};

TEST_P(StudioEmergencyStop, StaysInViewWhileConnectedWhicheverDockIsRaised) {
  ASSERT_TRUE(installTranslations(chooseLanguage(QString::fromLatin1(GetParam()))));
  hardware::DeviceSimulator sim;
  ASSERT_TRUE(sim.start().ok());
  for (const QSize& screen : kSmallScreens) {
    SCOPED_TRACE(QStringLiteral("%1x%2").arg(screen.width()).arg(screen.height()).toStdString());
    MainWindow window;
    ASSERT_NO_FATAL_FAILURE(showAt(window, screen));
    auto* panel = window.findChild<HardwarePanel*>();
    ASSERT_NE(panel, nullptr);
    panel->connectionForm()->setKind(DeviceKind::RotaryPlatform);
    panel->connectionForm()->setSettings(hardware::test::fastSettings(sim.port(), 1));
    auto* windowEstop = window.findChild<QPushButton*>(QStringLiteral("windowEstopButton"));
    ASSERT_NE(windowEstop, nullptr);
    EXPECT_FALSE(windowEstop->isVisible());  // nothing to stop yet

    panel->connectDevice();
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->deviceLink()->snapshot().state == DeviceState::Connected; },
                                kWaitMs));
    auto* panelEstop = panel->findChild<QPushButton*>(QStringLiteral("estopButton"));
    ASSERT_NE(panelEstop, nullptr);
    for (const char* dockName : {"planDock", "searchDock", "hardwareDock"}) {
      SCOPED_TRACE(dockName);
      window.findChild<QDockWidget*>(QString::fromLatin1(dockName))->raise();
      QCoreApplication::processEvents();
      // The window's E-STOP whatever is raised; the panel's own when its dock is, never scrolled away.
      std::vector<QPushButton*> shown = {windowEstop};
      if (QLatin1String(dockName) == QLatin1String("hardwareDock")) shown.push_back(panelEstop);
      const QImage picture = window.grab().toImage();
      for (QPushButton* estop : shown) {
        EXPECT_TRUE(whollyInView(estop, &window)) << estop->objectName().toStdString() << " at "
                                                  << rectIn(estop, &window).y();
        EXPECT_TRUE(estop->isEnabled());
        // The whole text fits, and the button is drawn red where it is.
        EXPECT_GE(estop->width(), estop->sizeHint().width()) << estop->text().toStdString();
        const QImage area = picture.copy(rectIn(estop, &window));
        EXPECT_GT(redPixels(area), area.width() * area.height() / 3) << estop->objectName().toStdString();
      }
    }
    panel->disconnectDevice();
    QCoreApplication::processEvents();
    EXPECT_FALSE(windowEstop->isVisible());
  }
}

INSTANTIATE_TEST_SUITE_P(Languages, StudioEmergencyStop, ::testing::Values("en", "de", "zh_CN"));

TEST(StudioMachineAndHardware, HardwareDeviceFollowsTheMachineTab) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showAt(window, QSize(1366, 768)));
  auto* panel = window.findChild<HardwarePanel*>();
  ASSERT_NE(panel, nullptr);
  core::MachineSpec arm;
  arm.kind = core::MachineKind::TiltRotate;
  window.findChild<MachinePanel*>()->setMachineSpec(arm);
  QCoreApplication::processEvents();
  EXPECT_EQ(panel->connectionForm()->kind(), DeviceKind::RobotArm);
  core::MachineSpec platform;
  platform.kind = core::MachineKind::RotaryPlatform;
  window.findChild<MachinePanel*>()->setMachineSpec(platform);
  QCoreApplication::processEvents();
  EXPECT_EQ(panel->connectionForm()->kind(), DeviceKind::RotaryPlatform);
}

}  // namespace
}  // namespace multidir::ui
