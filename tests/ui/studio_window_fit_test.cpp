// A new window opens fitting the screen it is on, title bar and frame included.
#include <gtest/gtest.h>

#include <QScreen>
#include <QTest>

#include "ui/main_window.h"
#include "ui/project/window_state.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

TEST(StudioWindowFit, NewWindowSizeFitsInsideA1280x720Screen) {
  const QSize available(1280, 720);
  const QSize size = initialWindowSize(available);
  EXPECT_LT(size.width(), available.width());
  EXPECT_LT(size.height(), available.height());
  // Room for a title bar of 40 px.
  EXPECT_LE(size.height() + 40, available.height());
}

TEST(StudioWindowFit, NewWindowKeepsThePreferredSizeOnALargeScreen) {
  EXPECT_EQ(initialWindowSize(QSize(1920, 1080)), kPreferredWindowSize);
}

// The window can be that small: its docks and toolbars do not hold it larger than the size it opens at.
TEST(StudioWindowFit, WindowOpenedForA1280x720ScreenKeepsItsSize) {
  test::resetStudioSettings();
  MainWindow window;
  const QSize size = initialWindowSize(QSize(1280, 720));
  window.resize(size);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  EXPECT_EQ(window.size(), size);
}

TEST(StudioWindowFit, NewWindowFitsItsScreensAvailableArea) {
  test::resetStudioSettings();  // nothing restored: the window opens at its initial size
  MainWindow window;
  ASSERT_NE(window.screen(), nullptr);
  const QSize available = window.screen()->availableGeometry().size();
  EXPECT_EQ(window.size(), initialWindowSize(available));
  EXPECT_LE(window.width(), available.width());
  EXPECT_LE(window.height(), available.height());
}

}  // namespace
}  // namespace multidir::ui
