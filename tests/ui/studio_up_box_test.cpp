// The Up box (issue 29, [cosmetic]): an entry a pose search added is shown whole, not cut to "Po:".
#include <gtest/gtest.h>

#include <QComboBox>
#include <QFontMetrics>

#include "ui/main_window.h"
#include "ui/studio_test_support.h"

namespace multidir::ui {
namespace {

TEST(StudioUpBox, PoseEntryIsShownWhole) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  auto* upBox = window.findChild<QComboBox*>(QStringLiteral("upBox"));
  ASSERT_NE(upBox, nullptr);
  UpPose pose;
  pose.up = core::Vec3(0.6, 0.0, 0.8);
  pose.pose.platformUp = core::Vec3::UnitZ();
  pose.pose.source = "hull-face";
  window.setUpPose(pose);
  ASSERT_TRUE(upBox->currentText().startsWith(QStringLiteral("Pose"))) << upBox->currentText().toStdString();

  const int textWidth = QFontMetrics(upBox->font()).horizontalAdvance(upBox->currentText());
  EXPECT_TRUE(test::waitUntil([&] { return upBox->width() >= textWidth; }, 2000))
      << "the box is " << upBox->width() << " px wide for " << textWidth << " px of text";
}

}  // namespace
}  // namespace multidir::ui
