#pragma once
// The plan view's support solids: one actor per region's support set, in one support colour, moved and
// shown together with their region (the exploded view, the sequence stepper). Turning the view with the
// machine needs nothing here: the camera turns, the supports stay attached to their regions.
// Part of ui/viewer: only mesh_viewer_widget.cpp includes this header.
//
// Thread: GUI thread only, like every VTK object.
#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

#include "multidir/core/supports/support_set.h"

class vtkActor;
class vtkRenderer;

namespace multidir::ui {

class SupportScene {
 public:
  explicit SupportScene(vtkRenderer* renderer);
  ~SupportScene();
  SupportScene(const SupportScene&) = delete;
  SupportScene& operator=(const SupportScene&) = delete;

  // Replaces the supports shown: set i belongs to region i of the plan shown (printing order). Sets without
  // struts get no actor. Every set is shown (when visible) and none is moved until place() says otherwise.
  void setSupports(std::shared_ptr<const std::vector<core::SupportSet>> supports);
  // Removes every support actor from the renderer.
  void clear();

  // Some set has struts.
  [[nodiscard]] bool hasSupports() const;
  void setVisible(bool visible);
  [[nodiscard]] bool isVisible() const { return m_visible; }
  // Set i moves by offsets[i] (its region's exploded-view offset; missing entries count as zero) and is
  // shown when i < shownRegions.
  void place(const std::vector<core::Vec3>& offsets, int shownRegions);
  // Support actors currently visible.
  [[nodiscard]] int shownCount() const;
  // Hides every support while something else stands in the plan's place (the G-code preview), keeping
  // setVisible's choice for when it ends.
  void setHidden(bool hidden);

 private:
  void applyVisibility();

  vtkRenderer* m_renderer;  // not owned: the widget's renderer outlives the scene
  std::shared_ptr<const std::vector<core::SupportSet>> m_supports;
  std::vector<vtkSmartPointer<vtkActor>> m_actors;  // one per set, null for an empty set
  int m_shownRegions = 0;
  bool m_visible = true;
  bool m_hidden = false;
};

}  // namespace multidir::ui
