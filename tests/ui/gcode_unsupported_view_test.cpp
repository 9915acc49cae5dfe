// The G-code preview's unsupported extrusions (issue 24, item 6): the extrusions the audit's check (b) finds
// resting on nothing are drawn in one warning colour, the panel says how much there is, and an audit that
// cannot run leaves the preview unmarked with its reason.
#include <gtest/gtest.h>

#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

#include "support/primitives.h"
#include "ui/jobs/preview_audit.h"
#include "ui/panels/slice_panel.h"
#include "ui/picture_census.h"
#include "ui/common/region_palette.h"
#include "ui/viewer/gcode_toolpaths.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// Twenty extrusions across the top of the 40 mm box, one step; the first `unsupported` of them marked.
std::shared_ptr<const GcodePreview> topOfTheBox(int unsupported) {
  auto preview = std::make_shared<GcodePreview>();
  preview->stepCount = 1;
  preview->layers.push_back({1, 1, 40.0});
  for (int i = 0; i < 20; ++i) {
    ToolpathSegment s;
    s.from = core::Vec3(-18.0, -18.0 + 1.8 * i, 40.0);
    s.to = core::Vec3(18.0, -18.0 + 1.8 * i, 40.0);
    s.line = 10 + i;
    s.unsupported = i < unsupported;
    preview->extrusions.push_back(s);
  }
  return preview;
}

QImage pictureOf(MeshViewerWidget& viewer) {
  QSignalSpy frame(&viewer, &MeshViewerWidget::frameRendered);
  viewer.update();
  frame.wait(2000);
  return viewer.grabFramebuffer();
}

TEST(GcodeUnsupportedView, MarkedExtrusionsShowInTheWarningColourAndAJobWithNoneShowsNone) {
  EXPECT_NE(unsupportedExtrusionColor(), regionColor(0));
  const core::TriangleMesh box = test::makeBox(core::Vec3(-20, -20, 0), core::Vec3(20, 20, 40));
  MeshViewerWidget viewer;
  viewer.resize(640, 480);
  viewer.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewer));
  viewer.setMesh(box, core::Vec3::UnitZ());
  auto plan = std::make_shared<core::Decomposition>();
  plan->regions.push_back({});
  plan->regions.back().mesh = box;
  viewer.setPlan(plan);

  ASSERT_TRUE(viewer.setGcodePreview(topOfTheBox(0)));
  EXPECT_EQ(viewer.gcodeExtrusionLinesShown(), 20);
  EXPECT_EQ(viewer.gcodeUnsupportedLinesShown(), 0);
  const QImage none = pictureOf(viewer);
  EXPECT_GT(test::colourFraction(none, regionColor(0)), 0.001);
  EXPECT_EQ(test::colourFraction(none, unsupportedExtrusionColor()), 0.0);

  ASSERT_TRUE(viewer.setGcodePreview(topOfTheBox(10)));
  EXPECT_EQ(viewer.gcodeExtrusionLinesShown(), 20);  // the marked ones count as extrusions still
  EXPECT_EQ(viewer.gcodeUnsupportedLinesShown(), 10);
  const QImage half = pictureOf(viewer);
  EXPECT_GT(test::colourFraction(half, unsupportedExtrusionColor()), 0.001);
  EXPECT_GT(test::colourFraction(half, regionColor(0)), 0.0005);  // the supported half keeps its step colour

  viewer.setGcodeLayerLimit(0);  // the layer slider hides the marks with their layer
  EXPECT_EQ(viewer.gcodeUnsupportedLinesShown(), 0);
  EXPECT_EQ(test::colourFraction(pictureOf(viewer), unsupportedExtrusionColor()), 0.0);
}

TEST(GcodeUnsupportedView, ThePanelSaysHowMuchExtrusionIsUnsupportedAndInWhichColour) {
  SlicePanel panel;
  EXPECT_FALSE(panel.unsupportedLabel()->isVisibleTo(&panel));
  panel.showUnsupported(true, 12.34, 0.5);
  EXPECT_TRUE(panel.unsupportedLabel()->isVisibleTo(&panel));
  EXPECT_EQ(panel.unsupportedLabel()->text(), QStringLiteral("Unsupported extrusion: 12.3 mm (0.5 %) in magenta"));
  panel.clearResult();
  EXPECT_FALSE(panel.unsupportedLabel()->isVisibleTo(&panel));
}

TEST(GcodeUnsupportedView, AnAuditThatCannotReadTheJobLeavesThePreviewUnmarkedAndSaysWhere) {
  QTemporaryDir empty;
  ASSERT_TRUE(empty.isValid());
  GcodePreview preview = *topOfTheBox(0);
  core::JobContext context;
  const core::Status status = markUnsupportedExtrusions(preview, empty.path().toStdString(), 45.0, context);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, core::ErrorCode::FileNotFound);
  EXPECT_NE(status.error().describe().find("print-job.json"), std::string::npos) << status.error().describe();
  EXPECT_FALSE(preview.audited);
  for (const ToolpathSegment& s : preview.extrusions) EXPECT_FALSE(s.unsupported);
}

}  // namespace
}  // namespace multidir::ui
