#pragma once
// Solids shown each in its own colour with a label beside it, in place of the model and plan: the Print apart
// view's parts exploded with their dowels, or one plate with its parts laid out. Part of ui/viewer: only
// mesh_viewer_widget.cpp includes this header.
//
// Thread: GUI thread only, like every VTK object.
#include <vtkSmartPointer.h>

#include <vector>

#include "ui/viewer/coloured_solid.h"

class vtkActor;
class vtkBillboardTextActor3D;
class vtkRenderer;

namespace multidir::ui {

class SolidsScene {
 public:
  // Solids go into `renderer`, their labels into `overlay` (drawn over them, so a label is never hidden).
  SolidsScene(vtkRenderer* renderer, vtkRenderer* overlay);
  ~SolidsScene();
  SolidsScene(const SolidsScene&) = delete;
  SolidsScene& operator=(const SolidsScene&) = delete;

  void setSolids(const std::vector<ColouredSolid>& solids);
  void clear();
  [[nodiscard]] int count() const { return static_cast<int>(m_actors.size()); }

 private:
  vtkRenderer* m_renderer;  // not owned: the widget's renderers outlive the scene
  vtkRenderer* m_overlay;
  std::vector<vtkSmartPointer<vtkActor>> m_actors;
  std::vector<vtkSmartPointer<vtkBillboardTextActor3D>> m_labels;
};

}  // namespace multidir::ui
