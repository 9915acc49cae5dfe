#include "ui/viewer/support_scene.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "ui/common/region_palette.h"
#include "ui/viewer/mesh_to_polydata.h"

namespace multidir::ui {

SupportScene::SupportScene(vtkRenderer* renderer) : m_renderer(renderer) {}

SupportScene::~SupportScene() { clear(); }

void SupportScene::clear() {
  for (const vtkSmartPointer<vtkActor>& actor : m_actors) {
    if (actor) m_renderer->RemoveActor(actor);
  }
  m_actors.clear();
  m_supports.reset();
  m_shownRegions = 0;
}

void SupportScene::setSupports(std::shared_ptr<const std::vector<core::SupportSet>> supports) {
  clear();
  if (!supports) return;
  m_supports = std::move(supports);
  const QColor colour = supportColor();
  for (const core::SupportSet& set : *m_supports) {
    vtkSmartPointer<vtkActor> actor;
    if (!set.empty() && !set.mesh.empty()) {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(toPolyData(set.mesh));
      mapper->ScalarVisibilityOff();
      actor = vtkSmartPointer<vtkActor>::New();
      actor->SetMapper(mapper);
      vtkProperty* property = actor->GetProperty();
      property->SetColor(colour.redF(), colour.greenF(), colour.blueF());
      // Flat and without highlights, like the regions: shading only scales the colour, so a picture tells
      // supports from regions by hue.
      property->SetInterpolationToFlat();
      property->SetAmbient(0.2);
      property->SetDiffuse(0.8);
      property->SetSpecular(0.0);
      actor->PickableOff();
      m_renderer->AddActor(actor);
    }
    m_actors.push_back(actor);
  }
  m_shownRegions = static_cast<int>(m_actors.size());
  applyVisibility();
}

bool SupportScene::hasSupports() const {
  for (const vtkSmartPointer<vtkActor>& actor : m_actors) {
    if (actor) return true;
  }
  return false;
}

void SupportScene::setVisible(bool visible) {
  m_visible = visible;
  applyVisibility();
}

void SupportScene::place(const std::vector<core::Vec3>& offsets, int shownRegions) {
  for (std::size_t i = 0; i < m_actors.size(); ++i) {
    if (!m_actors[i]) continue;
    const core::Vec3 offset = i < offsets.size() ? offsets[i] : core::Vec3::Zero();
    m_actors[i]->SetPosition(offset.x(), offset.y(), offset.z());
  }
  m_shownRegions = shownRegions;
  applyVisibility();
}

int SupportScene::shownCount() const {
  int count = 0;
  for (const vtkSmartPointer<vtkActor>& actor : m_actors) {
    if (actor && actor->GetVisibility()) ++count;
  }
  return count;
}

void SupportScene::setHidden(bool hidden) {
  m_hidden = hidden;
  applyVisibility();
}

void SupportScene::applyVisibility() {
  for (std::size_t i = 0; i < m_actors.size(); ++i) {
    if (m_actors[i]) m_actors[i]->SetVisibility(m_visible && !m_hidden && static_cast<int>(i) < m_shownRegions);
  }
}

}  // namespace multidir::ui
