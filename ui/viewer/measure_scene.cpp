#include "ui/viewer/measure_scene.h"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace multidir::ui {
namespace {

// A bright cyan, far in hue from the model's grey-blue, the overhang orange, the region palette's colours
// and the platform-pick magenta.
constexpr double kMeasureRgb[3] = {0.20, 0.95, 0.95};

}  // namespace

MeasureScene::MeasureScene(vtkRenderer* overlay) : m_overlay(overlay) {
  m_lineSource = vtkSmartPointer<vtkLineSource>::New();
  vtkNew<vtkPolyDataMapper> lineMapper;
  lineMapper->SetInputConnection(m_lineSource->GetOutputPort());
  m_line = vtkSmartPointer<vtkActor>::New();
  m_line->SetMapper(lineMapper);
  m_line->GetProperty()->SetColor(kMeasureRgb[0], kMeasureRgb[1], kMeasureRgb[2]);
  m_line->GetProperty()->SetLineWidth(3.0);
  m_line->GetProperty()->LightingOff();
  m_line->PickableOff();
  m_line->VisibilityOff();
  m_overlay->AddActor(m_line);

  m_label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
  vtkTextProperty* label = m_label->GetTextProperty();
  label->SetFontSize(18);
  label->SetBold(true);
  label->SetColor(kMeasureRgb[0], kMeasureRgb[1], kMeasureRgb[2]);
  label->SetBackgroundColor(0.0, 0.0, 0.0);
  label->SetBackgroundOpacity(0.6);
  label->SetJustificationToCentered();
  label->SetVerticalJustificationToBottom();
  m_label->PickableOff();
  m_label->VisibilityOff();
  m_overlay->AddActor(m_label);

  m_corner = vtkSmartPointer<vtkTextActor>::New();
  vtkTextProperty* corner = m_corner->GetTextProperty();
  corner->SetFontSize(16);
  corner->SetColor(1.0, 1.0, 1.0);
  corner->SetBackgroundColor(0.0, 0.0, 0.0);
  corner->SetBackgroundOpacity(0.6);
  corner->SetJustificationToLeft();
  corner->SetVerticalJustificationToTop();
  m_corner->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  m_corner->SetPosition(0.01, 0.98);
  m_corner->PickableOff();
  m_corner->VisibilityOff();
  m_overlay->AddActor2D(m_corner);
}

MeasureScene::~MeasureScene() { clear(); }

void MeasureScene::show(const std::vector<core::Vec3>& worldPoints, double markerRadiusMm, const std::string& corner,
                        const std::string& label) {
  clear();
  if (worldPoints.empty()) return;
  for (const core::Vec3& point : worldPoints) {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(point.x(), point.y(), point.z());
    sphere->SetRadius(markerRadiusMm);
    sphere->SetThetaResolution(20);
    sphere->SetPhiResolution(12);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(kMeasureRgb[0], kMeasureRgb[1], kMeasureRgb[2]);
    actor->GetProperty()->SetAmbient(0.5);
    actor->GetProperty()->SetDiffuse(0.5);
    actor->PickableOff();
    m_overlay->AddActor(actor);
    m_markers.push_back(actor);
  }
  m_markersShown = static_cast<int>(m_markers.size());
  if (worldPoints.size() == 2) {
    const core::Vec3& a = worldPoints[0];
    const core::Vec3& b = worldPoints[1];
    m_lineSource->SetPoint1(a.x(), a.y(), a.z());
    m_lineSource->SetPoint2(b.x(), b.y(), b.z());
    m_line->VisibilityOn();
    const core::Vec3 middle = 0.5 * (a + b);
    m_label->SetPosition(middle.x(), middle.y(), middle.z());
    m_label->SetInput(label.c_str());
    m_label->VisibilityOn();
  }
  m_corner->SetInput(corner.c_str());
  m_corner->VisibilityOn();
}

void MeasureScene::clear() {
  for (const vtkSmartPointer<vtkActor>& actor : m_markers) m_overlay->RemoveActor(actor);
  m_markers.clear();
  m_markersShown = 0;
  m_line->VisibilityOff();
  m_label->VisibilityOff();
  m_corner->VisibilityOff();
}

bool MeasureScene::lineShown() const { return m_line->GetVisibility() != 0; }

}  // namespace multidir::ui
