#include "ui/viewer/solids_scene.h"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include "ui/viewer/mesh_to_polydata.h"

namespace multidir::ui {

SolidsScene::SolidsScene(vtkRenderer* renderer, vtkRenderer* overlay) : m_renderer(renderer), m_overlay(overlay) {}

SolidsScene::~SolidsScene() { clear(); }

void SolidsScene::clear() {
  for (const vtkSmartPointer<vtkActor>& actor : m_actors) m_renderer->RemoveActor(actor);
  for (const vtkSmartPointer<vtkBillboardTextActor3D>& label : m_labels) m_overlay->RemoveActor(label);
  m_actors.clear();
  m_labels.clear();
}

void SolidsScene::setSolids(const std::vector<ColouredSolid>& solids) {
  clear();
  for (const ColouredSolid& solid : solids) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(toPolyData(solid.mesh));
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetColor(solid.colour.redF(), solid.colour.greenF(), solid.colour.blueF());
    // Flat and without highlights, like the plan's regions: shading only scales the colour, so a picture
    // tells the solids apart by hue.
    property->SetInterpolationToFlat();
    property->SetAmbient(0.2);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.0);
    actor->PickableOff();
    m_renderer->AddActor(actor);
    m_actors.push_back(actor);
    if (solid.label.isEmpty()) continue;
    auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    label->SetInput(solid.label.toUtf8().constData());
    label->SetPosition(solid.labelAt.x(), solid.labelAt.y(), solid.labelAt.z());
    vtkTextProperty* text = label->GetTextProperty();
    text->SetFontSize(18);
    text->SetBold(true);
    text->SetColor(0.05, 0.05, 0.05);
    text->SetBackgroundColor(1.0, 1.0, 1.0);
    text->SetBackgroundOpacity(0.8);
    text->SetJustificationToCentered();
    text->SetVerticalJustificationToCentered();
    label->PickableOff();
    m_overlay->AddActor(label);
    m_labels.push_back(label);
  }
}

}  // namespace multidir::ui
