// The robot cell in the studio (issue 25, item 5; docs/robot-cell.md, "Studio"): the Machine tab's cell section
// (model, nozzle, calibration, table, Load/Save, the check, "Find extruder position"), and the viewer's cell
// view posing the sliced job on the arm under the fixed nozzle and drawing the reach map, and the Hardware dock
// running the job on the cell.
#include <gtest/gtest.h>
#include <unistd.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <filesystem>
#include <memory>

#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "multidir/hardware/ur_simulator.h"
#include "multidir/robot/cell_file.h"
#include "multidir/slicing/printer_profile.h"
#include "support/test_models.h"
#include "support/ur_test_support.h"
#include "ui/device/connection_form.h"
#include "ui/device/hardware_panel.h"
#include "ui/device/robot_cell_section.h"
#include "ui/document/studio_document.h"
#include "ui/main_window.h"
#include "ui/panels/cell_panel.h"
#include "ui/panels/cell_view_panel.h"
#include "ui/panels/machine_panel.h"
#include "ui/slicing/slice_dialog.h"
#include "ui/slicing/slice_session.h"
#include "ui/studio_test_support.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

constexpr int kLongTimeoutMs = 240000;  // a guard against a hang under a busy ctest, not a limit checked

template <typename T>
T* child(const QWidget& parent, const char* name) {
  T* found = parent.findChild<T*>(QString::fromLatin1(name));
  EXPECT_NE(found, nullptr) << name;
  return found;
}

// The studio with the snowman and the robot cell chosen as the machine.
void showCellMachine(MainWindow& window) {
  test::resetStudioSettings();
  ASSERT_NO_FATAL_FAILURE(test::showDefaultSample(window));
  auto* kind = child<QComboBox>(*window.machinePanel(), "machineKind");
  ASSERT_NE(kind, nullptr);
  const int item = kind->findText(QStringLiteral("5-DOF: robot arm under a fixed extruder"));
  ASSERT_GE(item, 0);
  kind->setCurrentIndex(item);
}

TEST(StudioRobotCell, ChoosingTheRobotCellShowsThePaperCellSound) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  CellPanel* panel = window.cellPanel();
  ASSERT_NE(panel, nullptr);
  EXPECT_TRUE(panel->isVisibleTo(window.machinePanel()));
  EXPECT_TRUE(window.machinePanel()->isRobotCell());
  EXPECT_EQ(window.machinePanel()->kind(), core::MachineKind::TiltRotate);
  ASSERT_TRUE(window.document()->cell().has_value());
  EXPECT_EQ(child<QComboBox>(*panel, "cellRobotModel")->currentData().toString(), QStringLiteral("ur5"));
  EXPECT_DOUBLE_EQ(child<QDoubleSpinBox>(*panel, "cellNozzleY")->value(), -500.0);
  EXPECT_DOUBLE_EQ(child<QDoubleSpinBox>(*panel, "cellNozzleZ")->value(), 400.0);
  EXPECT_DOUBLE_EQ(child<QDoubleSpinBox>(*panel, "cellFlangeZ")->value(), 50.0);
  EXPECT_TRUE(panel->checkText().startsWith(QStringLiteral("Cell check: sound"))) << panel->checkText().toStdString();

  // Another machine hides the section.
  child<QComboBox>(*window.machinePanel(), "machineKind")->setCurrentIndex(0);
  EXPECT_FALSE(panel->isVisibleTo(window.machinePanel()));
}

TEST(StudioRobotCell, ChoosingTheRobotCellMachineSelectsTheRobotCellInTheHardwareDock) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  EXPECT_TRUE(window.document()->machineIsRobotCell());
  EXPECT_EQ(window.hardwarePanel()->connectionForm()->kind(), DeviceKind::RobotCell);

  // The 5-DOF machine whose arm tilts the platform under a printer is the robot arm device.
  auto* kind = child<QComboBox>(*window.machinePanel(), "machineKind");
  ASSERT_NE(kind, nullptr);
  const int arm = kind->findData(static_cast<int>(core::MachineKind::TiltRotate));
  ASSERT_GE(arm, 0);
  kind->setCurrentIndex(arm);
  EXPECT_FALSE(window.document()->machineIsRobotCell());
  EXPECT_EQ(window.hardwarePanel()->connectionForm()->kind(), DeviceKind::RobotArm);
}

TEST(StudioRobotCell, EditedFieldsGoIntoTheDocumentAndTheCheckNamesTheKey) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  CellPanel* panel = window.cellPanel();
  child<QComboBox>(*panel, "cellRobotModel")->setCurrentIndex(
      child<QComboBox>(*panel, "cellRobotModel")->findData(QStringLiteral("ur10e")));
  EXPECT_EQ(window.document()->cell()->arm.name, "ur10e");
  child<QDoubleSpinBox>(*panel, "cellNozzleX")->setValue(35.5);
  EXPECT_DOUBLE_EQ(window.document()->cell()->nozzleTipMm.x(), 35.5);
  child<QDoubleSpinBox>(*panel, "cellTableZ")->setValue(450.0);  // above the nozzle tip at z 400
  EXPECT_DOUBLE_EQ(window.document()->cell()->tableZMm, 450.0);
  EXPECT_TRUE(panel->checkText().contains(QStringLiteral("tableZMm"))) << panel->checkText().toStdString();
  EXPECT_FALSE(panel->checkText().contains(QStringLiteral("sound")));
}

TEST(StudioRobotCell, SavedCellLoadsBackIntoTheFields) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  CellPanel* panel = window.cellPanel();
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("lab-cell.json"));
  child<QDoubleSpinBox>(*panel, "cellNozzleX")->setValue(25.5);
  child<QDoubleSpinBox>(*panel, "cellFlangeRz")->setValue(15.0);
  ASSERT_TRUE(panel->saveCellFile(path)) << panel->messageText().toStdString();
  child<QDoubleSpinBox>(*panel, "cellNozzleX")->setValue(0.0);
  child<QDoubleSpinBox>(*panel, "cellFlangeRz")->setValue(0.0);
  ASSERT_TRUE(panel->loadCellFile(path)) << panel->messageText().toStdString();
  EXPECT_DOUBLE_EQ(child<QDoubleSpinBox>(*panel, "cellNozzleX")->value(), 25.5);
  EXPECT_NEAR(child<QDoubleSpinBox>(*panel, "cellFlangeRz")->value(), 15.0, 1e-9);
  EXPECT_DOUBLE_EQ(window.document()->cell()->nozzleTipMm.x(), 25.5);
}

TEST(StudioRobotCell, BrokenCellFileIsRefusedNamingTheKey) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  CellPanel* panel = window.cellPanel();
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("broken.json"));
  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write(R"({"format": "multidir-robot-cell", "version": 1, "robot": "ur5", "nozzleAxis": [0, 0, 1]})");
  file.close();
  const Eigen::Vector3d before = window.document()->cell()->nozzleTipMm;
  EXPECT_FALSE(panel->loadCellFile(path));
  EXPECT_TRUE(panel->messageText().contains(QStringLiteral("nozzleTipMm"))) << panel->messageText().toStdString();
  EXPECT_TRUE(panel->messageText().contains(QStringLiteral("broken.json")));
  EXPECT_EQ(window.document()->cell()->nozzleTipMm, before);
}

TEST(StudioRobotCell, FindExtruderPositionOffersTheBestAndUseItMovesTheNozzle) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  CellPanel* panel = window.cellPanel();
  child<QPushButton>(*panel, "cellFindNozzle")->click();
  EXPECT_TRUE(panel->isFindingPosition());
  EXPECT_TRUE(child<QPushButton>(*panel, "cellReachCancel")->isVisibleTo(panel));
  ASSERT_TRUE(test::waitUntil([&] { return !panel->isFindingPosition(); }, kLongTimeoutMs));
  ASSERT_TRUE(panel->bestPosition().has_value()) << panel->reachText().toStdString();
  EXPECT_TRUE(panel->reachText().startsWith(QStringLiteral("Best nozzle position"))) << panel->reachText().toStdString();
  EXPECT_GT(panel->bestPosition()->score, 0.0);
  auto* use = child<QPushButton>(*panel, "cellUseReach");
  ASSERT_TRUE(use->isVisibleTo(panel));
  use->click();
  EXPECT_LT((window.document()->cell()->nozzleTipMm - panel->bestPosition()->nozzleTipMm).norm(), 1e-9);
  EXPECT_NEAR(child<QDoubleSpinBox>(*panel, "cellNozzleZ")->value(), panel->bestPosition()->nozzleTipMm.z(), 0.01);
}

TEST(StudioRobotCell, FindExtruderPositionCancels) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  CellPanel* panel = window.cellPanel();
  ASSERT_TRUE(panel->findExtruderPosition());
  panel->cancelReach();
  ASSERT_TRUE(test::waitUntil([&] { return !panel->isFindingPosition(); }, kLongTimeoutMs));
  EXPECT_FALSE(panel->bestPosition().has_value());
  EXPECT_TRUE(panel->reachText().contains(QStringLiteral("cancelled"))) << panel->reachText().toStdString();
}

// Pixels of `image` within `tolerance` (per channel, 0..255) of `color`: their count and centroid.
struct Census {
  int count = 0;
  QPointF centroid;
};
Census census(const QImage& image, const QColor& color, int tolerance) {
  Census c;
  double x = 0, y = 0;
  for (int j = 0; j < image.height(); ++j)
    for (int i = 0; i < image.width(); ++i) {
      const QColor p = image.pixelColor(i, j);
      if (std::abs(p.red() - color.red()) <= tolerance && std::abs(p.green() - color.green()) <= tolerance &&
          std::abs(p.blue() - color.blue()) <= tolerance) {
        ++c.count;
        x += i;
        y += j;
      }
    }
  if (c.count > 0) c.centroid = QPointF(x / c.count, y / c.count);
  return c;
}

// What the arm carries, as drawn: the part (orange, lit or blended over what is behind it, told apart by hue) and
// its toolpath on it (drawn unlit in its own colour over the part's top).
Census partCensus(const QImage& image) {
  Census c;
  double x = 0, y = 0;
  const QColor toolpath = MeshViewerWidget::cellToolpathColor();
  for (int j = 0; j < image.height(); ++j)
    for (int i = 0; i < image.width(); ++i) {
      const QColor p = image.pixelColor(i, j);
      const bool part = p.red() > 90 && p.red() > p.green() + 20 && p.green() > p.blue() + 30;
      const bool path = std::abs(p.red() - toolpath.red()) <= 30 && std::abs(p.green() - toolpath.green()) <= 30 &&
                        std::abs(p.blue() - toolpath.blue()) <= 30;
      if (part || path) {
        ++c.count;
        x += i;
        y += j;
      }
    }
  if (c.count > 0) c.centroid = QPointF(x / c.count, y / c.count);
  return c;
}

QImage frameOf(MeshViewerWidget* viewer) {
  const std::size_t before = viewer->framesRendered();
  viewer->update();
  test::waitUntil([&] { return viewer->framesRendered() > before; });
  QImage image = viewer->grabFramebuffer();
  return image.scaled(viewer->size());  // logical pixels, as widgetPositionOf gives them
}


// The kitten at half size planned for a 5-DOF machine (the robot tests' job: it fits the cell's profile, where
// the snowman sample does not), opened in the studio as a plan folder, and sliced with the cell's profile.
void sliceHalfKittenOnTheCell(MainWindow& window, const QTemporaryDir& dir) {
  core::TriangleMesh model = test::loadSharedModel("kitten.off");
  for (core::Vec3& v : model.vertices) v *= 0.5;
  core::MachineSpec machine;
  machine.kind = core::MachineKind::TiltRotate;
  machine.up = core::Vec3::UnitY();
  core::PlanMetadata metadata;
  metadata.up = machine.up;
  metadata.machine = machine;
  metadata.options.scheme = core::SearchScheme::Greedy;
  metadata.multidirVersion = "test";
  core::JobContext job;
  const core::Result<core::Decomposition> plan = core::decompose(model, machine, metadata.options, job);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  const QString folder = dir.filePath(QStringLiteral("kitten-plan"));
  ASSERT_TRUE(core::savePlan(*plan, metadata, QFile::encodeName(folder).toStdString()).ok());
  ASSERT_NO_FATAL_FAILURE(test::openPlanFolder(window, folder));
  ASSERT_TRUE(test::waitUntil([&] { return !window.isGrowingSupports(); }, kLongTimeoutMs));
  SliceChoice choice;
  const auto profile = slicing::loadPrinterProfile("ur5-cell-0.8");
  ASSERT_TRUE(profile.ok());
  choice.profile = *profile;
  choice.options.settings = *slicing::parseSettingAssignments(
      "layer_height=0.6 first_layer_height=0.6 perimeters=1 top_solid_layers=1 bottom_solid_layers=1 "
      "fill_density=0% gcode_comments=0");
  choice.options.fixedDirection = false;
  SliceSession* session = window.sliceSession();
  QSignalSpy sliced(session, &SliceSession::sliced);
  QSignalSpy failed(session, &SliceSession::sliceFailed);
  ASSERT_TRUE(session->slice(choice));
  ASSERT_TRUE(test::waitUntil([&] { return !sliced.isEmpty() || !failed.isEmpty(); }, kLongTimeoutMs));
  ASSERT_TRUE(failed.isEmpty()) << failed.front().front().toString().toStdString();
  ASSERT_TRUE(window.document()->slicedJob().has_value());
}

TEST(StudioRobotCell, ViewerPosesThePartUnderTheFixedNozzle) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  QTemporaryDir dir;
  ASSERT_NO_FATAL_FAILURE(sliceHalfKittenOnTheCell(window, dir));

  CellViewPanel* panel = window.cellViewPanel();
  ASSERT_TRUE(panel->showOnCell()) << panel->statusText().toStdString();
  ASSERT_TRUE(test::waitUntil([&] { return !panel->isConverting(); }, kLongTimeoutMs));
  ASSERT_NE(panel->motion(), nullptr) << panel->statusText().toStdString();
  MeshViewerWidget* viewer = window.viewer();
  ASSERT_TRUE(viewer->hasCellMotion());
  const CellMotion& motion = *panel->motion();
  const robot::StepMotion& first = motion.steps.front();
  ASSERT_GE(first.samples.size(), 2u) << panel->warningsText().toStdString();

  auto* slider = child<QSlider>(*panel, "cellViewSlider");
  const Eigen::Vector3d tip = motion.cell.nozzleTipMm;
  struct Shot {
    Census part, point;
    QPointF tipOnScreen, pointOnScreen;
    core::Vec3 partCentre;
  };
  auto shoot = [&](int sliderValue) {
    slider->setValue(sliderValue);
    Shot s;
    const QImage image = frameOf(viewer);
    s.part = partCensus(image);
    s.point = census(image, MeshViewerWidget::cellToolpathPointColor(), 40);
    s.tipOnScreen = viewer->widgetPositionOf(tip).value_or(QPointF(-1e6, -1e6));
    s.pointOnScreen = viewer->widgetPositionOf(viewer->cellToolpathPointDrawn()).value_or(QPointF(1e6, 1e6));
    s.partCentre = viewer->cellPartCentreDrawn();
    return s;
  };
  const int last = static_cast<int>(first.samples.size()) - 1;
  const Shot a = shoot(0);
  const Shot b = shoot(last);
  for (const Shot* s : {&a, &b}) {
    // The toolpath point the move ends at is drawn where the nozzle tip is, on screen and in pixels.
    EXPECT_LT(std::hypot(s->pointOnScreen.x() - s->tipOnScreen.x(), s->pointOnScreen.y() - s->tipOnScreen.y()), 1.0);
    ASSERT_GT(s->point.count, 0);
    EXPECT_LT(std::hypot(s->point.centroid.x() - s->tipOnScreen.x(), s->point.centroid.y() - s->tipOnScreen.y()), 3.0);
    EXPECT_GT(s->part.count, 20);
  }
  // The part moved under the fixed nozzle between the two moves: in the scene and on the screen.
  EXPECT_GT((a.partCentre - b.partCentre).norm(), 1.0);
  EXPECT_GT(std::hypot(a.part.centroid.x() - b.part.centroid.x(), a.part.centroid.y() - b.part.centroid.y()), 1.0);
  auto* position = child<QLabel>(*panel, "cellViewPosition");
  EXPECT_TRUE(position->text().contains(QStringLiteral("line %1").arg(first.samples.back().line))) << position->text().toStdString();

  child<QPushButton>(*panel, "cellViewHide")->click();
  EXPECT_FALSE(viewer->hasCellMotion());
}

// The snowman's quick plan and "Find extruder position" run to its end: the map is kept by the cell panel and
// handed to the Cell view.
void findReachMap(MainWindow& window) {
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  ASSERT_TRUE(test::runQuickSearch(window).plan);
  ASSERT_TRUE(test::waitUntil([&] { return !window.isGrowingSupports(); }, kLongTimeoutMs));
  CellPanel* panel = window.cellPanel();
  ASSERT_TRUE(panel->findExtruderPosition()) << panel->reachText().toStdString();
  ASSERT_TRUE(test::waitUntil([&] { return !panel->isFindingPosition(); }, kLongTimeoutMs));
  ASSERT_NE(panel->reachMap(), nullptr) << panel->reachText().toStdString();
}

QColor reachColorOf(double score) {
  const auto c = robot::reachColour(score);
  return QColor(c[0], c[1], c[2]);
}

bool near(const QColor& a, const QColor& b, int tolerance) {
  return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
         std::abs(a.blue() - b.blue()) <= tolerance;
}

TEST(StudioRobotCell, ReachMapIsDrawnInTheCellViewWithTheBestInItsScoresColour) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(findReachMap(window));
  const CellReachMap& map = *window.cellPanel()->reachMap();
  CellViewPanel* panel = window.cellViewPanel();
  MeshViewerWidget* viewer = window.viewer();
  EXPECT_TRUE(panel->isReachMapShown());
  EXPECT_TRUE(viewer->hasCellMotion());  // the cell alone: no job is posed on it
  EXPECT_EQ(viewer->cellReachPointsShown(), static_cast<int>(map.map.points.size()));
  EXPECT_TRUE(viewer->cellReachColourBarShown());
  EXPECT_TRUE(panel->reachStatusText().contains(QStringLiteral("%1 nozzle positions").arg(map.map.points.size())))
      << panel->reachStatusText().toStdString();

  const QImage image = frameOf(viewer);
  const std::optional<QPointF> best = viewer->widgetPositionOf(map.map.best.nozzleTipMm);
  ASSERT_TRUE(best.has_value());
  const QPoint pixel = best->toPoint();
  ASSERT_TRUE(image.rect().contains(pixel));
  const QColor expected = reachColorOf(map.map.best.score);
  EXPECT_TRUE(near(image.pixelColor(pixel), expected, 8))
      << "at " << pixel.x() << ", " << pixel.y() << ": " << image.pixelColor(pixel).name().toStdString() << " not "
      << expected.name().toStdString();
  // The ball is drawn around it in the same colour, ringed in white.
  const Census ball = census(image.copy(QRect(pixel - QPoint(30, 30), QSize(61, 61))), expected, 8);
  EXPECT_GT(ball.count, 30);
  EXPECT_GT(census(image.copy(QRect(pixel - QPoint(30, 30), QSize(61, 61))), Qt::white, 8).count, 10);
}

TEST(StudioRobotCell, ReachMapToggleHidesAndShowsTheMap) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(findReachMap(window));
  const CellReachMap& map = *window.cellPanel()->reachMap();
  CellViewPanel* panel = window.cellViewPanel();
  MeshViewerWidget* viewer = window.viewer();
  auto* toggle = child<QCheckBox>(*panel, "cellViewReachMap");
  ASSERT_TRUE(toggle->isChecked());
  const QColor bestColour = reachColorOf(map.map.best.score);
  // Around the best position on screen (the corner's axes marker draws pure blue too).
  const auto aroundBest = [&] {
    const QPoint pixel = viewer->widgetPositionOf(map.map.best.nozzleTipMm).value_or(QPointF(-1000, -1000)).toPoint();
    return census(frameOf(viewer).copy(QRect(pixel - QPoint(30, 30), QSize(61, 61))), bestColour, 8).count;
  };
  ASSERT_GT(aroundBest(), 30);

  toggle->setChecked(false);
  EXPECT_FALSE(panel->isReachMapShown());
  EXPECT_EQ(viewer->cellReachPointsShown(), 0);
  EXPECT_FALSE(viewer->cellReachColourBarShown());
  EXPECT_EQ(aroundBest(), 0);
  EXPECT_NE(window.cellPanel()->reachMap(), nullptr);  // hidden, not dropped

  toggle->setChecked(true);
  EXPECT_EQ(viewer->cellReachPointsShown(), static_cast<int>(map.map.points.size()));
  EXPECT_GT(aroundBest(), 30);
}

TEST(StudioRobotCell, ChangedCellHidesTheStaleReachMapAndSaysWhy) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(findReachMap(window));
  MeshViewerWidget* viewer = window.viewer();
  // The nozzle axis tilted: every platform pose the map scored changes.
  child<QDoubleSpinBox>(*window.cellPanel(), "cellNozzleAxisX")->setValue(0.3);
  EXPECT_EQ(window.cellPanel()->reachMap(), nullptr);
  EXPECT_FALSE(window.cellPanel()->bestPosition().has_value());
  EXPECT_FALSE(child<QPushButton>(*window.cellPanel(), "cellUseReach")->isVisibleTo(window.cellPanel()));
  CellViewPanel* panel = window.cellViewPanel();
  EXPECT_FALSE(panel->isReachMapShown());
  EXPECT_FALSE(child<QCheckBox>(*panel, "cellViewReachMap")->isEnabled());
  EXPECT_TRUE(panel->reachStatusText().contains(QStringLiteral("The cell changed"))) << panel->reachStatusText().toStdString();
  EXPECT_EQ(viewer->cellReachPointsShown(), 0);
  EXPECT_FALSE(viewer->hasCellMotion());  // the cell alone was drawn for the map: back to the plan
}

TEST(StudioRobotCell, ChangedPlanHidesTheStaleReachMapAndSaysWhy) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(findReachMap(window));
  window.document()->clearPlan();
  EXPECT_EQ(window.cellPanel()->reachMap(), nullptr);
  EXPECT_EQ(window.viewer()->cellReachPointsShown(), 0);
  EXPECT_TRUE(window.cellViewPanel()->reachStatusText().contains(QStringLiteral("The plan changed")))
      << window.cellViewPanel()->reachStatusText().toStdString();
}

// The map scores positions of the nozzle tip, whatever the tip is now: moving the tip there ("Use this position")
// leaves it true, and the view draws the nozzle at the ringed best position.
TEST(StudioRobotCell, UsingTheBestPositionKeepsTheReachMapWithTheNozzleOnTheBest) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(findReachMap(window));
  const std::shared_ptr<const CellReachMap> map = window.cellPanel()->reachMap();
  child<QPushButton>(*window.cellPanel(), "cellUseReach")->click();
  EXPECT_EQ(window.cellPanel()->reachMap(), map);
  EXPECT_TRUE(window.cellViewPanel()->isReachMapShown());
  EXPECT_EQ(window.viewer()->cellReachPointsShown(), static_cast<int>(map->map.points.size()));
  EXPECT_LT((window.document()->cell()->nozzleTipMm - map->map.best.nozzleTipMm).norm(), 1e-9);
}

TEST(StudioRobotCell, UnreachableStepIsDrawnWithARedMarkerAndItsLine) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  QTemporaryDir dir;
  ASSERT_NO_FATAL_FAILURE(sliceHalfKittenOnTheCell(window, dir));
  // The nozzle beyond the UR5's reach: every step is refused at its first move.
  child<QDoubleSpinBox>(*window.cellPanel(), "cellNozzleY")->setValue(-950.0);
  CellViewPanel* panel = window.cellViewPanel();
  ASSERT_TRUE(panel->showOnCell());
  ASSERT_TRUE(test::waitUntil([&] { return !panel->isConverting(); }, kLongTimeoutMs));
  ASSERT_NE(panel->motion(), nullptr) << panel->statusText().toStdString();
  const robot::StepMotion& first = panel->motion()->steps.front();
  ASSERT_TRUE(first.warning.has_value());
  MeshViewerWidget* viewer = window.viewer();
  EXPECT_TRUE(viewer->cellWarningMarkerShown());
  EXPECT_TRUE(viewer->cellWarningShown().startsWith(QStringLiteral("step 1, line %1").arg(first.warning->line)))
      << viewer->cellWarningShown().toStdString();
  const QImage image = frameOf(viewer);
  EXPECT_GT(census(image, MeshViewerWidget::cellWarningColor(), 30).count, 20);
  EXPECT_TRUE(panel->warningsText().contains(QStringLiteral("step 1, line")));
}

// The Hardware dock's robot cell section converts the studio's sliced job for the Machine tab's cell (as
// `multidir robot-program` does, off the GUI thread) and runs it on the simulated cell (the UR simulator with
// that cell, 1000 times real time) to its end.
TEST(StudioRobotCell, HardwareDockConvertsTheSlicedJobAndRunsItOnTheSimulatedCell) {
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(showCellMachine(window));
  QTemporaryDir dir;
  ASSERT_NO_FATAL_FAILURE(sliceHalfKittenOnTheCell(window, dir));
  // The platform no larger than the plan's platform region (docs/robot-cell.md, "The platform").
  const std::filesystem::path sliced =
      std::filesystem::path(window.document()->slicedJob()->steps.front().path).parent_path();
  QFile printJob(QString::fromStdString((sliced / "print-job.json").string()));
  ASSERT_TRUE(printJob.open(QIODevice::ReadOnly));
  const QRegularExpressionMatch radius =
      QRegularExpression(QStringLiteral("\"pivot\"[^}]*\"platformRadiusMm\": *([0-9.eE+-]+)"))
          .match(QString::fromUtf8(printJob.readAll()));
  ASSERT_TRUE(radius.hasMatch());
  robot::Cell cell = *window.document()->cell();
  cell.platformRadiusMm = radius.captured(1).toDouble();
  window.document()->setCell(cell);

  RobotCellSection* section = window.hardwarePanel()->robotCellSection();
  ASSERT_TRUE(section->convertSlicedJob()) << section->messageText().toStdString();
  ASSERT_TRUE(test::waitUntil([&] { return !section->isConverting(); }, kLongTimeoutMs));
  ASSERT_FALSE(section->messageIsError()) << section->messageText().toStdString();
  ASSERT_TRUE(QFile::exists(section->jobFolder() + QStringLiteral("/robot-job.json")));

  const std::string cellFile = dir.filePath(QStringLiteral("cell.json")).toStdString();
  ASSERT_TRUE(robot::writeCell(cell, cellFile).ok());
  hardware::UrSimulatorOptions options;
  options.speed = 1000.0;
  options.cellPath = cellFile;
  std::unique_ptr<hardware::UrSimulator> simulator = test::startUrSimulatorOnFreePorts(options, 45000);
  ASSERT_TRUE(simulator);
  section->setAddress(QStringLiteral("127.0.0.1:%1").arg(simulator->dashboardPort()));
  section->connectRobot();
  ASSERT_TRUE(test::waitUntil([&] { return section->isConnected(); }, 10000)) << section->messageText().toStdString();
  section->startRun();
  ASSERT_TRUE(section->isRunUnderWay()) << section->messageText().toStdString();
  ASSERT_TRUE(test::waitUntil([&] { return !section->isRunUnderWay(); }, kLongTimeoutMs));
  const int steps = static_cast<int>(window.document()->plan()->plan->regions.size());
  EXPECT_EQ(section->messageText().toStdString(),
            QStringLiteral("The robot job is done: %1 steps printed.").arg(steps).toStdString());
  // Every program of the job ran to its end: one per step, or a step's parts (docs/robot-cell.md, "Programs the
  // controller accepts").
  const QStringList programs = QDir(section->jobFolder()).entryList({QStringLiteral("step-*.script")}, QDir::Files);
  EXPECT_GE(programs.size(), steps);
  EXPECT_EQ(simulator->state().programsFinished, static_cast<std::size_t>(programs.size()));
}

}  // namespace
}  // namespace multidir::ui
