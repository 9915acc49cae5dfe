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
#include "multidir/core/supports/support_set.h"
#include "ui/viewer/cell_motion.h"
#include "ui/viewer/cell_reach_map.h"
#include "ui/viewer/coloured_solid.h"
#include "ui/viewer/measurement.h"
#include "ui/viewer/platform_geometry.h"
#include "ui/viewer/platform_picker.h"
#include "ui/viewer/standard_view.h"

namespace multidir::ui {

struct GcodePreview;

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
  // Removes the model and the platform; the background and the axes marker stay, and the empty view's hint
  // shows again.
  void clear();
  // Shows `solids`, each in its colour with its label, instead of the model, plan and platform (the Print apart
  // view's exploded parts or one plate); `up` points up on the screen. setMesh and clear remove them.
  void setSolids(const std::vector<ColouredSolid>& solids, const core::Vec3& up);
  [[nodiscard]] int solidCount() const;
  // Looks at the whole model and platform from the front, slightly from above and to the right.
  void fitView();
  // Looks at the whole model and platform from `view` (ui/viewer/standard_view.h), relative to the model's up.
  void setStandardView(StandardView view);
  // Parallel (orthographic) projection instead of perspective; the framing stays.
  void setOrthographic(bool orthographic);
  [[nodiscard]] bool isOrthographic() const;
  // The camera as drawn now: the unit direction it looks along, and what points up on screen (unit).
  [[nodiscard]] core::Vec3 cameraDirection() const;
  [[nodiscard]] core::Vec3 cameraUp() const;
  // The up direction of an empty view (no model): the axes marker shows it up on screen, so an empty session
  // agrees with the Up box. setMesh brings the model's own up.
  void setEmptyUp(const core::Vec3& up);
  // The hint an empty view shows ("Open a model..."): shown exactly while there is no model.
  [[nodiscard]] bool isEmptyHintShown() const;
  [[nodiscard]] QString emptyHintText() const;

  // Measuring (View > Measure distance): while on, the cursor is a cross and each left click without
  // movement on the model (or the plan's regions) picks a point on the face under the cursor; the second
  // pick completes a measurement (both points, the line and the distance drawn), a third starts a new one.
  // Drags still turn the view. Esc ends it (measuringChanged(false)), and so do a new model, plan or clear();
  // ending clears the measurement.
  void setMeasuring(bool on);
  [[nodiscard]] bool isMeasuring() const;
  [[nodiscard]] const Measurement& measurement() const;
  // The point of the model's surface under `position` (widget coordinates, logical pixels), in the model's
  // coordinates (mm); nullopt when the ray meets no face of the model or the plan's regions.
  [[nodiscard]] std::optional<core::Vec3> modelPointAt(const QPointF& position) const;
  // Markers of the measurement drawn now (0, 1 or 2), and whether its line is drawn.
  [[nodiscard]] int measureMarkersShown() const;
  [[nodiscard]] bool measureLineShown() const;

  // Overhangs: faces flagged in `risky` (one flag per face of the mesh shown, cell i = face i) are drawn in
  // riskyColor(), the others in modelColor(). Only the per-face colour array is rewritten, nothing else of
  // the pipeline. Returns false and changes nothing when the count is not the mesh's face count.
  bool setRiskyFaces(const std::vector<char>& risky);
  // Faces currently drawn in the overhang colour.
  [[nodiscard]] std::size_t riskyFacesShown() const;

  // 4-DOF machines: an arrow along `axis` lying on the platform through its centre; nullopt hides it.
  void setRotationAxis(const std::optional<core::Vec3>& axis);
  [[nodiscard]] bool rotationAxisShown() const;

  // The platform under the model last set with setMesh (radius 0 before the first).
  [[nodiscard]] PlatformDisc platform() const;
  // Platform picking (choosing the 4-DOF axis by clicks): while on, the cursor is a cross and a left click
  // without movement emits platformPointPicked (on the platform) or platformPickMissed; drags still turn the
  // view. Esc emits platformPickCancelled and ends it, and so does a new model or clear(). Off clears the
  // pick markers.
  void setPlatformPicking(bool on);
  [[nodiscard]] bool isPlatformPicking() const;
  // What the ray under `position` (widget coordinates, logical pixels) meets on the platform, as drawn now.
  [[nodiscard]] PlatformHit platformHitAt(const QPointF& position) const;
  // The point of the platform under `position`; nullopt when the ray misses the disc or nothing is shown.
  [[nodiscard]] std::optional<core::Vec3> platformPointAt(const QPoint& position) const;
  // Where `point` (mm) appears in the widget (logical pixels); nullopt when it is behind the camera.
  [[nodiscard]] std::optional<QPointF> widgetPositionOf(const core::Vec3& point) const;
  // Small markers at picked points (empty: none).
  void setPickMarkers(const std::vector<core::Vec3>& points);
  [[nodiscard]] std::size_t pickMarkersShown() const;

  // Plan view: the plan's regions (in their palette colours, ui/region_palette.h) replace the model; the
  // platform stays under the model set with setMesh. A null or empty plan clears the plan view. Camera::Keep
  // leaves the camera where it is (an edited plan replacing the one shown) instead of fitting the view.
  enum class Camera { Fit, Keep };
  void setPlan(std::shared_ptr<const core::Decomposition> plan, Camera camera = Camera::Fit);
  // Back to the model view.
  void clearPlan();
  [[nodiscard]] bool hasPlan() const;
  // The plan's supports, one set per region in printing order, drawn in supportColor() (ui/region_palette.h)
  // and moved and stepped through with their regions. Call after setPlan (which drops earlier supports);
  // returns false and shows none when there is no plan or the count differs from its regions'.
  bool setSupports(std::shared_ptr<const std::vector<core::SupportSet>> supports);
  void setSupportsVisible(bool visible);
  // Support sets (with struts) drawn now.
  [[nodiscard]] int supportSetsShown() const;
  void setPrintingDirectionsVisible(bool visible);
  void setClippingPlanesVisible(bool visible);
  // The clipping plane being edited (-1: none): its disc is highlighted and shown even while the others are
  // hidden. Kept when the plan is replaced.
  void setSelectedPlane(int plane);
  [[nodiscard]] int selectedPlane() const;
  // The selected plane's disc is drawn now (false when it left no cut to draw).
  [[nodiscard]] bool selectedPlaneShown() const;
  // The clipping plane whose disc is drawn under `position` (widget coordinates, logical pixels), the disc
  // nearest the camera where several overlap; -1 when no disc is drawn there. Regions do not hide a disc
  // (every disc lies inside the part it cut). A click there emits clippingPlaneClicked.
  [[nodiscard]] int clippingPlaneAt(const QPointF& position) const;
  // Exploded view: regions moved apart along their printing directions by `distanceMm` per level.
  void setExplodeDistance(double distanceMm);
  // Sequence stepper: regions 1..count are shown (clamped to the plan's regions).
  void setShownRegions(int count);
  [[nodiscard]] int shownRegions() const;
  // When on, the view turns as the machine turns the part: the printing direction of the last region shown
  // points up on screen.
  void setTurnWithMachine(bool turn);
  // G-code preview (ui/viewer/gcode_toolpaths.h): the toolpaths of the sliced plan, in model coordinates so
  // they lie where the plan view shows the regions, each step's extrusions in its region's colour; the plan's
  // regions, arrows, discs and supports are hidden meanwhile (the platform stays). Travel moves are hidden
  // until setGcodeTravelVisible(true); every layer is shown until setGcodeLayerLimit. Null ends the preview
  // (back to the plan view as it was); so do setPlan, clearPlan, setMesh and clear. Returns false and shows
  // nothing when no plan is shown.
  bool setGcodePreview(std::shared_ptr<const GcodePreview> preview);
  [[nodiscard]] bool hasGcodePreview() const;
  // Layers 1..`layers` of the job (printing order over the steps) are drawn.
  void setGcodeLayerLimit(int layers);
  [[nodiscard]] int gcodeLayerLimit() const;
  void setGcodeTravelVisible(bool visible);
  // Line segments drawn now (extrusions: those in the warning colour included).
  [[nodiscard]] int gcodeExtrusionLinesShown() const;
  [[nodiscard]] int gcodeUnsupportedLinesShown() const;
  [[nodiscard]] int gcodeTravelLinesShown() const;

  // Robot cell view (docs/robot-cell.md, "Studio"): the job posed on the cell (ui/viewer/cell_motion.h) takes the
  // view's place (the robot base frame, z up) until ended with null, or by setMesh, setPlan, clearPlan or clear;
  // the camera frames the arm and the extruder once, then stays while the position changes. Shows the first
  // position.
  void setCellMotion(std::shared_ptr<const CellMotion> motion);
  [[nodiscard]] bool hasCellMotion() const;
  // The arm, platform and part at `position` (clamped to the motion's).
  void setCellPosition(CellPosition position);
  [[nodiscard]] CellPosition cellPosition() const;
  // Where the cell view draws things now (base frame, mm): the marker of the toolpath point the move shown
  // ends at (on the part as posed), and the centre of the step's part as posed.
  [[nodiscard]] core::Vec3 cellToolpathPointDrawn() const;
  [[nodiscard]] core::Vec3 cellPartCentreDrawn() const;
  // The warning text drawn for the step shown (empty: none), and whether its red marker is drawn.
  [[nodiscard]] QString cellWarningShown() const;
  [[nodiscard]] bool cellWarningMarkerShown() const;
  // The reach map "Find extruder position" made (ui/viewer/reach_scene.h), drawn with the cell while the cell view
  // is shown (ignored otherwise; ended with it): every sampled nozzle position in its score's colour, the best
  // ringed, the colour bar titled `colourBarTitle`; the camera frames the whole map with the cell. Null clears.
  void setCellReachMap(std::shared_ptr<const CellReachMap> map, const QString& colourBarTitle);
  // The map's points drawn now (0: none), and whether its colour bar is.
  [[nodiscard]] int cellReachPointsShown() const;
  [[nodiscard]] bool cellReachColourBarShown() const;
  // The cell view's colours: the part (lit), the nozzle, the toolpath point, the toolpath and the warning (unlit,
  // exact).
  [[nodiscard]] static QColor cellPartColor();
  [[nodiscard]] static QColor cellNozzleColor();
  [[nodiscard]] static QColor cellToolpathPointColor();
  [[nodiscard]] static QColor cellToolpathColor();
  [[nodiscard]] static QColor cellWarningColor();

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
  // The G-code preview's travel moves (extrusions are in their step's region colour).
  [[nodiscard]] static QColor gcodeTravelColor();

  QSize sizeHint() const override;

 signals:
  // Emitted after each rendered frame.
  void frameRendered();
  // Measuring began or ended (setMeasuring, Esc, a new scene).
  void measuringChanged(bool on);
  // A point was picked (or the measurement cleared): measurement() has it.
  void measurementChanged();
  // Platform picking (setPlatformPicking): a click hit the platform at `point` (mm).
  void platformPointPicked(const multidir::core::Vec3& point);
  // Platform picking: a click missed the platform.
  void platformPickMissed(multidir::ui::PlatformHitKind reason);
  // Platform picking ended by Esc, a new model or clear().
  void platformPickCancelled();
  // Outside platform picking, with the clipping planes shown: a left click without movement on the disc of
  // clipping plane `plane` (0-based, clipping order; the disc nearest the camera where several overlap).
  // A click on no disc emits nothing.
  void clippingPlaneClicked(int plane);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void resizeGL(int width, int height) override;
  bool event(QEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;

 private:
  void releaseGraphics();
  void endPickingOnNewScene();
  void showMeasurement();
  void placeSupports();

  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::ui
