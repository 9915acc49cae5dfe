#include "ui/viewer/reach_scene.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace multidir::ui {
namespace {

// Drawing choices, not dimensions: a point a few pixels across, the best ball about 1.5 % of the arm's
// length (a dozen pixels when the view frames the whole workspace), its ring half as wide again.
constexpr float kPointPixels = 6.0f;
constexpr double kBestRadiusPerArm = 0.015;
constexpr double kRingScale = 1.5;

void unlit(vtkActor* actor) {
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->PickableOff();
}

vtkSmartPointer<vtkActor> ball(const Eigen::Vector3d& centre, double radius, const double rgb[3]) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre.x(), centre.y(), centre.z());
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  unlit(actor);
  return actor;
}

}  // namespace

ReachScene::ReachScene(vtkRenderer* renderer, vtkRenderer* overlay) : m_renderer(renderer), m_overlay(overlay) {}

ReachScene::~ReachScene() { clear(); }

void ReachScene::clear() {
  if (m_points) m_renderer->RemoveActor(m_points);
  if (m_bestRing) m_renderer->RemoveActor(m_bestRing);
  if (m_best) m_overlay->RemoveActor(m_best);
  if (m_bar) m_overlay->RemoveActor2D(m_bar);
  m_points = nullptr;
  m_best = nullptr;
  m_bestRing = nullptr;
  m_bar = nullptr;
  m_map = nullptr;
}

void ReachScene::setMap(std::shared_ptr<const CellReachMap> map, const std::string& barTitle) {
  clear();
  m_map = std::move(map);
  if (!m_map) return;
  const robot::ReachMap& reach = m_map->map;

  auto points = vtkSmartPointer<vtkPoints>::New();
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetNumberOfComponents(3);
  for (const robot::ReachPoint& p : reach.points) {
    const vtkIdType id = points->InsertNextPoint(p.nozzleTipMm.data());
    vertices->InsertNextCell(1, &id);
    const auto c = robot::reachColour(p.score);
    const unsigned char rgb[3] = {c[0], c[1], c[2]};
    colours->InsertNextTypedTuple(rgb);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetVerts(vertices);
  data->GetPointData()->SetScalars(colours);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOn();
  mapper->SetColorModeToDirectScalars();
  m_points = vtkSmartPointer<vtkActor>::New();
  m_points->SetMapper(mapper);
  m_points->GetProperty()->SetPointSize(kPointPixels);
  unlit(m_points);
  m_renderer->AddActor(m_points);

  // The best position: a ball in its score's colour on the overlay (never hidden), ringed by a white ball
  // behind it in the scene (the slice's frame around the best square, on the view's dark background).
  const robot::ArmModel& arm = m_map->cell.arm;
  const double radius = kBestRadiusPerArm * (std::abs(arm.a[1]) + std::abs(arm.a[2]));
  const auto c = robot::reachColour(reach.best.score);
  const double bestRgb[3] = {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
  const double white[3] = {1.0, 1.0, 1.0};
  m_best = ball(reach.best.nozzleTipMm, radius, bestRgb);
  m_bestRing = ball(reach.best.nozzleTipMm, kRingScale * radius, white);
  m_overlay->AddActor(m_best);
  m_renderer->AddActor(m_bestRing);

  // The colour bar: the same scale, 0 to 100 % of the plan's poses reachable with margin.
  vtkNew<vtkLookupTable> table;
  constexpr int kColours = 256;
  table->SetNumberOfTableValues(kColours);
  table->SetRange(0.0, 100.0);
  for (int i = 0; i < kColours; ++i) {
    const auto t = robot::reachColour(static_cast<double>(i) / (kColours - 1));
    table->SetTableValue(i, t[0] / 255.0, t[1] / 255.0, t[2] / 255.0, 1.0);
  }
  m_bar = vtkSmartPointer<vtkScalarBarActor>::New();
  m_bar->SetLookupTable(table);
  m_bar->SetTitle(barTitle.c_str());
  m_bar->SetNumberOfLabels(3);
  m_bar->SetLabelFormat("%.0f");
  m_bar->SetPosition(0.88, 0.15);
  m_bar->SetWidth(0.1);
  m_bar->SetHeight(0.7);
  m_bar->SetMaximumWidthInPixels(110);
  for (vtkTextProperty* text : {m_bar->GetTitleTextProperty(), m_bar->GetLabelTextProperty()}) {
    text->SetColor(1.0, 1.0, 1.0);
    text->SetFontSize(13);
    text->ShadowOff();
    text->ItalicOff();
  }
  m_bar->PickableOff();
  m_overlay->AddActor2D(m_bar);
}

int ReachScene::pointsShown() const {
  if (!m_map || !m_points) return 0;
  return static_cast<int>(m_map->map.points.size());
}

bool ReachScene::colourBarShown() const { return m_bar && m_bar->GetVisibility() != 0; }

}  // namespace multidir::ui
