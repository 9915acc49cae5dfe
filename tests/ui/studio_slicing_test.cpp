// Slicing in the studio (issue 12, item 8): the Slice button under the Plan dock slices the plan shown with its
// supports off the GUI thread (progress, Cancel), the estimates table, the G-code preview (toolpaths in the
// step colours, a layer slider, travel moves), Export G-code, and the error for a missing slicer.
#include <gtest/gtest.h>

#include <signal.h>

#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSlider>
#include <QStringList>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "multidir/slicing/printer_profile.h"
#include "support/test_models.h"
#include "ui/device/hardware_panel.h"
#include "ui/jobs/slice_job_runner.h"
#include "ui/main_window.h"
#include "ui/panels/slice_panel.h"
#include "ui/picture_census.h"
#include "ui/common/region_palette.h"
#include "ui/slicing/slice_dialog.h"
#include "ui/slicing/slice_session.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/gcode_toolpaths.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// A guard against a hang, not a limit the tests check: under ctest -j2 on two busy cores the snowman's five
// steps and the comparison took over two minutes.
constexpr int kSliceTimeoutMs = 240000;

// Coarse layers and sparse infill on the robot's 0.8 mm nozzle: the snowman's steps slice in about a second.
const QString kCoarse = QStringLiteral("layer_height=0.6 first_layer_height=0.6 perimeters=1 top_solid_layers=1 "
                                       "bottom_solid_layers=1 fill_density=0% gcode_comments=0");

SliceChoice robotChoice(const std::string& slicer = "prusa-slicer") {
  SliceChoice choice;
  const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile("robot-0.8");
  EXPECT_TRUE(profile.ok());
  if (profile) choice.profile = *profile;
  choice.options.settings = *slicing::parseSettingAssignments(kCoarse.toStdString());
  choice.options.fixedDirection = false;
  choice.options.slicerExecutable = slicer;
  return choice;
}

SlicePanel* slicePanelOf(MainWindow& window) { return window.findChild<SlicePanel*>(QStringLiteral("slicePanel")); }

// The default sample's quick plan (5-DOF, with supports), shown.
void showSnowmanPlan(MainWindow& window) {
  test::resetStudioSettings();
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  const SearchRun run = test::runQuickSearch(window);
  ASSERT_TRUE(run.plan);
  ASSERT_TRUE(run.supports) << run.supportsNote.toStdString();
}

int rowsOfKind(const QTableWidget& table, SlicePanel::RowKind kind) {
  int count = 0;
  for (int row = 0; row < table.rowCount(); ++row)
    if (table.item(row, 0)->data(Qt::UserRole).toInt() == static_cast<int>(kind)) ++count;
  return count;
}

double secondsOfRow(const QTableWidget& table, SlicePanel::RowKind kind) {
  for (int row = 0; row < table.rowCount(); ++row)
    if (table.item(row, 0)->data(Qt::UserRole).toInt() == static_cast<int>(kind))
      return table.item(row, SlicePanel::kTimeColumn)->data(Qt::UserRole).toDouble();
  return -1.0;
}

QImage settledPicture(MeshViewerWidget* viewer) {
  QSignalSpy frame(viewer, &MeshViewerWidget::frameRendered);
  viewer->update();
  frame.wait(2000);
  return viewer->grabFramebuffer();
}

// One window shows the snowman's quick plan sliced through the Slice dialog (with the fixed-direction
// comparison): PrusaSlicer takes a few seconds per step, so the tests that read a result share it.
class StudioSlicedSnowman : public ::testing::Test {
 protected:
  // Made by the first test that runs (ctest runs each test in its own process): a failure here is that
  // test's failure, and the tests after it fail too, instead of being skipped.
  static void prepare() {
    s_attempted = true;
    s_window = new MainWindow;
    showSnowmanPlan(*s_window);
    if (::testing::Test::HasFatalFailure()) return;
    SlicePanel* panel = slicePanelOf(*s_window);
    ASSERT_NE(panel, nullptr);
    ASSERT_TRUE(panel->sliceButton()->isEnabled());
    QSignalSpy sliced(s_window->sliceSession(), &SliceSession::sliced);
    QSignalSpy failed(s_window->sliceSession(), &SliceSession::sliceFailed);
    QSignalSpy progress(s_window->sliceSession()->runner(), &SliceJobRunner::progressed);
    panel->sliceButton()->click();
    auto* dialog = s_window->findChild<SliceDialog*>(QStringLiteral("sliceDialog"));
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(dialog->selectPrinter(QStringLiteral("robot-0.8")));
    dialog->setSettingsText(kCoarse);
    dialog->setComparison(true);
    dialog->setSlicerProgram(QStringLiteral("prusa-slicer"));
    dialog->accept();
    ASSERT_TRUE(s_window->sliceSession()->isSlicing());
    ASSERT_TRUE(test::waitUntil([&] { return !sliced.isEmpty() || !failed.isEmpty(); }, kSliceTimeoutMs));
    ASSERT_TRUE(failed.isEmpty()) << failed.front().front().toString().toStdString();
    for (const QList<QVariant>& report : progress) s_stages << report.at(1).toString();
    s_ready = true;
  }
  static void TearDownTestSuite() {
    delete s_window;
    s_window = nullptr;
    s_attempted = false;
    s_ready = false;
  }
  void SetUp() override {
    if (!s_attempted) prepare();
    ASSERT_TRUE(s_ready) << "the snowman's plan could not be sliced (see the first test)";
  }

  static MainWindow* s_window;
  static bool s_attempted;
  static bool s_ready;
  static QStringList s_stages;  // what the progress said, in order
};

MainWindow* StudioSlicedSnowman::s_window = nullptr;
bool StudioSlicedSnowman::s_attempted = false;
bool StudioSlicedSnowman::s_ready = false;
QStringList StudioSlicedSnowman::s_stages;

TEST_F(StudioSlicedSnowman, SliceButtonGivesOneEstimateRowPerStepAPositiveTotalAndTheComparison) {
  MainWindow& window = *s_window;
  SlicePanel* panel = slicePanelOf(window);
  const int steps = static_cast<int>(window.plan()->plan->regions.size());
  const QTableWidget& table = *panel->estimatesTable();
  EXPECT_EQ(rowsOfKind(table, SlicePanel::RowKind::Step), steps);
  EXPECT_EQ(rowsOfKind(table, SlicePanel::RowKind::Total), 1);
  EXPECT_EQ(rowsOfKind(table, SlicePanel::RowKind::FixedDirection), 1);
  EXPECT_GT(secondsOfRow(table, SlicePanel::RowKind::Total), 0.0);
  EXPECT_GT(secondsOfRow(table, SlicePanel::RowKind::FixedDirection), 0.0);
  // The progress said which step was being sliced.
  EXPECT_TRUE(s_stages.contains(QStringLiteral("Slicing step 1 of %1").arg(steps))) << s_stages.join(QStringLiteral(" | ")).toStdString();
  EXPECT_TRUE(s_stages.contains(QStringLiteral("Slicing step %1 of %1").arg(steps)));
  EXPECT_TRUE(panel->exportButton()->isEnabled());
  EXPECT_TRUE(window.findChild<QAction*>(QStringLiteral("exportGcode"))->isEnabled());
}

TEST_F(StudioSlicedSnowman, PreviewDrawsEachStepInItsColourTheLayerSliderLimitsItAndTravelMovesAreAToggle) {
  MainWindow& window = *s_window;
  SlicePanel* panel = slicePanelOf(window);
  MeshViewerWidget* viewer = window.viewer();
  const int steps = static_cast<int>(window.sliceSession()->outcome()->job->steps.size());
  ASSERT_GE(steps, 2);
  const int planColours = test::regionColoursSeen(settledPicture(viewer), steps, 0.0005);

  ASSERT_TRUE(panel->previewButton()->isEnabled());
  panel->previewButton()->click();
  ASSERT_TRUE(viewer->hasGcodePreview());
  const int allLines = viewer->gcodeExtrusionLinesShown();
  EXPECT_GT(allLines, 0);
  EXPECT_EQ(viewer->gcodeTravelLinesShown(), 0);  // travel moves are off at first
  const QImage all = settledPicture(viewer);
  // The regions are hidden: what shows in a step's colour is its toolpaths.
  for (int step = 0; step < steps; ++step)
    EXPECT_GT(test::colourFraction(all, regionColor(step)), 0.0002) << "step " << step + 1;
  // The runner audited the job: its unsupported extrusions are marked, drawn in the warning colour and
  // counted under the estimates.
  const GcodePreview& preview = *window.sliceSession()->outcome()->preview;
  EXPECT_TRUE(preview.audited) << window.sliceSession()->outcome()->auditError.toStdString();
  EXPECT_TRUE(panel->unsupportedLabel()->isVisibleTo(panel));
  EXPECT_TRUE(panel->unsupportedLabel()->text().startsWith(QStringLiteral("Unsupported extrusion: ")));
  EXPECT_EQ(viewer->gcodeUnsupportedLinesShown() > 0, preview.unsupportedMm > 0.0);

  QSlider* slider = panel->layerSlider();
  ASSERT_TRUE(slider->isEnabled());
  ASSERT_GT(slider->maximum(), 2);
  EXPECT_EQ(slider->value(), slider->maximum());
  slider->setValue(slider->maximum() / 3);
  EXPECT_LT(viewer->gcodeExtrusionLinesShown(), allLines);
  EXPECT_GT(viewer->gcodeExtrusionLinesShown(), 0);
  const QImage fewer = settledPicture(viewer);
  EXPECT_LT(test::colourFraction(fewer, regionColor(steps - 1)), test::colourFraction(all, regionColor(steps - 1)));

  const double travelBefore = test::colourFraction(fewer, MeshViewerWidget::gcodeTravelColor());
  panel->travelBox()->setChecked(true);
  EXPECT_GT(viewer->gcodeTravelLinesShown(), 0);
  const QImage travel = settledPicture(viewer);
  EXPECT_GT(test::colourFraction(travel, MeshViewerWidget::gcodeTravelColor()), travelBefore + 0.0002);

  // Back to the plan view: the regions again, no toolpaths.
  panel->previewButton()->click();
  EXPECT_FALSE(viewer->hasGcodePreview());
  EXPECT_EQ(viewer->gcodeExtrusionLinesShown(), 0);
  EXPECT_EQ(test::regionColoursSeen(settledPicture(viewer), steps, 0.0005), planColours);
  panel->travelBox()->setChecked(false);
  slider->setValue(slider->maximum());
}

TEST_F(StudioSlicedSnowman, LayerSliderShowsItsLayersZBesideIt) {
  MainWindow& window = *s_window;
  SlicePanel* panel = slicePanelOf(window);
  panel->previewButton()->click();
  ASSERT_TRUE(window.viewer()->hasGcodePreview());
  QSlider* slider = panel->layerSlider();
  QLabel* z = panel->layerZLabel();
  ASSERT_NE(z, nullptr);
  EXPECT_TRUE(z->isVisibleTo(panel));
  // Beside the slider: on its row, to its right.
  const QRect sliderRect(slider->mapTo(panel, QPoint(0, 0)), slider->size());
  const QRect zRect(z->mapTo(panel, QPoint(0, 0)), z->size());
  EXPECT_GE(zRect.left(), sliderRect.right());
  EXPECT_TRUE(zRect.top() <= sliderRect.center().y() && sliderRect.center().y() <= zRect.bottom());
  const GcodePreview& preview = *window.sliceSession()->outcome()->preview;
  for (const int layer : {1, slider->maximum() / 2, slider->maximum()}) {
    slider->setValue(layer);
    const double zMm = preview.layers[static_cast<std::size_t>(layer - 1)].printerZMm;
    EXPECT_EQ(z->text(), QStringLiteral("Z %1 mm").arg(QLocale().toString(zMm, 'f', 2))) << "layer " << layer;
  }
  EXPECT_NE(preview.layers.front().printerZMm, preview.layers[static_cast<std::size_t>(slider->maximum() / 2 - 1)].printerZMm);
  panel->previewButton()->click();
  EXPECT_FALSE(z->isVisibleTo(panel));
}

TEST_F(StudioSlicedSnowman, ExportGcodeWritesTheStepProgramsAndTheJobIntoANewFolder) {
  MainWindow& window = *s_window;
  QTemporaryDir scratch;
  ASSERT_TRUE(scratch.isValid());
  const QString folder = scratch.filePath(QStringLiteral("new/snowman-gcode"));
  QString error;
  ASSERT_TRUE(window.sliceSession()->exportGcode(folder, &error)) << error.toStdString();
  const auto& job = *window.sliceSession()->outcome()->job;
  for (const slicing::SlicedStep& step : job.steps) {
    const QFileInfo file(QDir(folder).filePath(QString::fromStdString(step.gcodeFile)));
    EXPECT_TRUE(file.exists()) << step.gcodeFile;
    EXPECT_GT(file.size(), 0);
  }
  EXPECT_FALSE(QFileInfo::exists(QDir(folder).filePath(QStringLiteral("job.gcode"))));  // the robot turns over Modbus
  QFile jobFile(QDir(folder).filePath(QStringLiteral("print-job.json")));
  ASSERT_TRUE(jobFile.open(QIODevice::ReadOnly));
  EXPECT_TRUE(jobFile.readAll().contains("\"slicing\""));
  EXPECT_TRUE(QDir(folder).entryList({QStringLiteral("*.part")}, QDir::Files).isEmpty());

  // A file where the folder should be is refused, saying so.
  const QString aFile = scratch.filePath(QStringLiteral("not-a-folder"));
  QFile(aFile).open(QIODevice::WriteOnly);
  EXPECT_FALSE(window.sliceSession()->exportGcode(aFile, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("is a file, not a folder"))) << error.toStdString();
}

TEST_F(StudioSlicedSnowman, TheHardwarePanelGetsEveryStepsGcodeAndEstimateForThePrinter) {
  MainWindow& window = *s_window;
  auto* hardware = window.findChild<HardwarePanel*>();
  ASSERT_NE(hardware, nullptr);
  const auto& job = *window.sliceSession()->outcome()->job;
  const std::vector<StepGcode> gcode = hardware->jobGcode();
  ASSERT_EQ(gcode.size(), job.steps.size());
  for (std::size_t k = 0; k < job.steps.size(); ++k) {
    const StepGcode& step = gcode[k];
    EXPECT_EQ(QFileInfo(QString::fromStdString(step.path)).fileName().toStdString(), job.steps[k].gcodeFile);
    EXPECT_TRUE(QFileInfo::exists(QString::fromStdString(step.path))) << step.path;
    EXPECT_DOUBLE_EQ(step.estimateSeconds, job.steps[k].estimate.printSeconds);
  }
  EXPECT_TRUE(hardware->findChild<QLabel*>(QStringLiteral("planSummaryText"))->text().contains(QStringLiteral("Sliced")));
}

// One window shows the snowman's quick plan for the tests of slicing that goes wrong or is stopped: each
// leaves the plan shown and no result, as it found them.
class StudioSnowmanPlan : public ::testing::Test {
 protected:
  // Made by the first test that runs, as in StudioSlicedSnowman.
  static void prepare() {
    s_attempted = true;
    s_window = new MainWindow;
    showSnowmanPlan(*s_window);
    s_ready = !::testing::Test::HasFatalFailure();
  }
  static void TearDownTestSuite() {
    delete s_window;
    s_window = nullptr;
    s_attempted = false;
    s_ready = false;
  }
  void SetUp() override {
    if (!s_attempted) prepare();
    ASSERT_TRUE(s_ready) << "the snowman's plan could not be shown";
    ASSERT_FALSE(s_window->sliceSession()->isSlicing());
  }

  static MainWindow* s_window;
  static bool s_attempted;
  static bool s_ready;
};

MainWindow* StudioSnowmanPlan::s_window = nullptr;
bool StudioSnowmanPlan::s_attempted = false;
bool StudioSnowmanPlan::s_ready = false;

TEST_F(StudioSnowmanPlan, CancelStopsTheSlicerLeavesNoFilesAndKeepsThePlan) {
  MainWindow& window = *s_window;
  const auto planBefore = window.plan()->plan;
  // A slicer that never ends on its own: it writes its process id, then waits.
  QTemporaryDir scratch;
  ASSERT_TRUE(scratch.isValid());
  const QString pidFile = scratch.filePath(QStringLiteral("slicer.pid"));
  const QString fake = scratch.filePath(QStringLiteral("slow-slicer.sh"));
  {
    QFile script(fake);
    ASSERT_TRUE(script.open(QIODevice::WriteOnly));
    script.write(QStringLiteral("#!/bin/sh\necho $$ > '%1'\nexec sleep 60\n").arg(pidFile).toUtf8());
  }
  QFile::setPermissions(fake, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
  SliceSession* session = window.sliceSession();
  QSignalSpy cancelled(session, &SliceSession::sliceCancelled);
  ASSERT_TRUE(session->slice(robotChoice(QFile::encodeName(fake).toStdString())));
  const QString work = session->runner()->workFolder();
  ASSERT_FALSE(work.isEmpty());
  ASSERT_TRUE(test::waitUntil([&] { return QFileInfo::exists(pidFile); }, 20000)) << "the slicer never started";
  SlicePanel* panel = slicePanelOf(window);
  ASSERT_TRUE(panel->cancelButton()->isVisible());
  panel->cancelButton()->click();
  ASSERT_TRUE(cancelled.wait(20000));

  QFile pidText(pidFile);
  ASSERT_TRUE(pidText.open(QIODevice::ReadOnly));
  const pid_t pid = static_cast<pid_t>(pidText.readAll().trimmed().toLong());
  EXPECT_NE(::kill(pid, 0), 0) << "the slicer (pid " << pid << ") still runs";
  EXPECT_FALSE(QFileInfo::exists(work)) << "the job's folder is still there";
  EXPECT_FALSE(session->outcome().has_value());
  EXPECT_EQ(panel->estimatesTable()->rowCount(), 0);
  EXPECT_TRUE(window.findChild<HardwarePanel*>()->jobGcode().empty());
  EXPECT_FALSE(panel->exportButton()->isEnabled());
  EXPECT_FALSE(window.findChild<QAction*>(QStringLiteral("exportGcode"))->isEnabled());
  ASSERT_TRUE(window.plan().has_value());
  EXPECT_EQ(window.plan()->plan, planBefore);
  EXPECT_TRUE(window.viewer()->hasPlan());
  EXPECT_TRUE(panel->sliceButton()->isEnabled());
}

TEST_F(StudioSnowmanPlan, MissingSlicerShowsTheDocumentedErrorAndKeepsThePlan) {
  MainWindow& window = *s_window;
  const auto planBefore = window.plan()->plan;
  SliceSession* session = window.sliceSession();
  QSignalSpy failed(session, &SliceSession::sliceFailed);
  ASSERT_TRUE(session->slice(robotChoice("/nonexistent/prusa-slicer")));
  ASSERT_TRUE(failed.wait(kSliceTimeoutMs));
  const QString shown = slicePanelOf(window)->messageLabel()->text();
  EXPECT_TRUE(shown.contains(QStringLiteral("The slicer '/nonexistent/prusa-slicer' was not found"))) << shown.toStdString();
  // The library's documented message, in full: the command as it would have run.
  EXPECT_TRUE(shown.contains(QStringLiteral("was not found (no executable of that name on PATH)"))) << shown.toStdString();
  EXPECT_TRUE(shown.contains(QStringLiteral("/nonexistent/prusa-slicer --loglevel 1 --export-gcode"))) << shown.toStdString();
  EXPECT_FALSE(session->outcome().has_value());
  EXPECT_EQ(window.plan()->plan, planBefore);
  EXPECT_TRUE(window.viewer()->hasPlan());
}

TEST_F(StudioSnowmanPlan, APartTooBigForTheBedIsRefusedBeforeSlicingSayingByHowMuch) {
  MainWindow& window = *s_window;
  // A printer whose bed (30 x 30 mm) is smaller than the snowman: refused before the slicer runs.
  QTemporaryDir scratch;
  ASSERT_TRUE(scratch.isValid());
  const QString ini = scratch.filePath(QStringLiteral("tiny-bed.ini"));
  {
    QFile file(ini);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("# multidir.platform = modbus\nbed_shape = 0x0,30x0,30x30,0x30\nmax_print_height = 1000\n"
               "nozzle_diameter = 0.8\nskirts = 0\n");
  }
  const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(QFile::encodeName(ini).toStdString());
  ASSERT_TRUE(profile.ok()) << profile.error().describe();
  SliceChoice choice = robotChoice();
  choice.profile = *profile;
  SliceSession* session = window.sliceSession();
  QSignalSpy failed(session, &SliceSession::sliceFailed);
  ASSERT_TRUE(session->slice(choice));
  ASSERT_TRUE(failed.wait(kSliceTimeoutMs));
  const QString shown = slicePanelOf(window)->messageLabel()->text();
  EXPECT_TRUE(shown.contains(QStringLiteral("does not fit this printer, so nothing was sliced"))) << shown.toStdString();
  EXPECT_TRUE(shown.contains(QRegularExpression(QStringLiteral("step \\d+ reaches [0-9.]+ mm past the bed's"))))
      << shown.toStdString();
  EXPECT_TRUE(shown.contains(QStringLiteral("scale the model by"))) << shown.toStdString();
  EXPECT_FALSE(session->outcome().has_value());
  EXPECT_TRUE(window.viewer()->hasPlan());
}

// Issue 29: the slicing result goes with the plan, and a model without a plan is not told to slice it again.
TEST(StudioSlicingDocument, AnotherModelWithoutAPlanIsNotToldToSliceAgain) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showSnowmanPlan(window));
  SliceSession* session = window.sliceSession();
  QSignalSpy sliced(session, &SliceSession::sliced);
  QSignalSpy failed(session, &SliceSession::sliceFailed);
  ASSERT_TRUE(session->slice(robotChoice()));
  ASSERT_TRUE(test::waitUntil([&] { return !sliced.isEmpty() || !failed.isEmpty(); }, kSliceTimeoutMs));
  ASSERT_TRUE(failed.isEmpty()) << failed.front().front().toString().toStdString();
  ASSERT_TRUE(window.document()->slicedJob().has_value());
  auto* message = slicePanelOf(window)->findChild<QLabel*>(QStringLiteral("sliceMessage"));
  ASSERT_NE(message, nullptr);

  ASSERT_NO_FATAL_FAILURE(
      test::openModelFile(window, QString::fromStdString(test::sharedModelPath("bunny.off"))));
  EXPECT_FALSE(window.document()->slicedJob().has_value());
  EXPECT_FALSE(message->text().contains(QStringLiteral("slice it again"))) << message->text().toStdString();
  EXPECT_TRUE(message->isHidden()) << message->text().toStdString();
}

}  // namespace
}  // namespace multidir::ui
