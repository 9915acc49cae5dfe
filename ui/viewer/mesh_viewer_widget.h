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

#include "multidir/core/mesh/triangle_mesh.h"

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

  [[nodiscard]] bool hasMesh() const;
  // Number of frames rendered so far (grows by one per paintGL).
  [[nodiscard]] std::size_t framesRendered() const;

  // The colours the view uses; tests tell the model from the background by them.
  [[nodiscard]] static QColor modelColor();
  [[nodiscard]] static QColor platformColor();
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
