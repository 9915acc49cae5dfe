#include "ui/viewer/plan_scene.h"

#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCellPicker.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderer.h>
#include <vtkTransform.h>
#include <vtkTubeFilter.h>

#include "multidir/core/common/units.h"
#include "ui/common/region_palette.h"
#include "ui/viewer/mesh_to_polydata.h"

namespace multidir::ui {
namespace {

constexpr double kArrowRgb[3] = {0.96, 0.96, 0.96};
constexpr double kDiscRgb[3] = {0.85, 0.92, 1.0};
constexpr double kDiscOpacity = 0.35;
// The plane being edited is outlined by a thick opaque ring in a warm yellow that no region colour is close
// to. A ring rather than a denser fill: the disc of a steep plane covers most of the part behind it.
constexpr double kOutlineRgb[3] = {1.0, 0.78, 0.18};
// The ring is a tube (wide GL lines are not drawn wide everywhere) this fraction of the disc's radius thick.
constexpr double kOutlineFraction = 0.012;
// Arrows are this fraction of the model's bounding diagonal long.
constexpr double kArrowFraction = 0.3;

// VTK's arrow points along +X from 0 to 1; this turns it to `direction`, starting at `start`.
vtkSmartPointer<vtkTransform> arrowTransform(const core::Vec3& start, const core::Vec3& direction, double length) {
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->Translate(start.x(), start.y(), start.z());
  const core::Vec3 unit = direction.normalized();
  const core::Vec3 axis = core::Vec3::UnitX().cross(unit);
  const double angle = std::atan2(axis.norm(), core::Vec3::UnitX().dot(unit));
  if (axis.norm() > 1e-12) {
    transform->RotateWXYZ(core::radToDeg(angle), axis.x(), axis.y(), axis.z());
  } else if (angle > 1.0) {  // -X
    transform->RotateZ(180.0);
  }
  transform->Scale(length, length, length);
  return transform;
}

vtkSmartPointer<vtkActor> arrowActor() {
  vtkNew<vtkArrowSource> source;
  source->SetTipResolution(24);
  source->SetShaftResolution(16);
  source->SetShaftRadius(0.025);
  source->SetTipRadius(0.07);
  source->SetTipLength(0.22);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(kArrowRgb[0], kArrowRgb[1], kArrowRgb[2]);
  actor->GetProperty()->SetAmbient(0.4);
  actor->GetProperty()->SetDiffuse(0.6);
  actor->PickableOff();
  return actor;
}

vtkSmartPointer<vtkActor> discActor(const PlaneDisc& disc) {
  vtkNew<vtkRegularPolygonSource> source;
  source->SetNumberOfSides(96);
  source->GeneratePolygonOn();
  source->GeneratePolylineOff();
  source->SetCenter(disc.center.x(), disc.center.y(), disc.center.z());
  source->SetNormal(disc.normal.x(), disc.normal.y(), disc.normal.z());
  source->SetRadius(disc.radiusMm);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  property->SetColor(kDiscRgb[0], kDiscRgb[1], kDiscRgb[2]);
  property->SetOpacity(kDiscOpacity);
  property->SetAmbient(0.5);
  property->SetDiffuse(0.5);
  property->BackfaceCullingOff();
  return actor;
}

vtkSmartPointer<vtkActor> outlineActor(const PlaneDisc& disc) {
  vtkNew<vtkRegularPolygonSource> source;
  source->SetNumberOfSides(96);
  source->GeneratePolygonOff();
  source->GeneratePolylineOn();
  source->SetCenter(disc.center.x(), disc.center.y(), disc.center.z());
  source->SetNormal(disc.normal.x(), disc.normal.y(), disc.normal.z());
  source->SetRadius(disc.radiusMm);
  vtkNew<vtkTubeFilter> tube;
  tube->SetInputConnection(source->GetOutputPort());
  tube->SetRadius(kOutlineFraction * disc.radiusMm);
  tube->SetNumberOfSides(10);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(tube->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  property->SetColor(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
  property->SetAmbient(0.35);
  property->SetDiffuse(0.65);
  actor->PickableOff();
  actor->VisibilityOff();
  return actor;
}

}  // namespace

PlanScene::PlanScene(vtkRenderer* renderer, vtkRenderer* overlay) : m_renderer(renderer), m_overlay(overlay) {}

PlanScene::~PlanScene() { clear(); }

int PlanScene::regionCount() const { return m_plan ? static_cast<int>(m_plan->regions.size()) : 0; }

void PlanScene::clear() {
  for (auto* list : {&m_regions, &m_arrows, &m_discs, &m_outlines}) {
    for (const vtkSmartPointer<vtkActor>& actor : *list) {
      if (!actor) continue;
      m_renderer->RemoveActor(actor);
      m_overlay->RemoveActor(actor);
    }
    list->clear();
  }
  m_arrowStarts.clear();
  m_planeDiscs.clear();
  m_plan.reset();
  m_shown = 0;
  m_explodeMm = 0.0;
}

void PlanScene::setPlan(std::shared_ptr<const core::Decomposition> plan, const core::Vec3& platformCenter,
                        double sizeMm) {
  clear();
  if (!plan || plan->regions.empty()) return;
  m_plan = std::move(plan);
  m_arrowLengthMm = kArrowFraction * (std::isfinite(sizeMm) && sizeMm > 0.0 ? sizeMm : 50.0);
  m_planeDiscs = planeDiscs(*m_plan);

  const std::size_t count = m_plan->regions.size();
  for (std::size_t i = 0; i < count; ++i) {
    const core::Region& region = m_plan->regions[i];
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(toPolyData(region.mesh));
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    const QColor colour = regionColor(static_cast<int>(i));
    vtkProperty* property = actor->GetProperty();
    property->SetColor(colour.redF(), colour.greenF(), colour.blueF());
    property->SetInterpolationToFlat();
    property->SetAmbient(0.15);
    property->SetDiffuse(0.85);
    property->SetSpecular(0.0);
    m_renderer->AddActor(actor);
    m_regions.push_back(actor);

    // The arrow starts on the region's base: the centre of its clipping plane's cut, or the platform.
    core::Vec3 start = platformCenter;
    const std::int32_t plane = region.clippingIndex;
    if (plane >= 0 && static_cast<std::size_t>(plane) < m_planeDiscs.size() &&
        m_planeDiscs[static_cast<std::size_t>(plane)].radiusMm > 0.0) {
      start = m_planeDiscs[static_cast<std::size_t>(plane)].center;
    }
    m_arrowStarts.push_back(start);
    vtkSmartPointer<vtkActor> arrow = arrowActor();
    m_overlay->AddActor(arrow);
    m_arrows.push_back(arrow);
  }
  for (const PlaneDisc& disc : m_planeDiscs) {
    vtkSmartPointer<vtkActor> actor;
    vtkSmartPointer<vtkActor> outline;
    if (disc.radiusMm > 0.0) {
      actor = discActor(disc);
      m_renderer->AddActor(actor);
      outline = outlineActor(disc);
      m_renderer->AddActor(outline);
    }
    m_discs.push_back(actor);
    m_outlines.push_back(outline);
  }
  m_shown = static_cast<int>(count);
  applyPlacement();
  applyVisibility();
}

void PlanScene::setDirectionsVisible(bool visible) {
  m_directionsVisible = visible;
  applyVisibility();
}

void PlanScene::setPlanesVisible(bool visible) {
  m_planesVisible = visible;
  applyVisibility();
}

void PlanScene::setExplodeDistance(double distanceMm) {
  m_explodeMm = std::isfinite(distanceMm) ? std::max(0.0, distanceMm) : 0.0;
  applyPlacement();
}

void PlanScene::setShownRegions(int count) {
  if (!m_plan) return;
  m_shown = std::clamp(count, 1, regionCount());
  applyVisibility();
}

void PlanScene::setSelectedPlane(int plane) {
  m_selectedPlane = plane >= 0 ? plane : -1;
  applyVisibility();
}

bool PlanScene::selectedPlaneShown() const {
  if (m_selectedPlane < 0 || static_cast<std::size_t>(m_selectedPlane) >= m_outlines.size()) return false;
  const vtkSmartPointer<vtkActor>& outline = m_outlines[static_cast<std::size_t>(m_selectedPlane)];
  return outline && outline->GetVisibility() != 0;
}

int PlanScene::planeAt(double x, double y) const {
  // A ray cast against the disc actors only (their placement included), done on the CPU: no GL context is
  // needed, unlike the hardware pickers.
  vtkNew<vtkCellPicker> picker;
  picker->PickFromListOn();
  bool anyShown = false;
  for (const vtkSmartPointer<vtkActor>& disc : m_discs) {
    if (!disc || disc->GetVisibility() == 0) continue;
    picker->AddPickList(disc);
    anyShown = true;
  }
  if (!anyShown || picker->Pick(x, y, 0.0, m_renderer) == 0) return -1;
  const vtkActor* hit = picker->GetActor();
  for (std::size_t k = 0; k < m_discs.size(); ++k) {
    if (m_discs[k] && m_discs[k].GetPointer() == hit) return static_cast<int>(k);
  }
  return -1;
}

void PlanScene::applyPlacement() {
  if (!m_plan) return;
  const std::vector<core::Vec3> offsets = explodeOffsets(*m_plan, m_explodeMm);
  for (std::size_t i = 0; i < m_regions.size(); ++i) {
    const core::Vec3& offset = offsets[i];
    m_regions[i]->SetPosition(offset.x(), offset.y(), offset.z());
    m_arrows[i]->SetUserTransform(
        arrowTransform(m_arrowStarts[i] + offset, m_plan->regions[i].printingDirection, m_arrowLengthMm));
  }
  // A disc moves with the region standing on it, so it stays at that region's base.
  for (std::size_t i = 0; i < m_regions.size(); ++i) {
    const std::int32_t plane = m_plan->regions[i].clippingIndex;
    if (plane < 0 || static_cast<std::size_t>(plane) >= m_discs.size() || !m_discs[static_cast<std::size_t>(plane)])
      continue;
    const core::Vec3& offset = offsets[i];
    m_discs[static_cast<std::size_t>(plane)]->SetPosition(offset.x(), offset.y(), offset.z());
    m_outlines[static_cast<std::size_t>(plane)]->SetPosition(offset.x(), offset.y(), offset.z());
  }
}

void PlanScene::setHidden(bool hidden) {
  m_hidden = hidden;
  applyVisibility();
}

void PlanScene::applyVisibility() {
  if (!m_plan) return;
  for (std::size_t i = 0; i < m_regions.size(); ++i) {
    const bool shown = !m_hidden && static_cast<int>(i) < m_shown;
    m_regions[i]->SetVisibility(shown);
    m_arrows[i]->SetVisibility(shown && m_directionsVisible);
  }
  for (std::size_t k = 0; k < m_discs.size(); ++k) {
    if (!m_discs[k]) continue;
    m_discs[k]->VisibilityOff();
    m_outlines[k]->VisibilityOff();
  }
  for (std::size_t i = 0; i < m_regions.size(); ++i) {
    const std::int32_t plane = m_plan->regions[i].clippingIndex;
    if (plane < 0 || static_cast<std::size_t>(plane) >= m_discs.size() || !m_discs[static_cast<std::size_t>(plane)])
      continue;
    const bool shown = !m_hidden && static_cast<int>(i) < m_shown;
    const bool selected = plane == m_selectedPlane;
    m_discs[static_cast<std::size_t>(plane)]->SetVisibility((m_planesVisible || selected) && shown);
    m_outlines[static_cast<std::size_t>(plane)]->SetVisibility(selected && shown);
  }
}

}  // namespace multidir::ui
