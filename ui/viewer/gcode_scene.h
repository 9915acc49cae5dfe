#pragma once
// The G-code preview's VTK actors: the extrusions of every step as lines in the step's region colour
// (ui/region_palette.h), drawn unlit so they keep it exactly, and the travel moves as thinner lines in
// MeshViewerWidget::gcodeTravelColor(), hidden until asked for. The layer limit shows layers 1..N of the job
// (printing order over all steps). Extrusions the audit marked unsupported (ToolpathSegment::unsupported) are
// drawn instead in unsupportedExtrusionColor(), a little thicker.
// Part of ui/viewer: only mesh_viewer_widget.cpp includes this header.
//
// Thread: GUI thread only, like every VTK object.
#include <vtkSmartPointer.h>

#include <memory>

#include "ui/viewer/gcode_toolpaths.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace multidir::ui {

class GcodeScene {
 public:
  explicit GcodeScene(vtkRenderer* renderer);
  ~GcodeScene();
  GcodeScene(const GcodeScene&) = delete;
  GcodeScene& operator=(const GcodeScene&) = delete;

  // Shows `preview` with every layer; travel moves as set with setTravelVisible. Null clears.
  void setPreview(std::shared_ptr<const GcodePreview> preview);
  void clear();
  [[nodiscard]] bool hasPreview() const { return m_preview != nullptr; }
  [[nodiscard]] const GcodePreview* preview() const { return m_preview.get(); }

  // Layers 1..`layers` are drawn (clamped to [0, layerCount]).
  void setLayerLimit(int layers);
  [[nodiscard]] int layerLimit() const { return m_layerLimit; }
  void setTravelVisible(bool visible);
  [[nodiscard]] bool travelVisible() const { return m_travelVisible; }

  // Line segments drawn now (extrusions: the unsupported ones included).
  [[nodiscard]] int extrusionLinesShown() const;
  [[nodiscard]] int unsupportedLinesShown() const;
  [[nodiscard]] int travelLinesShown() const;

 private:
  void rebuild();

  vtkRenderer* m_renderer;  // not owned: the widget's renderer outlives the scene
  std::shared_ptr<const GcodePreview> m_preview;
  vtkSmartPointer<vtkPolyData> m_extrusionData;
  vtkSmartPointer<vtkPolyData> m_travelData;
  vtkSmartPointer<vtkActor> m_extrusionActor;
  vtkSmartPointer<vtkActor> m_travelActor;
  vtkSmartPointer<vtkPolyData> m_unsupportedData;
  vtkSmartPointer<vtkActor> m_unsupportedActor;
  int m_layerLimit = 0;
  bool m_travelVisible = false;
};

}  // namespace multidir::ui
