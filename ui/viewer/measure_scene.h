#pragma once
// The measuring tool's VTK actors: a marker at each picked point, the line between them with the distance
// at its middle, and the picked coordinates in the view's top-left corner (so a screenshot records them).
// Part of ui/viewer: only mesh_viewer_widget.cpp includes this header.
//
// Thread: GUI thread only, like every VTK object.
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"

class vtkActor;
class vtkBillboardTextActor3D;
class vtkLineSource;
class vtkRenderer;
class vtkTextActor;

namespace multidir::ui {

class MeasureScene {
 public:
  // Everything goes into `overlay`, a layer drawn over the model with the same camera: a point picked on a
  // face stays visible however the view turns.
  explicit MeasureScene(vtkRenderer* overlay);
  ~MeasureScene();
  MeasureScene(const MeasureScene&) = delete;
  MeasureScene& operator=(const MeasureScene&) = delete;

  // Shows the picked points where they are drawn (`worldPoints`: none, one, or two with the line between them),
  // markers of `markerRadiusMm`, with `corner` in the corner and `label` at the line's middle. No points
  // hides everything.
  void show(const std::vector<core::Vec3>& worldPoints, double markerRadiusMm, const std::string& corner,
            const std::string& label);
  void clear();
  [[nodiscard]] int markersShown() const { return m_markersShown; }
  [[nodiscard]] bool lineShown() const;

 private:
  vtkRenderer* m_overlay;  // not owned: the widget's renderers outlive the scene
  std::vector<vtkSmartPointer<vtkActor>> m_markers;
  vtkSmartPointer<vtkLineSource> m_lineSource;
  vtkSmartPointer<vtkActor> m_line;
  vtkSmartPointer<vtkBillboardTextActor3D> m_label;
  vtkSmartPointer<vtkTextActor> m_corner;
  int m_markersShown = 0;
};

}  // namespace multidir::ui
