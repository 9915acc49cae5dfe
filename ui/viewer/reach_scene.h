#pragma once
// The reach map in the viewer's cell view (docs/robot-cell.md, "Studio"): every sampled nozzle position as a point
// in its score's colour (robot::reachColour, the PLY's and the PNG's scale), the best position as a larger ball
// in its colour ringed in black, and the colour bar with its meaning. Drawn with the cell (the base frame, mm):
// the points in the scene, the best ball on the overlay so nothing hides it, its black ring behind it in the
// scene.
// Part of ui/viewer: only mesh_viewer_widget.cpp includes this header.
//
// Thread: GUI thread only, like every VTK object.
#include <vtkSmartPointer.h>

#include <memory>
#include <string>

#include "ui/viewer/cell_reach_map.h"

class vtkActor;
class vtkRenderer;
class vtkScalarBarActor;

namespace multidir::ui {

class ReachScene {
 public:
  ReachScene(vtkRenderer* renderer, vtkRenderer* overlay);
  ~ReachScene();
  ReachScene(const ReachScene&) = delete;
  ReachScene& operator=(const ReachScene&) = delete;

  // Shows `map` (null clears); `barTitle` is the colour bar's title (translated by the caller).
  void setMap(std::shared_ptr<const CellReachMap> map, const std::string& barTitle);
  [[nodiscard]] const CellReachMap* map() const { return m_map.get(); }
  // Points drawn now: the map's positions when one is shown, else 0.
  [[nodiscard]] int pointsShown() const;
  [[nodiscard]] bool colourBarShown() const;

 private:
  void clear();

  vtkRenderer* m_renderer;  // not owned
  vtkRenderer* m_overlay;   // not owned
  std::shared_ptr<const CellReachMap> m_map;
  vtkSmartPointer<vtkActor> m_points;
  vtkSmartPointer<vtkActor> m_best;
  vtkSmartPointer<vtkActor> m_bestRing;
  vtkSmartPointer<vtkScalarBarActor> m_bar;
};

}  // namespace multidir::ui
