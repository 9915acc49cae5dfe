#include "ui/viewer/mesh_viewer_widget.h"

#include <QKeyEvent>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCylinderSource.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOpenGLState.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>

#include "multidir/core/common/units.h"
#include "ui/viewer/cell_colors.h"
#include "ui/viewer/cell_scene.h"
#include "ui/viewer/reach_scene.h"
#include "ui/viewer/gcode_scene.h"
#include "ui/viewer/measure_scene.h"
#include "ui/viewer/mesh_to_polydata.h"
#include "ui/viewer/plan_scene.h"
#include "ui/viewer/solids_scene.h"
#include "ui/viewer/platform_geometry.h"
#include "ui/viewer/support_scene.h"

namespace multidir::ui {
namespace {

// Light grey-blue model on a dark, nearly neutral gradient; the platform is a neutral grey. The model's
// hue differs from both, so a picture can be told apart by colour (the viewer tests do).
constexpr double kModelRgb[3] = {0.66, 0.75, 0.92};
constexpr double kPlatformRgb[3] = {0.60, 0.60, 0.61};
// Overhanging faces: an orange-red that stands out against the grey-blue model and the grey platform.
constexpr unsigned char kRiskyRgb[3] = {236, 84, 40};
constexpr double kAxisRgb[3] = {1.0, 0.80, 0.10};
constexpr double kPickMarkerRgb[3] = {0.95, 0.25, 0.85};
// G-code travel moves: a light azure, far in hue from every region colour, the support colour, the model's
// grey-blue and the greys of the platform and background.
constexpr unsigned char kTravelRgb[3] = {0, 150, 255};
// A pick marker's radius as a fraction of the platform's.
constexpr double kPickMarkerFraction = 0.025;
// A measured point's marker radius as a fraction of the model's bounding diagonal.
constexpr double kMeasureMarkerFraction = 0.008;
// The cell picker's tolerance (a fraction of the window's diagonal): a click on a face's edge still picks.
constexpr double kCellPickTolerance = 0.0005;
// A press and release this close (logical pixels) are a click, which picks; farther apart they are a drag.
constexpr double kClickSlopPixels = 4.0;
constexpr double kGridRgb[3] = {0.38, 0.38, 0.40};
constexpr double kBackgroundTopRgb[3] = {0.12, 0.12, 0.14};
constexpr double kBackgroundBottomRgb[3] = {0.40, 0.40, 0.42};

// The platform's thickness and its gap below the model, as fractions of its radius: the gap keeps the
// faces the model stands on from fighting with the platform's top in the depth buffer.
constexpr double kPlatformThickness = 0.015;
constexpr double kPlatformGap = 0.006;

QColor toQColor(const double rgb[3]) { return QColor::fromRgbF(float(rgb[0]), float(rgb[1]), float(rgb[2])); }

core::Vec3 unitOrZ(const core::Vec3& v) {
  const double length = v.norm();
  if (!std::isfinite(length) || length == 0.0) return core::Vec3::UnitZ();
  return v / length;
}

// A transform taking VTK's Y-axis sources (cylinder, and the grid built in the XZ plane) to the platform:
// +Y becomes the disc's normal, the origin goes `below` mm under the disc's centre.
vtkSmartPointer<vtkTransform> platformFrame(const PlatformDisc& disc, double below) {
  const core::Vec3 origin = disc.center - below * disc.normal;
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->Translate(origin.x(), origin.y(), origin.z());
  const core::Vec3 axis = core::Vec3::UnitY().cross(disc.normal);
  const double angle = std::atan2(axis.norm(), core::Vec3::UnitY().dot(disc.normal));
  if (axis.norm() > 1e-12) {
    transform->RotateWXYZ(core::radToDeg(angle), axis.x(), axis.y(), axis.z());
  } else if (angle > 1.0) {  // the normal is -Y
    transform->RotateX(180.0);
  }
  return transform;
}

// The thin cylinder of the platform, its top a small gap below the model's lowest point.
vtkSmartPointer<vtkTransform> platformPlacement(const PlatformDisc& disc) {
  const double thickness = kPlatformThickness * disc.radiusMm;
  auto transform = platformFrame(disc, kPlatformGap * disc.radiusMm + 0.5 * thickness);
  transform->Scale(disc.radiusMm, thickness, disc.radiusMm);
  return transform;
}

// 1, 2 or 5 times a power of ten, near `rough`: grid spacings a person reads as round millimetres.
double roundStep(double rough) {
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * decade >= rough) return factor * decade;
  }
  return 10.0 * decade;
}

// Grid lines across the platform's top (in its XZ plane, clipped to the disc), about ten each way, so the
// model's size can be judged at a glance.
vtkSmartPointer<vtkPolyData> platformGrid(double radius) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  const double step = roundStep(radius / 5.0);
  const int count = static_cast<int>(std::floor(radius / step));
  for (int i = -count; i <= count; ++i) {
    const double across = i * step;
    const double half = std::sqrt(std::max(0.0, radius * radius - across * across));
    if (half <= 0.0) continue;
    const vtkIdType a = points->InsertNextPoint(across, 0.0, -half);
    const vtkIdType b = points->InsertNextPoint(across, 0.0, half);
    const vtkIdType c = points->InsertNextPoint(-half, 0.0, across);
    const vtkIdType d = points->InsertNextPoint(half, 0.0, across);
    const vtkIdType first[2] = {a, b};
    const vtkIdType second[2] = {c, d};
    lines->InsertNextCell(2, first);
    lines->InsertNextCell(2, second);
  }
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  grid->SetPoints(points);
  grid->SetLines(lines);
  return grid;
}

}  // namespace

struct MeshViewerWidget::Impl {
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkGenericRenderWindowInteractor> interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderer> overlay;  // layer 1: the plan's arrows, over the parts, with the same camera
  // The cell view's pair, in the window instead of the two above while it is shown.
  vtkNew<vtkRenderer> cellRenderer;
  vtkNew<vtkRenderer> cellOverlay;
  std::unique_ptr<CellScene> cell;
  std::unique_ptr<ReachScene> reach;
  bool cellShown = false;

  vtkNew<vtkPolyDataMapper> modelMapper;
  vtkNew<vtkActor> modelActor;
  vtkNew<vtkCylinderSource> platformSource;
  vtkNew<vtkPolyDataMapper> platformMapper;
  vtkNew<vtkActor> platformActor;
  vtkNew<vtkPolyDataMapper> gridMapper;
  vtkNew<vtkActor> gridActor;
  vtkNew<vtkArrowSource> axisSource;
  vtkNew<vtkPolyDataMapper> axisMapper;
  vtkNew<vtkActor> axisActor;

  // The model's per-face colours (cell data of modelData): recolouring rewrites only this array.
  vtkSmartPointer<vtkPolyData> modelData;
  vtkSmartPointer<vtkUnsignedCharArray> faceColors;
  std::size_t riskyShown = 0;
  PlatformDisc platform;
  double modelSizeMm = 0.0;
  std::optional<core::Vec3> rotationAxis;
  std::unique_ptr<PlanScene> plan;
  std::unique_ptr<SupportScene> supports;
  std::unique_ptr<GcodeScene> gcode;
  std::unique_ptr<MeasureScene> measure;
  std::unique_ptr<SolidsScene> solids;
  bool measuring = false;
  Measurement measurement;
  std::vector<core::Vec3> measuredWorld;  // the measurement's points where they are drawn
  QLabel* emptyHint = nullptr;            // owned by the widget
  StandardView pendingView = StandardView::Home;
  bool picking = false;
  std::optional<QPointF> clickPress;  // where the left button went down, until it moved away: a click
  std::vector<vtkSmartPointer<vtkActor>> pickMarkers;
  bool turnWithMachine = false;
  core::Vec3 viewUp = core::Vec3::UnitZ();

  vtkNew<vtkAxesActor> axes;
  vtkNew<vtkOrientationMarkerWidget> axesMarker;  // declared last: it must go before the interactor

  core::Vec3 up = core::Vec3::UnitZ();
  bool hasMesh = false;
  bool fitPending = true;
  bool glReady = false;
  std::size_t frames = 0;
  QMetaObject::Connection contextConnection;

  Impl() {
    plan = std::make_unique<PlanScene>(renderer, overlay);
    supports = std::make_unique<SupportScene>(renderer);
    gcode = std::make_unique<GcodeScene>(renderer);
    measure = std::make_unique<MeasureScene>(overlay);
    solids = std::make_unique<SolidsScene>(renderer, overlay);
    cell = std::make_unique<CellScene>(cellRenderer, cellOverlay);
    reach = std::make_unique<ReachScene>(cellRenderer, cellOverlay);
    cellRenderer->GradientBackgroundOn();
    cellRenderer->SetBackground(kBackgroundBottomRgb[0], kBackgroundBottomRgb[1], kBackgroundBottomRgb[2]);
    cellRenderer->SetBackground2(kBackgroundTopRgb[0], kBackgroundTopRgb[1], kBackgroundTopRgb[2]);
    cellOverlay->SetLayer(1);
    cellOverlay->InteractiveOff();
    cellOverlay->SetActiveCamera(cellRenderer->GetActiveCamera());
    renderer->GradientBackgroundOn();
    renderer->SetBackground(kBackgroundBottomRgb[0], kBackgroundBottomRgb[1], kBackgroundBottomRgb[2]);
    renderer->SetBackground2(kBackgroundTopRgb[0], kBackgroundTopRgb[1], kBackgroundTopRgb[2]);
    window->SetNumberOfLayers(2);
    window->AddRenderer(renderer);
    overlay->SetLayer(1);
    overlay->InteractiveOff();
    overlay->SetActiveCamera(renderer->GetActiveCamera());
    window->AddRenderer(overlay);
    // Qt owns the context; VTK draws into its own framebuffer and blits to the one Qt has bound.
    window->SetOwnContext(false);
    window->SetFrameBlitModeToBlitToCurrent();
    window->SetMultiSamples(4);  // smooth silhouettes; resolved when VTK blits into Qt's framebuffer

    interactor->SetRenderWindow(window);
    interactor->SetInteractorStyle(style);
    // Renders happen only in paintGL; the widget asks Qt for a repaint after each forwarded event.
    interactor->EnableRenderOff();

    modelActor->SetMapper(modelMapper);
    vtkProperty* model = modelActor->GetProperty();
    model->SetColor(kModelRgb[0], kModelRgb[1], kModelRgb[2]);
    model->SetInterpolationToFlat();
    model->EdgeVisibilityOff();
    model->SetAmbient(0.12);
    model->SetDiffuse(0.88);
    model->SetSpecular(0.0);
    modelMapper->SetScalarModeToUseCellData();
    modelMapper->SetColorModeToDirectScalars();
    modelMapper->ScalarVisibilityOn();

    platformSource->SetResolution(128);
    platformSource->SetRadius(1.0);
    platformSource->SetHeight(1.0);
    platformSource->CappingOn();
    platformMapper->SetInputConnection(platformSource->GetOutputPort());
    platformActor->SetMapper(platformMapper);
    vtkProperty* platform = platformActor->GetProperty();
    platform->SetColor(kPlatformRgb[0], kPlatformRgb[1], kPlatformRgb[2]);
    // Mostly ambient: seen at a grazing angle under the headlight it would otherwise look like a shadow.
    platform->SetAmbient(0.6);
    platform->SetDiffuse(0.4);
    platformActor->PickableOff();  // measuring picks the model's faces only
    gridActor->SetMapper(gridMapper);
    gridActor->GetProperty()->SetColor(kGridRgb[0], kGridRgb[1], kGridRgb[2]);
    gridActor->GetProperty()->LightingOff();
    gridActor->PickableOff();

    // A double-headed look comes from the shaft running through the platform's centre: the arrow spans
    // the platform from one rim to the other along the axis.
    axisSource->SetTipResolution(24);
    axisSource->SetShaftResolution(16);
    axisSource->SetShaftRadius(0.012);
    axisSource->SetTipRadius(0.035);
    axisSource->SetTipLength(0.08);
    axisMapper->SetInputConnection(axisSource->GetOutputPort());
    axisActor->SetMapper(axisMapper);
    axisActor->GetProperty()->SetColor(kAxisRgb[0], kAxisRgb[1], kAxisRgb[2]);
    axisActor->GetProperty()->SetAmbient(0.5);
    axisActor->GetProperty()->SetDiffuse(0.5);
    axisActor->PickableOff();

    modelActor->VisibilityOff();
    platformActor->VisibilityOff();
    gridActor->VisibilityOff();
    axisActor->VisibilityOff();
    renderer->AddActor(modelActor);
    renderer->AddActor(platformActor);
    renderer->AddActor(gridActor);
    renderer->AddActor(axisActor);

    axesMarker->SetOrientationMarker(axes);
    axesMarker->SetViewport(0.0, 0.0, 0.18, 0.18);
    axesMarker->SetZoom(1.7);  // the axes actor's bounds are symmetric about its origin: fill the corner
  }

  // The renderer drawn now (the cell view's or the model's) and its overlay.
  [[nodiscard]] vtkRenderer* shownRenderer() const { return cellShown ? cellRenderer.Get() : renderer.Get(); }
  [[nodiscard]] vtkRenderer* shownOverlay() const { return cellShown ? cellOverlay.Get() : overlay.Get(); }

  // The cell view's renderers in the window instead of the model's, or back.
  void showCell(bool on) {
    if (on == cellShown) return;
    vtkRenderer* off[2] = {shownRenderer(), shownOverlay()};
    cellShown = on;
    window->RemoveRenderer(off[0]);
    window->RemoveRenderer(off[1]);
    window->AddRenderer(shownRenderer());
    window->AddRenderer(shownOverlay());
  }

  // The cell view's camera: from the front right and above, z up, framing `box` (base frame, mm); `armMm` sets
  // how far away the eye starts (the framing then zooms to the box).
  void frameCell(const Eigen::AlignedBox3d& box, double armMm) {
    const Eigen::Vector3d centre = box.center();
    const Eigen::Vector3d eye = centre + Eigen::Vector3d(1.0, -1.6, 0.9).normalized() * 4.0 * armMm;
    vtkCamera* camera = cellRenderer->GetActiveCamera();
    camera->SetFocalPoint(centre.x(), centre.y(), centre.z());
    camera->SetPosition(eye.x(), eye.y(), eye.z());
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetParallelProjection(renderer->GetActiveCamera()->GetParallelProjection());
    const double bounds[6] = {box.min().x(), box.max().x(), box.min().y(), box.max().y(), box.min().z(), box.max().z()};
    cellRenderer->ResetCamera(bounds);
    camera->Zoom(1.2);
  }

  void endCellView() {
    reach->setMap(nullptr, {});
    cell->setMotion(nullptr);
    showCell(false);
  }

  // Back from the G-code preview: the plan's actors show again as they were set.
  void endGcodePreview() {
    gcode->clear();
    plan->setHidden(false);
    supports->setHidden(false);
  }

  // The model colour for every face; setRiskyFaces then paints the risky ones.
  void resetFaceColors() {
    const unsigned char base[3] = {static_cast<unsigned char>(std::lround(255 * kModelRgb[0])),
                                   static_cast<unsigned char>(std::lround(255 * kModelRgb[1])),
                                   static_cast<unsigned char>(std::lround(255 * kModelRgb[2]))};
    for (vtkIdType i = 0; i < faceColors->GetNumberOfTuples(); ++i) faceColors->SetTypedTuple(i, base);
    faceColors->Modified();
    riskyShown = 0;
  }

  void placeRotationAxis() {
    if (!rotationAxis || !hasMesh || plan->hasPlan()) {
      axisActor->VisibilityOff();
      return;
    }
    // In the platform plane (the part of the axis along up is dropped), just above the grid.
    core::Vec3 axis = *rotationAxis - rotationAxis->dot(platform.normal) * platform.normal;
    if (!(axis.norm() > 1e-9)) {
      axisActor->VisibilityOff();
      return;
    }
    axis.normalize();
    const double length = 2.0 * platform.radiusMm;
    const core::Vec3 start = platform.center - platform.radiusMm * axis - 0.2 * kPlatformGap * platform.radiusMm * platform.normal;
    auto transform = vtkSmartPointer<vtkTransform>::New();
    transform->Translate(start.x(), start.y(), start.z());
    const core::Vec3 turn = core::Vec3::UnitX().cross(axis);
    const double angle = std::atan2(turn.norm(), core::Vec3::UnitX().dot(axis));
    if (turn.norm() > 1e-12) {
      transform->RotateWXYZ(core::radToDeg(angle), turn.x(), turn.y(), turn.z());
    } else if (angle > 1.0) {
      transform->RotateZ(180.0);
    }
    transform->Scale(length, length, length);
    axisActor->SetUserTransform(transform);
    axisActor->VisibilityOn();
  }

  void applyFit() {
    vtkCamera* camera = renderer->GetActiveCamera();
    const StandardView view = pendingView;
    pendingView = StandardView::Home;
    core::Vec3 modelUp = up;
    if (hasMesh && turnWithMachine && plan->hasPlan()) {
      modelUp = unitOrZ(plan->plan()->regions[static_cast<std::size_t>(plan->shownRegions() - 1)].printingDirection);
    }
    const ViewOrientation orientation = orientationOf(view, modelUp);
    const core::Vec3& direction = orientation.fromCentre;
    viewUp = orientation.screenUp;
    if (!hasMesh) {
      // Nothing to frame, but the axes marker turns with the camera: it shows the empty session's up, up.
      camera->SetFocalPoint(0.0, 0.0, 0.0);
      camera->SetPosition(direction.x(), direction.y(), direction.z());
      camera->SetViewUp(viewUp.x(), viewUp.y(), viewUp.z());
      camera->OrthogonalizeViewUp();
      return;
    }
    double bounds[6];
    if (plan->hasPlan()) {
      renderer->ComputeVisiblePropBounds(bounds);
    } else {
      modelActor->GetBounds(bounds);
    }
    const core::Vec3 centre(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                            0.5 * (bounds[4] + bounds[5]));
    const core::Vec3 eye = centre + direction;
    camera->SetFocalPoint(centre.x(), centre.y(), centre.z());
    camera->SetPosition(eye.x(), eye.y(), eye.z());
    camera->SetViewUp(viewUp.x(), viewUp.y(), viewUp.z());
    renderer->ResetCamera();  // keeps the direction, frames every visible actor (model and platform)
    camera->Zoom(1.25);
    renderer->ResetCameraClippingRange();
  }
};

MeshViewerWidget::MeshViewerWidget(QWidget* parent) : QOpenGLWidget(parent), m_impl(std::make_unique<Impl>()) {
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(200, 150);
  // A Qt label over the view (not drawn by VTK, so it never appears in an exported screenshot).
  m_impl->emptyHint = new QLabel(
      tr("Open a model (%1) or File > Samples").arg(QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText)),
      this);
  m_impl->emptyHint->setObjectName(QStringLiteral("emptyViewHint"));
  m_impl->emptyHint->setAlignment(Qt::AlignCenter);
  m_impl->emptyHint->setWordWrap(true);
  m_impl->emptyHint->setAttribute(Qt::WA_TransparentForMouseEvents);
  m_impl->emptyHint->setStyleSheet(QStringLiteral("color: #e6e6e6; background: transparent; font-size: 15pt;"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_impl->emptyHint, 0, Qt::AlignCenter);
}

MeshViewerWidget::~MeshViewerWidget() {
  if (m_impl->contextConnection) disconnect(m_impl->contextConnection);
  if (m_impl->glReady && context()) {
    makeCurrent();
    releaseGraphics();
    doneCurrent();
  }
  if (m_impl->axesMarker->GetEnabled()) m_impl->axesMarker->SetEnabled(0);
}

QSize MeshViewerWidget::sizeHint() const { return {900, 700}; }

void MeshViewerWidget::setMesh(const core::TriangleMesh& mesh, const core::Vec3& up) {
  Impl& m = *m_impl;
  endPickingOnNewScene();
  m.up = unitOrZ(up);
  m.endCellView();
  m.endGcodePreview();
  m.plan->clear();
  m.supports->clear();
  m.solids->clear();
  m.modelData = toPolyData(mesh);
  m.faceColors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  m.faceColors->SetName("faceColors");
  m.faceColors->SetNumberOfComponents(3);
  m.faceColors->SetNumberOfTuples(m.modelData->GetNumberOfCells());
  m.resetFaceColors();
  m.modelData->GetCellData()->SetScalars(m.faceColors);
  m.modelMapper->SetInputData(m.modelData);
  m.modelActor->SetVisibility(!mesh.empty());
  const PlatformDisc disc = platformUnder(mesh, m.up);
  m.platform = disc;
  double bounds[6];
  m.modelData->GetBounds(bounds);
  m.modelSizeMm = mesh.empty() ? 0.0 : std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
  m.platformActor->SetUserTransform(platformPlacement(disc));
  m.platformActor->SetVisibility(!mesh.empty());
  // Halfway between the platform's top and the model, so neither hides the lines.
  m.gridMapper->SetInputData(platformGrid(disc.radiusMm));
  m.gridActor->SetUserTransform(platformFrame(disc, 0.5 * kPlatformGap * disc.radiusMm));
  m.gridActor->SetVisibility(!mesh.empty());
  m.hasMesh = !mesh.empty();
  m.emptyHint->setVisible(!m.hasMesh);
  m.placeRotationAxis();
  fitView();
}

void MeshViewerWidget::clear() {
  Impl& m = *m_impl;
  endPickingOnNewScene();
  m.endCellView();
  m.endGcodePreview();
  m.plan->clear();
  m.supports->clear();
  m.solids->clear();
  m.modelData = vtkSmartPointer<vtkPolyData>::New();
  m.faceColors = nullptr;
  m.riskyShown = 0;
  m.modelMapper->SetInputData(m.modelData);
  m.modelActor->VisibilityOff();
  m.axisActor->VisibilityOff();
  m.platformActor->VisibilityOff();
  m.gridActor->VisibilityOff();
  m.hasMesh = false;
  m.emptyHint->setVisible(true);
  update();
}

void MeshViewerWidget::setSolids(const std::vector<ColouredSolid>& solids, const core::Vec3& up) {
  clear();
  Impl& m = *m_impl;
  m.up = unitOrZ(up);
  m.solids->setSolids(solids);
  m.hasMesh = !solids.empty();
  m.emptyHint->setVisible(!m.hasMesh);
  fitView();
}

int MeshViewerWidget::solidCount() const { return m_impl->solids->count(); }

void MeshViewerWidget::fitView() { setStandardView(StandardView::Home); }

void MeshViewerWidget::setStandardView(StandardView view) {
  // The camera's framing depends on the viewport's aspect ratio, known for sure only when painting.
  m_impl->pendingView = view;
  m_impl->fitPending = true;
  update();
}

void MeshViewerWidget::setOrthographic(bool orthographic) {
  vtkCamera* camera = m_impl->renderer->GetActiveCamera();
  if ((camera->GetParallelProjection() != 0) == orthographic) return;
  if (orthographic) {
    // The parallel view as wide at the focal point as the perspective one was: the model keeps its size.
    camera->SetParallelScale(camera->GetDistance() * std::tan(core::degToRad(0.5 * camera->GetViewAngle())));
  }
  camera->SetParallelProjection(orthographic ? 1 : 0);
  update();
}

bool MeshViewerWidget::isOrthographic() const {
  return m_impl->renderer->GetActiveCamera()->GetParallelProjection() != 0;
}

core::Vec3 MeshViewerWidget::cameraDirection() const {
  double direction[3];
  m_impl->renderer->GetActiveCamera()->GetDirectionOfProjection(direction);
  return core::Vec3(direction[0], direction[1], direction[2]).normalized();
}

core::Vec3 MeshViewerWidget::cameraUp() const {
  double up[3];
  m_impl->renderer->GetActiveCamera()->GetViewUp(up);
  return core::Vec3(up[0], up[1], up[2]).normalized();
}

void MeshViewerWidget::setEmptyUp(const core::Vec3& up) {
  if (m_impl->hasMesh) return;
  m_impl->up = unitOrZ(up);
  fitView();
}

bool MeshViewerWidget::isEmptyHintShown() const { return !m_impl->emptyHint->isHidden(); }

QString MeshViewerWidget::emptyHintText() const { return m_impl->emptyHint->text(); }

void MeshViewerWidget::setMeasuring(bool on) {
  Impl& m = *m_impl;
  if (m.measuring == on) return;
  if (on && m.picking) {
    setPlatformPicking(false);
    emit platformPickCancelled();
  }
  m.measuring = on;
  m.clickPress.reset();
  m.measurement = {};
  m.measuredWorld.clear();
  if (on) {
    setCursor(Qt::CrossCursor);
  } else {
    unsetCursor();
  }
  showMeasurement();
  emit measuringChanged(on);
  emit measurementChanged();
}

bool MeshViewerWidget::isMeasuring() const { return m_impl->measuring; }

const Measurement& MeshViewerWidget::measurement() const { return m_impl->measurement; }

int MeshViewerWidget::measureMarkersShown() const { return m_impl->measure->markersShown(); }

bool MeshViewerWidget::measureLineShown() const { return m_impl->measure->lineShown(); }

namespace {

// A picked surface point: in the model's coordinates, and where it is drawn (the exploded plan view moves a
// region's actor away from the model's coordinates).
struct SurfacePick {
  core::Vec3 model;
  core::Vec3 world;
};

std::optional<SurfacePick> pickSurface(vtkRenderer* renderer, vtkRenderWindow* window, const QWidget* widget,
                                       const QPointF& position) {
  // VTK's display coordinates: device pixels, origin bottom left (as setMouseInformation hands clicks over).
  const qreal ratio = widget->devicePixelRatioF();
  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(kCellPickTolerance);
  if (picker->Pick(position.x() * ratio, window->GetSize()[1] - 1 - position.y() * ratio, 0.0, renderer) == 0)
    return std::nullopt;
  vtkActor* actor = picker->GetActor();
  if (actor == nullptr || picker->GetCellId() < 0) return std::nullopt;
  double world[4] = {0.0, 0.0, 0.0, 1.0};
  picker->GetPickPosition(world);
  vtkNew<vtkMatrix4x4> toModel;
  vtkMatrix4x4::Invert(actor->GetMatrix(), toModel);
  double model[4];
  toModel->MultiplyPoint(world, model);
  return SurfacePick{core::Vec3(model[0], model[1], model[2]) / model[3], core::Vec3(world[0], world[1], world[2])};
}

QString formatMm(double value) { return QLocale().toString(value, 'f', 2); }

}  // namespace

std::optional<core::Vec3> MeshViewerWidget::modelPointAt(const QPointF& position) const {
  if (!m_impl->hasMesh) return std::nullopt;
  const std::optional<SurfacePick> pick = pickSurface(m_impl->renderer, m_impl->window, this, position);
  if (!pick) return std::nullopt;
  return pick->model;
}

void MeshViewerWidget::showMeasurement() {
  Impl& m = *m_impl;
  const auto point = [](const core::Vec3& p) {
    return tr("%1, %2, %3 mm").arg(formatMm(p.x()), formatMm(p.y()), formatMm(p.z()));
  };
  QString corner;
  QString label;
  if (m.measurement.first) corner = tr("A: %1").arg(point(*m.measurement.first));
  if (m.measurement.second) {
    const QString distance = tr("%1 mm").arg(formatMm(*m.measurement.distanceMm()));
    corner += QLatin1Char('\n') + tr("B: %1").arg(point(*m.measurement.second)) + QLatin1Char('\n') +
              tr("Distance: %1").arg(distance);
    label = distance;
  } else if (m.measurement.first) {
    corner += QLatin1Char('\n') + tr("Click a second point on the model (Esc ends measuring)");
  }
  m.measure->show(m.measuredWorld, kMeasureMarkerFraction * (m.modelSizeMm > 0.0 ? m.modelSizeMm : 100.0),
                  corner.toStdString(), label.toStdString());
  update();
}

bool MeshViewerWidget::setRiskyFaces(const std::vector<char>& risky) {
  Impl& m = *m_impl;
  if (!m.faceColors || static_cast<vtkIdType>(risky.size()) != m.faceColors->GetNumberOfTuples()) return false;
  m.resetFaceColors();
  std::size_t count = 0;
  for (std::size_t i = 0; i < risky.size(); ++i) {
    if (!risky[i]) continue;
    m.faceColors->SetTypedTuple(static_cast<vtkIdType>(i), kRiskyRgb);
    ++count;
  }
  m.faceColors->Modified();
  m.riskyShown = count;
  update();
  return true;
}

std::size_t MeshViewerWidget::riskyFacesShown() const { return m_impl->riskyShown; }

void MeshViewerWidget::setRotationAxis(const std::optional<core::Vec3>& axis) {
  m_impl->rotationAxis = axis;
  m_impl->placeRotationAxis();
  update();
}

bool MeshViewerWidget::rotationAxisShown() const { return m_impl->axisActor->GetVisibility() != 0; }

PlatformDisc MeshViewerWidget::platform() const { return m_impl->platform; }

void MeshViewerWidget::setPlatformPicking(bool on) {
  Impl& m = *m_impl;
  if (on) setMeasuring(false);
  m.picking = on;
  m.clickPress.reset();
  if (on) {
    setCursor(Qt::CrossCursor);
  } else {
    unsetCursor();
    setPickMarkers({});
  }
}

bool MeshViewerWidget::isPlatformPicking() const { return m_impl->picking; }

void MeshViewerWidget::endPickingOnNewScene() {
  setMeasuring(false);
  if (!m_impl->picking) return;
  setPlatformPicking(false);
  emit platformPickCancelled();
}

PlatformHit MeshViewerWidget::platformHitAt(const QPointF& position) const {
  const Impl& m = *m_impl;
  if (!m.hasMesh) return {PlatformHitKind::NoPlatform, core::Vec3::Zero()};
  // The ray from the near to the far clipping plane through the pixel, in VTK's display coordinates
  // (device pixels, origin bottom left), as setMouseInformation hands clicks to VTK.
  const qreal ratio = devicePixelRatioF();
  const double x = position.x() * ratio;
  const double y = m.window->GetSize()[1] - 1 - position.y() * ratio;
  double ends[2][4];
  for (int i = 0; i < 2; ++i) {
    m.renderer->SetDisplayPoint(x, y, static_cast<double>(i));
    m.renderer->DisplayToWorld();
    m.renderer->GetWorldPoint(ends[i]);
    if (ends[i][3] == 0.0) return {PlatformHitKind::Parallel, core::Vec3::Zero()};
  }
  const core::Vec3 nearPoint(ends[0][0] / ends[0][3], ends[0][1] / ends[0][3], ends[0][2] / ends[0][3]);
  const core::Vec3 farPoint(ends[1][0] / ends[1][3], ends[1][1] / ends[1][3], ends[1][2] / ends[1][3]);
  return hitPlatform(m.platform, nearPoint, farPoint - nearPoint);
}

std::optional<core::Vec3> MeshViewerWidget::platformPointAt(const QPoint& position) const {
  const PlatformHit hit = platformHitAt(QPointF(position));
  if (hit.kind != PlatformHitKind::Hit) return std::nullopt;
  return hit.point;
}

std::optional<QPointF> MeshViewerWidget::widgetPositionOf(const core::Vec3& point) const {
  const Impl& m = *m_impl;
  vtkRenderer* renderer = m.shownRenderer();
  vtkCamera* camera = renderer->GetActiveCamera();
  double eye[3];
  double forward[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(forward);
  if ((point - core::Vec3(eye[0], eye[1], eye[2])).dot(core::Vec3(forward[0], forward[1], forward[2])) <= 0.0)
    return std::nullopt;
  renderer->SetWorldPoint(point.x(), point.y(), point.z(), 1.0);
  renderer->WorldToDisplay();
  double display[3];
  renderer->GetDisplayPoint(display);
  const qreal ratio = devicePixelRatioF();
  return QPointF(display[0] / ratio, (m.window->GetSize()[1] - 1 - display[1]) / ratio);
}

void MeshViewerWidget::setPickMarkers(const std::vector<core::Vec3>& points) {
  Impl& m = *m_impl;
  for (const vtkSmartPointer<vtkActor>& actor : m.pickMarkers) m.overlay->RemoveActor(actor);
  m.pickMarkers.clear();
  const double radius = kPickMarkerFraction * (m.platform.radiusMm > 0.0 ? m.platform.radiusMm : 50.0);
  for (const core::Vec3& point : points) {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(point.x(), point.y(), point.z());
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(16);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(kPickMarkerRgb[0], kPickMarkerRgb[1], kPickMarkerRgb[2]);
    actor->GetProperty()->SetAmbient(0.4);
    actor->GetProperty()->SetDiffuse(0.6);
    actor->PickableOff();
    // On the overlay layer, so a marker stays visible where the model stands in front of the platform.
    m.overlay->AddActor(actor);
    m.pickMarkers.push_back(actor);
  }
  update();
}

std::size_t MeshViewerWidget::pickMarkersShown() const { return m_impl->pickMarkers.size(); }

void MeshViewerWidget::setPlan(std::shared_ptr<const core::Decomposition> plan, Camera camera) {
  Impl& m = *m_impl;
  if (!plan || plan->regions.empty() || !m.hasMesh) {
    clearPlan();
    return;
  }
  setMeasuring(false);
  m.endCellView();
  m.endGcodePreview();
  m.plan->setPlan(std::move(plan), m.platform.center, m.modelSizeMm);
  m.supports->clear();
  m.modelActor->VisibilityOff();
  m.axisActor->VisibilityOff();
  if (camera == Camera::Keep) {
    update();
  } else {
    fitView();
  }
}

void MeshViewerWidget::clearPlan() {
  Impl& m = *m_impl;
  if (m.cellShown) {
    m.endCellView();
    update();
  }
  if (!m.plan->hasPlan()) return;
  setMeasuring(false);
  m.endGcodePreview();
  m.plan->clear();
  m.supports->clear();
  m.modelActor->SetVisibility(m.hasMesh);
  m.placeRotationAxis();
  fitView();
}

bool MeshViewerWidget::hasPlan() const { return m_impl->plan->hasPlan(); }

bool MeshViewerWidget::setSupports(std::shared_ptr<const std::vector<core::SupportSet>> supports) {
  Impl& m = *m_impl;
  m.supports->clear();
  update();
  if (!supports || supports->empty()) return true;
  if (!m.plan->hasPlan() || supports->size() != m.plan->plan()->regions.size()) return false;
  m.supports->setSupports(std::move(supports));
  placeSupports();
  return true;
}

void MeshViewerWidget::setSupportsVisible(bool visible) {
  m_impl->supports->setVisible(visible);
  update();
}

int MeshViewerWidget::supportSetsShown() const { return m_impl->supports->shownCount(); }

void MeshViewerWidget::placeSupports() {
  Impl& m = *m_impl;
  if (!m.plan->hasPlan() || !m.supports->hasSupports()) return;
  m.supports->place(explodeOffsets(*m.plan->plan(), m.plan->explodeDistance()), m.plan->shownRegions());
}

void MeshViewerWidget::setPrintingDirectionsVisible(bool visible) {
  m_impl->plan->setDirectionsVisible(visible);
  update();
}

void MeshViewerWidget::setClippingPlanesVisible(bool visible) {
  m_impl->plan->setPlanesVisible(visible);
  update();
}

void MeshViewerWidget::setSelectedPlane(int plane) {
  m_impl->plan->setSelectedPlane(plane);
  update();
}

int MeshViewerWidget::selectedPlane() const { return m_impl->plan->selectedPlane(); }

bool MeshViewerWidget::selectedPlaneShown() const { return m_impl->plan->selectedPlaneShown(); }

int MeshViewerWidget::clippingPlaneAt(const QPointF& position) const {
  // VTK's display coordinates: device pixels, origin bottom left (as setMouseInformation hands clicks over).
  const qreal ratio = devicePixelRatioF();
  return m_impl->plan->planeAt(position.x() * ratio, m_impl->window->GetSize()[1] - 1 - position.y() * ratio);
}

void MeshViewerWidget::setExplodeDistance(double distanceMm) {
  // Measured points stay where they were picked: a new explosion starts a new measurement.
  if (m_impl->measuring && m_impl->plan->explodeDistance() != distanceMm) {
    m_impl->measurement = {};
    m_impl->measuredWorld.clear();
    showMeasurement();
    emit measurementChanged();
  }
  m_impl->plan->setExplodeDistance(distanceMm);
  placeSupports();
  update();
}

void MeshViewerWidget::setShownRegions(int count) {
  m_impl->plan->setShownRegions(count);
  placeSupports();
  if (m_impl->turnWithMachine) {
    fitView();
  } else {
    update();
  }
}

int MeshViewerWidget::shownRegions() const { return m_impl->plan->shownRegions(); }

void MeshViewerWidget::setTurnWithMachine(bool turn) {
  if (m_impl->turnWithMachine == turn) return;
  m_impl->turnWithMachine = turn;
  fitView();
}

core::Vec3 MeshViewerWidget::viewUp() const { return m_impl->viewUp; }

bool MeshViewerWidget::hasMesh() const { return m_impl->hasMesh; }
std::size_t MeshViewerWidget::framesRendered() const { return m_impl->frames; }

QColor MeshViewerWidget::modelColor() { return toQColor(kModelRgb); }
QColor MeshViewerWidget::platformColor() { return toQColor(kPlatformRgb); }
QColor MeshViewerWidget::riskyColor() { return QColor(kRiskyRgb[0], kRiskyRgb[1], kRiskyRgb[2]); }
QColor MeshViewerWidget::backgroundTopColor() { return toQColor(kBackgroundTopRgb); }
QColor MeshViewerWidget::backgroundBottomColor() { return toQColor(kBackgroundBottomRgb); }
QColor MeshViewerWidget::gcodeTravelColor() { return QColor(kTravelRgb[0], kTravelRgb[1], kTravelRgb[2]); }

bool MeshViewerWidget::setGcodePreview(std::shared_ptr<const GcodePreview> preview) {
  Impl& m = *m_impl;
  if (!preview) {
    if (!m.gcode->hasPreview()) return true;
    m.endGcodePreview();
    update();
    return true;
  }
  if (!m.plan->hasPlan()) return false;
  m.gcode->setPreview(std::move(preview));
  m.plan->setHidden(true);
  m.supports->setHidden(true);
  update();
  return true;
}

bool MeshViewerWidget::hasGcodePreview() const { return m_impl->gcode->hasPreview(); }

void MeshViewerWidget::setGcodeLayerLimit(int layers) {
  m_impl->gcode->setLayerLimit(layers);
  update();
}

int MeshViewerWidget::gcodeLayerLimit() const { return m_impl->gcode->layerLimit(); }

void MeshViewerWidget::setGcodeTravelVisible(bool visible) {
  m_impl->gcode->setTravelVisible(visible);
  update();
}

int MeshViewerWidget::gcodeExtrusionLinesShown() const { return m_impl->gcode->extrusionLinesShown(); }
int MeshViewerWidget::gcodeUnsupportedLinesShown() const { return m_impl->gcode->unsupportedLinesShown(); }
int MeshViewerWidget::gcodeTravelLinesShown() const { return m_impl->gcode->travelLinesShown(); }

void MeshViewerWidget::setCellMotion(std::shared_ptr<const CellMotion> motion) {
  Impl& m = *m_impl;
  if (!motion) {
    if (!m.cellShown) return;
    m.endCellView();
    update();
    return;
  }
  setMeasuring(false);
  m.cell->setMotion(std::move(motion));
  m.showCell(true);
  // The camera once: from the front right and above, z up, framing the arm's base and the nozzle with a quarter
  // of the arm's reach around them (the part is under the nozzle, the arm between the two).
  const robot::Cell& cell = m.cell->motion()->cell;
  const double reach = std::abs(cell.arm.a[1]) + std::abs(cell.arm.a[2]);
  Eigen::AlignedBox3d box(Eigen::Vector3d::Zero());
  box.extend(cell.nozzleTipMm);
  box.min().array() -= 0.25 * reach;
  box.max().array() += 0.25 * reach;
  m.frameCell(box, reach);
  update();
}

void MeshViewerWidget::setCellReachMap(std::shared_ptr<const CellReachMap> map, const QString& colourBarTitle) {
  Impl& m = *m_impl;
  if (!m.cellShown) map = nullptr;  // drawn with the cell only
  m.reach->setMap(map, colourBarTitle.toStdString());
  if (map) {
    // The whole map in view with the cell: the camera as setCellMotion sets it, framing the sampled positions too.
    const robot::Cell& cell = map->cell;
    const double reach = std::abs(cell.arm.a[1]) + std::abs(cell.arm.a[2]);
    Eigen::AlignedBox3d box(Eigen::Vector3d::Zero());
    box.extend(m.cell->motion()->cell.nozzleTipMm);
    for (const robot::ReachPoint& p : map->map.points) box.extend(p.nozzleTipMm);
    m.frameCell(box, reach);
  }
  update();
}

int MeshViewerWidget::cellReachPointsShown() const { return m_impl->cellShown ? m_impl->reach->pointsShown() : 0; }
bool MeshViewerWidget::cellReachColourBarShown() const { return m_impl->cellShown && m_impl->reach->colourBarShown(); }

bool MeshViewerWidget::hasCellMotion() const { return m_impl->cellShown; }

void MeshViewerWidget::setCellPosition(CellPosition position) {
  m_impl->cell->setPosition(position);
  update();
}

CellPosition MeshViewerWidget::cellPosition() const { return m_impl->cell->position(); }
core::Vec3 MeshViewerWidget::cellToolpathPointDrawn() const { return m_impl->cell->toolpathPointDrawn(); }
core::Vec3 MeshViewerWidget::cellPartCentreDrawn() const { return m_impl->cell->partCentreDrawn(); }
QString MeshViewerWidget::cellWarningShown() const { return QString::fromStdString(m_impl->cell->warningShown()); }
bool MeshViewerWidget::cellWarningMarkerShown() const { return m_impl->cellShown && m_impl->cell->warningMarkerShown(); }

namespace {
QColor colorOf(const double rgb[3]) { return QColor::fromRgbF(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2])); }
}  // namespace

QColor MeshViewerWidget::cellPartColor() { return colorOf(kCellPartRgb); }
QColor MeshViewerWidget::cellNozzleColor() { return colorOf(kCellNozzleRgb); }
QColor MeshViewerWidget::cellToolpathPointColor() { return colorOf(kCellToolpathPointRgb); }
QColor MeshViewerWidget::cellToolpathColor() { return colorOf(kCellToolpathRgb); }
QColor MeshViewerWidget::cellWarningColor() { return colorOf(kCellWarningRgb); }

void MeshViewerWidget::initializeGL() {
  Impl& m = *m_impl;
  // A new context (first show, or the widget moved to another top-level window): VTK's GPU resources
  // belong to the old one and are released before it goes.
  if (m.contextConnection) disconnect(m.contextConnection);
  m.contextConnection = connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
    makeCurrent();
    releaseGraphics();
    doneCurrent();
  });
  m.window->SetIsCurrent(true);
  m.window->OpenGLInitContext();
  m.window->SetIsCurrent(false);
  if (!m.interactor->GetInitialized()) m.interactor->Initialize();
  if (!m.axesMarker->GetEnabled()) {
    m.axesMarker->SetInteractor(m.interactor);
    m.axesMarker->SetEnabled(1);
    m.axesMarker->InteractiveOff();
  }
  m.glReady = true;
}

void MeshViewerWidget::resizeGL(int /*width*/, int /*height*/) {
  // The size VTK renders at is set in paintGL, from the device pixel size at that moment.
}

void MeshViewerWidget::paintGL() {
  Impl& m = *m_impl;
  const qreal ratio = devicePixelRatioF();
  const int w = std::max(1, static_cast<int>(std::lround(width() * ratio)));
  const int h = std::max(1, static_cast<int>(std::lround(height() * ratio)));
  m.window->SetSize(w, h);
  m.interactor->SetSize(w, h);
  if (m.fitPending && !m.cellShown) {
    m.applyFit();
    m.fitPending = false;
  }
  // One camera for both layers: its clipping range must hold the parts and the arrows over them.
  double bounds[6];
  double overlayBounds[6];
  vtkRenderer* shown = m.shownRenderer();
  shown->ComputeVisiblePropBounds(bounds);
  m.shownOverlay()->ComputeVisiblePropBounds(overlayBounds);
  if (overlayBounds[0] <= overlayBounds[1]) {
    for (int i = 0; i < 6; i += 2) {
      bounds[i] = std::min(bounds[i], overlayBounds[i]);
      bounds[i + 1] = std::max(bounds[i + 1], overlayBounds[i + 1]);
    }
  }
  if (bounds[0] <= bounds[1]) {
    shown->ResetCameraClippingRange(bounds);
  } else {
    shown->ResetCameraClippingRange();
  }

  // Qt changed GL state behind VTK's cache since the last frame: re-read it, and restore Qt's after.
  vtkOpenGLState* state = m.window->GetState();
  state->Reset();
  state->Push();
  m.window->SetIsCurrent(true);
  m.window->SetReadyForRendering(true);
  m.window->Render();
  m.window->SetReadyForRendering(false);
  m.window->SetIsCurrent(false);
  state->Pop();

  ++m.frames;
  emit frameRendered();
}

void MeshViewerWidget::releaseGraphics() {
  if (!m_impl->glReady) return;
  m_impl->window->SetIsCurrent(true);
  // The pair of renderers not in the window now drew in this context too.
  if (m_impl->cellShown) {
    m_impl->renderer->ReleaseGraphicsResources(m_impl->window);
    m_impl->overlay->ReleaseGraphicsResources(m_impl->window);
  } else {
    m_impl->cellRenderer->ReleaseGraphicsResources(m_impl->window);
    m_impl->cellOverlay->ReleaseGraphicsResources(m_impl->window);
  }
  m_impl->window->ReleaseGraphicsResources(m_impl->window);
  m_impl->window->SetIsCurrent(false);
  m_impl->glReady = false;
}

namespace {

// Tells the interactor where a mouse event happened, in VTK's device pixels (origin bottom left).
void setMouseInformation(vtkGenericRenderWindowInteractor* interactor, const QWidget* widget,
                         const QPointF& position, Qt::KeyboardModifiers modifiers, int repeat) {
  const qreal ratio = widget->devicePixelRatioF();
  interactor->SetEventInformationFlipY(static_cast<int>(std::lround(position.x() * ratio)),
                                       static_cast<int>(std::lround(position.y() * ratio)),
                                       modifiers.testFlag(Qt::ControlModifier) ? 1 : 0,
                                       modifiers.testFlag(Qt::ShiftModifier) ? 1 : 0, 0, repeat);
  interactor->SetAltKey(modifiers.testFlag(Qt::AltModifier) ? 1 : 0);
}

unsigned long pressEventFor(Qt::MouseButton button) {
  switch (button) {
    case Qt::LeftButton: return vtkCommand::LeftButtonPressEvent;
    case Qt::MiddleButton: return vtkCommand::MiddleButtonPressEvent;
    case Qt::RightButton: return vtkCommand::RightButtonPressEvent;
    default: return vtkCommand::NoEvent;
  }
}

unsigned long releaseEventFor(Qt::MouseButton button) {
  switch (button) {
    case Qt::LeftButton: return vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton: return vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton: return vtkCommand::RightButtonReleaseEvent;
    default: return vtkCommand::NoEvent;
  }
}

}  // namespace

void MeshViewerWidget::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) m_impl->clickPress = event->position();
  const unsigned long id = pressEventFor(event->button());
  if (id == vtkCommand::NoEvent) return QOpenGLWidget::mousePressEvent(event);
  setMouseInformation(m_impl->interactor, this, event->position(), event->modifiers(), 0);
  m_impl->interactor->InvokeEvent(id);
  event->accept();
  update();
}

void MeshViewerWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  // Two quick clicks are two clicks (two picks): the second press arrives as this event.
  if (event->button() == Qt::LeftButton) m_impl->clickPress = event->position();
  const unsigned long id = pressEventFor(event->button());
  if (id == vtkCommand::NoEvent) return QOpenGLWidget::mouseDoubleClickEvent(event);
  setMouseInformation(m_impl->interactor, this, event->position(), event->modifiers(), 1);
  m_impl->interactor->InvokeEvent(id);
  event->accept();
  update();
}

void MeshViewerWidget::mouseReleaseEvent(QMouseEvent* event) {
  const unsigned long id = releaseEventFor(event->button());
  if (id == vtkCommand::NoEvent) return QOpenGLWidget::mouseReleaseEvent(event);
  setMouseInformation(m_impl->interactor, this, event->position(), event->modifiers(), 0);
  m_impl->interactor->InvokeEvent(id);
  event->accept();
  update();
  // A click without movement picks; the view has not turned, so what is picked is what the cursor shows.
  if (event->button() != Qt::LeftButton || !m_impl->clickPress) return;
  m_impl->clickPress.reset();
  if (m_impl->measuring) {
    const std::optional<SurfacePick> pick =
        m_impl->hasMesh ? pickSurface(m_impl->renderer, m_impl->window, this, event->position()) : std::nullopt;
    if (!pick) return;
    Measurement& measurement = m_impl->measurement;
    if (!measurement.first || measurement.second) {
      measurement = {pick->model, std::nullopt};
      m_impl->measuredWorld = {pick->world};
    } else {
      measurement.second = pick->model;
      m_impl->measuredWorld.push_back(pick->world);
    }
    showMeasurement();
    emit measurementChanged();
  } else if (m_impl->picking) {
    const PlatformHit hit = platformHitAt(event->position());
    if (hit.kind == PlatformHitKind::Hit) {
      emit platformPointPicked(hit.point);
    } else {
      emit platformPickMissed(hit.kind);
    }
  } else if (m_impl->plan->planesVisible()) {
    const int plane = clippingPlaneAt(event->position());
    if (plane >= 0) emit clippingPlaneClicked(plane);
  }
}

void MeshViewerWidget::mouseMoveEvent(QMouseEvent* event) {
  if (m_impl->clickPress) {
    const QPointF moved = event->position() - *m_impl->clickPress;
    if (std::abs(moved.x()) + std::abs(moved.y()) > kClickSlopPixels) m_impl->clickPress.reset();  // a drag
  }
  setMouseInformation(m_impl->interactor, this, event->position(), event->modifiers(), 0);
  m_impl->interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
  event->accept();
  update();
}

void MeshViewerWidget::wheelEvent(QWheelEvent* event) {
  const int delta = event->angleDelta().y();
  if (delta == 0) return QOpenGLWidget::wheelEvent(event);
  setMouseInformation(m_impl->interactor, this, event->position(), event->modifiers(), 0);
  m_impl->interactor->InvokeEvent(delta > 0 ? vtkCommand::MouseWheelForwardEvent
                                            : vtkCommand::MouseWheelBackwardEvent);
  event->accept();
  update();
}

void MeshViewerWidget::keyPressEvent(QKeyEvent* event) {
  // R and Home fit the view. VTK's own 'e'/'q' (quit), '3' (stereo) and 'p'/'f' (pick, fly) make no sense
  // here, so only the keys the trackball style uses for views go through: 'w'/'s' wireframe and surface.
  switch (event->key()) {
    case Qt::Key_R:
    case Qt::Key_Home:
      fitView();
      event->accept();
      return;
    case Qt::Key_Escape:
      if (m_impl->measuring) {
        setMeasuring(false);
        event->accept();
        return;
      }
      if (!m_impl->picking) break;
      setPlatformPicking(false);
      event->accept();
      emit platformPickCancelled();
      return;
    case Qt::Key_W:
    case Qt::Key_S: {
      const QByteArray text = event->text().toLower().toLatin1();
      const char code = text.isEmpty() ? '\0' : text.front();
      m_impl->interactor->SetKeyEventInformation(event->modifiers().testFlag(Qt::ControlModifier) ? 1 : 0,
                                                 event->modifiers().testFlag(Qt::ShiftModifier) ? 1 : 0, code,
                                                 event->isAutoRepeat() ? 1 : 0, text.constData());
      m_impl->interactor->InvokeEvent(vtkCommand::KeyPressEvent);
      m_impl->interactor->InvokeEvent(vtkCommand::CharEvent);
      event->accept();
      update();
      return;
    }
    default:
      break;
  }
  QOpenGLWidget::keyPressEvent(event);
}

bool MeshViewerWidget::event(QEvent* event) {
  // While picking or measuring, Esc ends it here rather than triggering the window's Esc shortcut.
  if (event->type() == QEvent::ShortcutOverride && (m_impl->picking || m_impl->measuring) &&
      static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape) {
    event->accept();
    return true;
  }
  return QOpenGLWidget::event(event);
}

void MeshViewerWidget::keyReleaseEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_W || event->key() == Qt::Key_S) {
    m_impl->interactor->InvokeEvent(vtkCommand::KeyReleaseEvent);
    event->accept();
    return;
  }
  QOpenGLWidget::keyReleaseEvent(event);
}

}  // namespace multidir::ui
