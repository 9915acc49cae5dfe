#include "ui/viewer/axis_picker.h"

#include <QLocale>

#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {

AxisPicker::AxisPicker(MeshViewerWidget* viewer, QObject* parent) : QObject(parent), m_viewer(viewer) {
  connect(m_viewer, &MeshViewerWidget::platformPointPicked, this, &AxisPicker::onPointPicked);
  connect(m_viewer, &MeshViewerWidget::platformPickMissed, this, &AxisPicker::onMissed);
  connect(m_viewer, &MeshViewerWidget::platformPickCancelled, this, &AxisPicker::onViewerCancelled);
}

bool AxisPicker::start() {
  if (!m_viewer->hasMesh()) {
    emit message(tr("Open a model first: the rotation axis is picked on the platform under it."));
    return false;
  }
  m_points.clear();
  m_viewer->setPickMarkers(m_points);
  m_viewer->setPlatformPicking(true);
  m_viewer->setFocus(Qt::OtherFocusReason);  // so that Esc reaches the view
  const bool wasActive = m_active;
  m_active = true;
  emit message(tr("Click the first point on the platform (Esc cancels)."));
  if (!wasActive) emit activeChanged(true);
  return true;
}

void AxisPicker::cancel() {
  if (!m_active) return;
  m_viewer->setPlatformPicking(false);
  finish();
  emit message(tr("Picking the rotation axis was cancelled."));
}

void AxisPicker::onViewerCancelled() {
  if (!m_active) return;
  finish();
  emit message(tr("Picking the rotation axis was cancelled."));
}

void AxisPicker::onPointPicked(const core::Vec3& point) {
  if (!m_active) return;
  if (m_points.empty()) {
    m_points.push_back(point);
    m_viewer->setPickMarkers(m_points);
    emit message(tr("Click the second point on the platform: the axis runs from the first point to it."));
    return;
  }
  const std::optional<core::Vec3> axis = axisThroughPoints(m_viewer->platform().normal, m_points.front(), point);
  if (!axis) {
    emit message(tr("The second point is less than %1 mm from the first: click farther away.")
                     .arg(QLocale().toString(kMinAxisPointDistanceMm)));
    return;
  }
  m_viewer->setPlatformPicking(false);
  finish();
  const QLocale locale;
  emit message(tr("Rotation axis picked: (%1, %2, %3).")
                   .arg(locale.toString(axis->x(), 'f', 3), locale.toString(axis->y(), 'f', 3),
                        locale.toString(axis->z(), 'f', 3)));
  emit axisPicked(*axis);
}

void AxisPicker::onMissed(PlatformHitKind reason) {
  if (!m_active) return;
  switch (reason) {
    case PlatformHitKind::Parallel:
      emit message(tr("The view looks along the platform: turn the view and click again."));
      return;
    case PlatformHitKind::Behind:
    case PlatformHitKind::OutsideDisc:
    case PlatformHitKind::NoPlatform:
    case PlatformHitKind::Hit:
      break;
  }
  emit message(tr("That click missed the platform: click on the grey disc under the model."));
}

void AxisPicker::finish() {
  m_points.clear();
  m_active = false;
  emit activeChanged(false);
}

}  // namespace multidir::ui
