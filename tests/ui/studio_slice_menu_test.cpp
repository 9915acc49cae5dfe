// Slice in the menu with a shortcut (issue 29, [missing]): Search > Slice the plan... (Ctrl+L) opens the same
// Slice dialog as the Plan dock's button, and only when a plan can be sliced.
#include <gtest/gtest.h>

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QTest>

#include "ui/main_window.h"
#include "ui/slicing/slice_dialog.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

TEST(StudioSliceMenu, CtrlLInTheSearchMenuOpensTheSliceDialogOnceThereIsAPlan) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  auto* slice = window.findChild<QAction*>(QStringLiteral("slicePlan"));
  ASSERT_NE(slice, nullptr);
  EXPECT_EQ(slice->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_L));
  bool inAMenu = false;
  for (QAction* menu : window.menuBar()->actions())
    if (menu->menu() && menu->menu()->actions().contains(slice)) inAMenu = true;
  EXPECT_TRUE(inAMenu);
  EXPECT_FALSE(slice->isEnabled());  // no plan yet

  const SearchRun run = test::runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  ASSERT_TRUE(test::waitUntil([&] { return slice->isEnabled(); })) << "Slice stays greyed with a plan shown";
  window.activateWindow();  // shortcuts reach the active window only
  ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
  window.viewer()->setFocus();
  QTest::keyClick(window.viewer(), Qt::Key_L, Qt::ControlModifier);
  auto* dialog = window.findChild<SliceDialog*>(QStringLiteral("sliceDialog"));
  ASSERT_NE(dialog, nullptr);
  ASSERT_TRUE(test::waitUntil([&] { return dialog->isVisible(); }));
  dialog->reject();
}

}  // namespace
}  // namespace multidir::ui
