#pragma once
// The robot cell's VTK actors (the viewer's cell view, docs/robot-cell.md "Studio"): the arm's links as simple
// solids from its DH frames (robot/arm_frames.h), the platform disc and the part (the regions printed before
// the step solid, the step's own translucent) at the pose the step's program commands for the move shown, the
// step's toolpath on the part, the fixed nozzle and the extruder's bodies, and the table. On the overlay (never
// hidden by the part): the toolpath point the move ends at, the nozzle tip, and where a step's conversion was
// refused a red marker with the text naming the step and line.
// Part of ui/viewer: only mesh_viewer_widget.cpp includes this header.
//
// Thread: GUI thread only, like every VTK object.
#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"
#include "ui/viewer/cell_motion.h"

class vtkActor;
class vtkRenderer;
class vtkTextActor;

namespace multidir::ui {

class CellScene {
 public:
  CellScene(vtkRenderer* renderer, vtkRenderer* overlay);
  ~CellScene();
  CellScene(const CellScene&) = delete;
  CellScene& operator=(const CellScene&) = delete;

  // Shows `motion` at its first position; null clears. A motion with no steps shows the cell alone, the arm at
  // its home joints.
  void setMotion(std::shared_ptr<const CellMotion> motion);
  [[nodiscard]] bool hasMotion() const { return m_motion != nullptr; }
  [[nodiscard]] const CellMotion* motion() const { return m_motion.get(); }
  void setPosition(CellPosition position);
  [[nodiscard]] CellPosition position() const { return m_position; }

  // Where things are drawn now (base frame, mm): the toolpath point of the move shown as its marker is placed,
  // the centre of the part's drawn bounds, and the warning shown ("" when none).
  [[nodiscard]] core::Vec3 toolpathPointDrawn() const;
  [[nodiscard]] core::Vec3 partCentreDrawn() const;
  [[nodiscard]] std::string warningShown() const;
  [[nodiscard]] bool warningMarkerShown() const;

 private:
  void build();
  void pose();
  void poseArm(const Eigen::Isometry3d& platform, const robot::Joints& joints);

  vtkRenderer* m_renderer;  // not owned
  vtkRenderer* m_overlay;   // not owned
  std::shared_ptr<const CellMotion> m_motion;
  CellPosition m_position;
  int m_builtStep = -1;  // the step whose part and toolpath the actors hold
  std::vector<vtkSmartPointer<vtkActor>> m_links;  // base column and one per joint, then the link solids
  vtkSmartPointer<vtkActor> m_platform;
  vtkSmartPointer<vtkActor> m_earlierPart;
  vtkSmartPointer<vtkActor> m_stepPart;
  vtkSmartPointer<vtkActor> m_toolpath;
  vtkSmartPointer<vtkActor> m_point;
  vtkSmartPointer<vtkActor> m_nozzle;
  vtkSmartPointer<vtkActor> m_warningMarker;
  vtkSmartPointer<vtkTextActor> m_warningText;
  std::vector<vtkSmartPointer<vtkActor>> m_fixed;  // extruder bodies and the table
};

}  // namespace multidir::ui
