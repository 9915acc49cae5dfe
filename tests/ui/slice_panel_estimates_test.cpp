// The Slice panel's estimates: when the multi-directional job takes longer than the fixed direction, a line
// beside the estimates says why; when it does not, nothing is said.
#include <gtest/gtest.h>

#include <QLabel>

#include "multidir/slicing/slice_job.h"
#include "ui/panels/slice_panel.h"

namespace multidir::ui {
namespace {

// A two-step job of `totalSeconds`, with the fixed direction taking `fixedSeconds`.
slicing::SlicedJob jobOf(double totalSeconds, double fixedSeconds) {
  slicing::SlicedJob job;
  for (int k = 1; k <= 2; ++k) {
    slicing::SlicedStep step;
    step.index = k;
    step.gcodeFile = "step-0" + std::to_string(k) + ".gcode";
    step.estimate.printSeconds = totalSeconds / 2.0;
    job.steps.push_back(step);
  }
  job.total.printSeconds = totalSeconds;
  slicing::Estimate fixed;
  fixed.printSeconds = fixedSeconds;
  job.fixedDirection = fixed;
  return job;
}

QLabel* slowerNote(const SlicePanel& panel) { return panel.findChild<QLabel*>(QStringLiteral("slowerThanFixedNote")); }

TEST(SlicePanelEstimates, AJobSlowerThanTheFixedDirectionSaysWhyBesideTheEstimates) {
  SlicePanel panel;
  panel.show();
  panel.showResult(jobOf(3600.0, 3000.0), 10);
  QLabel* note = slowerNote(panel);
  ASSERT_NE(note, nullptr);
  EXPECT_TRUE(note->isVisible());
  EXPECT_TRUE(note->text().startsWith(QStringLiteral("Slower than the fixed direction: each of the 2 steps")))
      << note->text().toStdString();
}

TEST(SlicePanelEstimates, AJobFasterThanTheFixedDirectionNeedsNoExplanation) {
  SlicePanel panel;
  panel.show();
  panel.showResult(jobOf(2400.0, 3000.0), 10);
  QLabel* note = slowerNote(panel);
  ASSERT_NE(note, nullptr);
  EXPECT_FALSE(note->isVisible());
  panel.showResult(jobOf(3600.0, 3000.0), 10);
  panel.clearResult();
  EXPECT_FALSE(note->isVisible());
}

}  // namespace
}  // namespace multidir::ui
