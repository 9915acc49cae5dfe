#pragma once
// The plan view's VTK actors: one per region (in its palette colour), an arrow per printing direction and a
// translucent disc per clipping plane, with the exploded view and the sequence stepper applied to them.
// Part of ui/viewer: only mesh_viewer_widget.cpp includes this header.
//
// Thread: GUI thread only, like every VTK object.
#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

#include "multidir/core/search/decomposition.h"
#include "ui/viewer/plan_geometry.h"

class vtkActor;
class vtkRenderer;

namespace multidir::ui {

class PlanScene {
 public:
  // Regions and discs go into `renderer`; arrows into `overlay`, a layer drawn over it with the same camera,
  // so an arrow starting inside the part stays visible.
  PlanScene(vtkRenderer* renderer, vtkRenderer* overlay);
  ~PlanScene();
  PlanScene(const PlanScene&) = delete;
  PlanScene& operator=(const PlanScene&) = delete;

  // Replaces the shown plan; `platformCenter` is where the first region's arrow starts and `sizeMm` (the
  // model's bounding diagonal) scales the arrows. Every region is shown, not exploded.
  void setPlan(std::shared_ptr<const core::Decomposition> plan, const core::Vec3& platformCenter, double sizeMm);
  // Removes every actor of the plan from the renderer.
  void clear();

  [[nodiscard]] bool hasPlan() const { return m_plan != nullptr; }
  [[nodiscard]] const core::Decomposition* plan() const { return m_plan.get(); }
  [[nodiscard]] int regionCount() const;

  void setDirectionsVisible(bool visible);
  void setPlanesVisible(bool visible);
  [[nodiscard]] bool planesVisible() const { return m_planesVisible; }
  // Moves regions apart along their printing directions (see explodeOffsets).
  void setExplodeDistance(double distanceMm);
  // Shows regions 1..count (clamped to [1, regionCount()]), with their arrows and base discs.
  void setShownRegions(int count);
  [[nodiscard]] int shownRegions() const { return m_shown; }
  [[nodiscard]] double explodeDistance() const { return m_explodeMm; }
  // The plane being edited (-1: none): its disc is outlined by a thick ring in a highlight colour and shown
  // even while the other discs are hidden. Kept when the plan is replaced (an edit rebuilds it).
  void setSelectedPlane(int plane);
  [[nodiscard]] int selectedPlane() const { return m_selectedPlane; }
  // The selected plane's outline is drawn now.
  [[nodiscard]] bool selectedPlaneShown() const;
  // The clipping plane whose disc is drawn at display point (x, y) (VTK's display pixels, origin bottom
  // left), the disc nearest the camera where several overlap; -1 when no disc drawn now is there. Regions
  // do not hide a disc: every disc lies inside the part it cut.
  [[nodiscard]] int planeAt(double x, double y) const;
  // Hides every actor of the plan while something else stands in its place (the G-code preview), keeping
  // the settings above; false shows them again as they were.
  void setHidden(bool hidden);
  [[nodiscard]] bool isHidden() const { return m_hidden; }

 private:
  void applyVisibility();
  void applyPlacement();

  vtkRenderer* m_renderer;  // not owned: the widget's renderers outlive the scene
  vtkRenderer* m_overlay;
  std::shared_ptr<const core::Decomposition> m_plan;
  std::vector<vtkSmartPointer<vtkActor>> m_regions;
  std::vector<vtkSmartPointer<vtkActor>> m_arrows;  // one per region
  std::vector<vtkSmartPointer<vtkActor>> m_discs;   // one per clipping plane (null when it left no cap)
  std::vector<vtkSmartPointer<vtkActor>> m_outlines;  // the discs' rims, shown for the selected plane
  std::vector<core::Vec3> m_arrowStarts;
  std::vector<PlaneDisc> m_planeDiscs;
  double m_arrowLengthMm = 10.0;
  double m_explodeMm = 0.0;
  int m_shown = 0;
  bool m_directionsVisible = true;
  bool m_planesVisible = false;
  int m_selectedPlane = -1;
  bool m_hidden = false;
};

}  // namespace multidir::ui
