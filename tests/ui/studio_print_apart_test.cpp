// The studio's Print apart view (issue 27, item 4; docs/apart.md, "The studio"): Run prints the plan shown apart
// off the GUI thread, the parts are drawn exploded each in its own colour, the slicer's estimates per plate, for
// all plates and for the one piece, Export writes every file, a new plan empties the view, Cancel leaves nothing.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <cmath>

#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "support/primitives.h"
#include "support/test_models.h"
#include "ui/common/region_palette.h"
#include "ui/document/studio_document.h"
#include "ui/jobs/apart_job_runner.h"
#include "ui/main_window.h"
#include "ui/panels/apart_panel.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// A guard against a hang, not a limit the tests check: slicing runs PrusaSlicer on busy cores.
constexpr int kApartTimeoutMs = 240000;

ApartPanel* apartPanelOf(MainWindow& window) { return window.findChild<ApartPanel*>(QStringLiteral("apartPanel")); }

// The kitten searched for the apart machine (greedy, +Y up), saved without its model and opened in `window`.
void showKittensPlan(MainWindow& window, const QTemporaryDir& dir) {
  test::resetStudioSettings();
  window.resize(1400, 900);
  window.show();
  const core::TriangleMesh kitten = test::loadSharedModel("kitten.off");
  core::PlanMetadata metadata;
  metadata.up = core::Vec3::UnitY();
  metadata.machine.kind = core::MachineKind::Apart;
  metadata.machine.up = metadata.up;
  metadata.machine.rotationAxis = core::platformFrameX(metadata.up);
  metadata.options.scheme = core::SearchScheme::Greedy;
  core::JobContext job;
  const core::Result<core::Decomposition> plan = core::decompose(kitten, metadata.machine, metadata.options, job);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  ASSERT_GE(plan->regions.size(), 2u);
  const QString folder = dir.filePath(QStringLiteral("kitten-plan"));
  const core::Status saved = core::savePlan(*plan, metadata, folder.toStdString());
  ASSERT_TRUE(saved.ok()) << saved.error().describe();
  ASSERT_NO_FATAL_FAILURE(test::openPlanFolder(window, folder));
}

// Opens the Print apart view from its menu entry, as the user does.
ApartPanel* openApartView(MainWindow& window) {
  auto* action = window.findChild<QAction*>(QStringLiteral("printApart"));
  EXPECT_NE(action, nullptr);
  if (!action) return nullptr;
  EXPECT_TRUE(action->isEnabled());
  action->trigger();
  return apartPanelOf(window);
}

// Runs Print apart from the panel and waits until it finishes; false (with the panel's message) when it failed.
bool runApart(ApartPanel& panel) {
  QSignalSpy finished(panel.runner(), &ApartJobRunner::finished);
  QSignalSpy failed(panel.runner(), &ApartJobRunner::failed);
  panel.runButton()->click();
  EXPECT_TRUE(panel.runner()->isRunning());
  EXPECT_TRUE(test::waitUntil([&] { return !finished.isEmpty() || !failed.isEmpty(); }, kApartTimeoutMs));
  EXPECT_TRUE(failed.isEmpty()) << panel.messageLabel()->text().toStdString();
  // The document takes the result in the same turn of the event loop as the signal.
  return !finished.isEmpty() && test::waitUntil([&] { return !panel.runner()->isRunning(); });
}

QImage settledPicture(MeshViewerWidget* viewer) {
  QSignalSpy frame(viewer, &MeshViewerWidget::frameRendered);
  viewer->update();
  frame.wait(2000);
  return viewer->grabFramebuffer();
}

// Pixels whose colour points the way `colour` does in RGB space (flat shading under white light only scales a
// solid's colour), bright enough not to be a shadow.
int pixelsOfColour(const QImage& picture, const QColor& colour) {
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  const double cr = colour.redF(), cg = colour.greenF(), cb = colour.blueF();
  const double cn = std::sqrt(cr * cr + cg * cg + cb * cb);
  int count = 0;
  for (int y = 0; y < image.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = 0; x < image.width(); ++x) {
      const double r = qRed(line[x]), g = qGreen(line[x]), b = qBlue(line[x]);
      const double n = std::sqrt(r * r + g * g + b * b);
      if (r + g + b < 90.0 || n == 0.0) continue;
      if ((r * cr + g * cg + b * cb) / (n * cn) > 0.998) ++count;
    }
  }
  return count;
}

int rowsOfKind(const QTableWidget& table, ApartPanel::RowKind kind) {
  int count = 0;
  for (int row = 0; row < table.rowCount(); ++row)
    if (table.item(row, 0)->data(Qt::UserRole).toInt() == static_cast<int>(kind)) ++count;
  return count;
}

// A T on its stem (80 mm bar), searched for the apart machine and opened: small, so its plates and its one
// piece slice in seconds.
ApartPanel* tBarApartView(MainWindow& window, const QTemporaryDir& dir) {
  test::resetStudioSettings();
  window.resize(1400, 900);
  window.show();
  core::PlanMetadata metadata;
  metadata.machine.kind = core::MachineKind::Apart;
  metadata.machine.rotationAxis = core::platformFrameX(metadata.up);
  metadata.options.scheme = core::SearchScheme::Greedy;
  core::JobContext job;
  const core::Result<core::Decomposition> plan =
      core::decompose(test::makeTBar(10, 30, 80, 10, 10), metadata.machine, metadata.options, job);
  EXPECT_TRUE(plan.ok()) << plan.error().describe();
  if (!plan) return nullptr;
  const QString folder = dir.filePath(QStringLiteral("t-bar-plan"));
  const core::Status saved = core::savePlan(*plan, metadata, folder.toStdString());
  EXPECT_TRUE(saved.ok()) << saved.error().describe();
  test::openPlanFolder(window, folder);
  if (::testing::Test::HasFatalFailure()) return nullptr;
  return openApartView(window);
}

TEST(StudioPrintApart, RunOnTheKittensPlanDrawsEveryPartExplodedInItsOwnColour) {
  QTemporaryDir dir;
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showKittensPlan(window, dir));
  ApartPanel* panel = openApartView(window);
  ASSERT_NE(panel, nullptr);
  panel->sliceBox()->setChecked(false);  // the parts only: the picture does not need the slicer
  ASSERT_TRUE(runApart(*panel));
  ASSERT_TRUE(window.document()->apartPrint().has_value());
  const int parts = static_cast<int>(window.document()->apartPrint()->result->parts.size());
  ASSERT_GE(parts, 2);
  EXPECT_EQ(panel->viewBox()->currentIndex(), 0);  // "Parts exploded"
  EXPECT_EQ(panel->viewer()->solidCount(),
            parts + static_cast<int>(window.document()->apartPrint()->result->dowels.size()));
  const QImage picture = settledPicture(panel->viewer());
  const int minimum = picture.width() * picture.height() / 2000;  // 0.05 % of the view: more than a label's edge
  for (int p = 0; p < parts; ++p)
    EXPECT_GT(pixelsOfColour(picture, regionColor(p)), minimum) << "part " << p + 1 << " is not drawn in its colour";
}

TEST(StudioPrintApart, EstimatesTableHasARowPerPlateAllPlatesAndTheOnePieceWithSupports) {
  QTemporaryDir planDir;
  MainWindow window;
  ApartPanel* panel = tBarApartView(window, planDir);
  ASSERT_NE(panel, nullptr);
  ASSERT_TRUE(panel->sliceBox()->isChecked());
  ASSERT_TRUE(runApart(*panel));
  const int plates = window.document()->apartPrint()->result->plates.plates;
  ASSERT_GE(plates, 1);
  const QTableWidget& table = *panel->estimatesTable();
  EXPECT_EQ(table.rowCount(), plates + 2);
  EXPECT_EQ(rowsOfKind(table, ApartPanel::RowKind::Plate), plates);
  EXPECT_EQ(rowsOfKind(table, ApartPanel::RowKind::AllPlates), 1);
  EXPECT_EQ(rowsOfKind(table, ApartPanel::RowKind::OnePiece), 1);
  for (int row = 0; row < table.rowCount(); ++row)
    EXPECT_GT(table.item(row, ApartPanel::kTimeColumn)->data(Qt::UserRole).toDouble(), 0.0) << "row " << row;
}

TEST(StudioPrintApart, ExportWritesEveryPartThe3mfTheGcodeTheSheetAndApartJson) {
  QTemporaryDir planDir;
  MainWindow window;
  ApartPanel* panel = tBarApartView(window, planDir);
  ASSERT_NE(panel, nullptr);
  ASSERT_TRUE(runApart(*panel));
  ASSERT_TRUE(panel->exportButton()->isEnabled());
  const apart::ApartResult& result = *window.document()->apartPrint()->result;
  QTemporaryDir dir;
  const QString folder = dir.filePath(QStringLiteral("exported"));
  ASSERT_TRUE(panel->exportTo(folder)) << panel->messageLabel()->text().toStdString();
  for (std::size_t p = 1; p <= result.parts.size(); ++p)
    EXPECT_TRUE(QFileInfo::exists(folder + QStringLiteral("/part-%1.stl").arg(p, 2, 10, QLatin1Char('0')))) << p;
  for (int k = 1; k <= result.plates.plates; ++k)
    EXPECT_TRUE(QFileInfo::exists(folder + QStringLiteral("/plate-%1.gcode").arg(k))) << k;
  for (const char* name : {"parts.3mf", "whole.gcode", "assembly.html", "apart.json"})
    EXPECT_TRUE(QFileInfo::exists(folder + QLatin1Char('/') + QLatin1String(name))) << name;
}

TEST(StudioPrintApart, ANewPlanEmptiesTheView) {
  QTemporaryDir dir;
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showKittensPlan(window, dir));
  ApartPanel* panel = openApartView(window);
  ASSERT_NE(panel, nullptr);
  panel->sliceBox()->setChecked(false);
  ASSERT_TRUE(runApart(*panel));
  ASSERT_GT(panel->viewer()->solidCount(), 0);
  // Another plan of the same model, as a search or an opened plan brings.
  SearchRun another = *window.document()->plan();
  another.plan = std::make_shared<const core::Decomposition>(*another.plan);
  window.document()->setPlan(another);
  EXPECT_FALSE(window.document()->apartPrint().has_value());
  EXPECT_EQ(panel->viewer()->solidCount(), 0);
  EXPECT_EQ(panel->viewBox()->count(), 0);
  EXPECT_FALSE(panel->exportButton()->isEnabled());
}

TEST(StudioPrintApart, CancelWhileSlicingLeavesNoFilesAndNoResult) {
  QTemporaryDir planDir;
  MainWindow window;
  ApartPanel* panel = tBarApartView(window, planDir);
  ASSERT_NE(panel, nullptr);
  QSignalSpy cancelled(panel->runner(), &ApartJobRunner::cancelled);
  QSignalSpy finished(panel->runner(), &ApartJobRunner::finished);
  QString workFolder;
  QObject::connect(panel->runner(), &ApartJobRunner::progressed, panel, [&](double, const QString& stage) {
    if (stage.startsWith(QStringLiteral("Slicing plate")) && workFolder.isEmpty()) {
      workFolder = panel->runner()->workFolder();
      panel->cancelButton()->click();
    }
  });
  panel->runButton()->click();
  ASSERT_TRUE(test::waitUntil([&] { return !cancelled.isEmpty() || !finished.isEmpty(); }, kApartTimeoutMs));
  ASSERT_EQ(cancelled.size(), 1) << "the run was not cancelled";
  ASSERT_FALSE(workFolder.isEmpty());
  EXPECT_FALSE(QFileInfo::exists(workFolder)) << workFolder.toStdString();
  EXPECT_FALSE(window.document()->apartPrint().has_value());
  EXPECT_EQ(panel->viewer()->solidCount(), 0);
  EXPECT_FALSE(panel->exportButton()->isEnabled());
  EXPECT_TRUE(panel->runButton()->isEnabled());
}

}  // namespace
}  // namespace multidir::ui
