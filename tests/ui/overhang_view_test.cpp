// The overhang view: risky faces coloured on the model, alpha_max changing them live.
#include <gtest/gtest.h>

#include <QLocale>
#include <QSlider>

#include "multidir/core/analysis/overhang.h"
#include "ui/main_window.h"
#include "ui/panels/overhang_panel.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

void showDefaultSample(MainWindow& window) { test::showDefaultSample(window, QSize(1200, 800)); }

TEST(StudioOverhangs, RiskyFacesOfTheModelAreColouredAndCounted) {
  MainWindow window;
  showDefaultSample(window);
  const core::Result<core::OverhangAnalysis> expected = core::analyzeOverhang(*window.model()->mesh, window.upDirection());
  ASSERT_TRUE(expected.ok());
  ASSERT_GT(expected->riskyFaces, 0u);
  EXPECT_EQ(window.overhangPanel()->alphaMaxDegrees(), 45);
  EXPECT_EQ(window.viewer()->riskyFacesShown(), expected->riskyFaces);
  EXPECT_EQ(window.overhangPanel()->riskyAreaText(),
            QObject::tr("%1 mm²").arg(QLocale().toString(expected->riskyAreaMm2, 'f', 1)));
}

TEST(StudioOverhangs, MovingTheAlphaSliderChangesTheRiskyAreaShown) {
  MainWindow window;
  showDefaultSample(window);
  auto* slider = window.overhangPanel()->findChild<QSlider*>(QStringLiteral("alphaSlider"));
  ASSERT_NE(slider, nullptr);
  const QString at45 = window.overhangPanel()->riskyAreaText();
  const std::size_t faces45 = window.viewer()->riskyFacesShown();
  const QImage before = window.viewer()->grabFramebuffer();

  slider->setValue(10);  // a stricter printer: more faces need support
  EXPECT_EQ(window.overhangPanel()->alphaMaxDegrees(), 10);
  EXPECT_NE(window.overhangPanel()->riskyAreaText(), at45);
  EXPECT_GT(window.viewer()->riskyFacesShown(), faces45);
  EXPECT_NE(window.viewer()->grabFramebuffer(), before);

  slider->setValue(80);  // a lenient one: fewer
  EXPECT_LT(window.viewer()->riskyFacesShown(), faces45);
}

TEST(StudioOverhangs, FaceCountMismatchLeavesColoursAlone) {
  MainWindow window;
  showDefaultSample(window);
  const std::size_t shown = window.viewer()->riskyFacesShown();
  EXPECT_FALSE(window.viewer()->setRiskyFaces(std::vector<char>(3, 1)));
  EXPECT_EQ(window.viewer()->riskyFacesShown(), shown);
}

}  // namespace
}  // namespace multidir::ui
