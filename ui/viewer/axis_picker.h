#pragma once
// Picking the 4-DOF rotation axis in the 3D view: two clicks on the platform, the axis runs from the first
// point to the second (within the platform plane). The picker drives the viewer's platform-picking mode,
// marks the points picked so far and tells, through message(), what to do next or why a click was not
// taken (it missed the platform, or lies too close to the first point).
//
// Picking ends with axisPicked() after the second point, or without an axis on cancel(), Esc in the view,
// or a new model in the view.
//
// Thread: GUI thread.
#include <QObject>
#include <QString>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"
#include "ui/viewer/platform_picker.h"

namespace multidir::ui {

class MeshViewerWidget;

class AxisPicker : public QObject {
  Q_OBJECT

 public:
  // `viewer` must outlive the picker (make it the picker's parent, or a sibling under one parent).
  explicit AxisPicker(MeshViewerWidget* viewer, QObject* parent = nullptr);

  // Starts picking from the first point (again, when already picking). False, with a message, when the
  // view shows no model (and so no platform).
  bool start();
  // Stops picking without an axis; does nothing when not picking.
  void cancel();
  [[nodiscard]] bool isActive() const { return m_active; }
  // The points picked so far in this round (0 or 1 while active).
  [[nodiscard]] const std::vector<core::Vec3>& points() const { return m_points; }

 signals:
  // For the status bar: what to click next, why a click was not taken, or how picking ended.
  void message(const QString& text);
  // The axis through the two points picked: unit length, in the platform plane.
  void axisPicked(const multidir::core::Vec3& axis);
  void activeChanged(bool active);

 private:
  void onPointPicked(const core::Vec3& point);
  void onMissed(PlatformHitKind reason);
  void onViewerCancelled();
  void finish();

  MeshViewerWidget* m_viewer;
  std::vector<core::Vec3> m_points;
  bool m_active = false;
};

}  // namespace multidir::ui
