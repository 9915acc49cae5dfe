#pragma once
// The 3D view of one model: VTK rendering inside a Qt6 QOpenGLWidget. VTK stays behind the pimpl, so
// this header is usable without VTK (multidir-studio and the tests include it).
//
// Debian's VTK Qt module is built against Qt5 and must not be linked (Qt5 and Qt6 in one process crash),
// so the bridge is done here: VTK renders through a vtkGenericOpenGLRenderWindow into this widget's
// framebuffer, and Qt's input events are forwarded to a VTK interactor with a trackball-camera style.
//
// Thread: everything runs on the GUI thread.
#include <QColor>
#include <QOpenGLWidget>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::ui {

class MeshViewerWidget : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit MeshViewerWidget(QWidget* parent = nullptr);
  ~MeshViewerWidget() override;
  MeshViewerWidget(const MeshViewerWidget&) = delete;
  MeshViewerWidget& operator=(const MeshViewerWidget&) = delete;

  // Shows `mesh` (copied into the view), flat-shaded, on a platform through its lowest point along `up`,
  // with `up` pointing up on screen, and fits the view. A zero or non-finite `up` counts as +Z.
  void setMesh(const core::TriangleMesh& mesh, const core::Vec3& up);
  // Removes the model and the platform; the background and the axes marker stay.
  void clear();
  // Looks at the whole model and platform from the front, slightly from above and to the right.
  void fitView();

  // Overhangs: faces flagged in `risky` (one flag per face of the mesh shown, cell i = face i) are drawn in
  // riskyColor(), the others in modelColor(). Only the per-face colour array is rewritten, nothing else of
  // the pipeline. Returns false and changes nothing when the count is not the mesh's face count.
  bool setRiskyFaces(const std::vector<char>& risky);
  // Faces currently drawn in the overhang colour.
  [[nodiscard]] std::size_t riskyFacesShown() const;

  // 4-DOF machines: an arrow along `axis` lying on the platform through its centre; nullopt hides it.
  void setRotationAxis(const std::optional<core::Vec3>& axis);
  [[nodiscard]] bool rotationAxisShown() const;

  // Plan view: the plan's regions (in their palette colours, ui/region_palette.h) replace the model; the
  // platform stays under the model set with setMesh. A null or empty plan clears the plan view.
  void setPlan(std::shared_ptr<const core::Decomposition> plan);
  // Back to the model view.
  void clearPlan();
  [[nodiscard]] bool hasPlan() const;
  void setPrintingDirectionsVisible(bool visible);
  void setClippingPlanesVisible(bool visible);
  // Exploded view: regions moved apart along their printing directions by `distanceMm` per level.
  void setExplodeDistance(double distanceMm);
  // Sequence stepper: regions 1..count are shown (clamped to the plan's regions).
  void setShownRegions(int count);
  [[nodiscard]] int shownRegions() const;
  // When on, the view turns as the machine turns the part: the printing direction of the last region shown
  // points up on screen.
  void setTurnWithMachine(bool turn);
  // The direction pointing up on screen after the last fit.
  [[nodiscard]] core::Vec3 viewUp() const;

  [[nodiscard]] bool hasMesh() const;
  // Number of frames rendered so far (grows by one per paintGL).
  [[nodiscard]] std::size_t framesRendered() const;

  // The colours the view uses; tests tell the model from the background by them.
  [[nodiscard]] static QColor modelColor();
  [[nodiscard]] static QColor platformColor();
  [[nodiscard]] static QColor riskyColor();
  [[nodiscard]] static QColor backgroundTopColor();
  [[nodiscard]] static QColor backgroundBottomColor();

  QSize sizeHint() const override;

 signals:
  // Emitted after each rendered frame.
  void frameRendered();

 protected:
  void initializeGL() override;
  void paintGL() override;
  void resizeGL(int width, int height) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;

 private:
  void releaseGraphics();

  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::ui
