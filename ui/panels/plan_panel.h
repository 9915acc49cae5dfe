#pragma once
// The Plan panel: the regions of the current plan as a table that doubles as the colour legend (index,
// volume, risky area, printing direction, machine angles, support volume and what it holds up), view options (printing
// directions, clipping planes, supports, exploded view) and the sequence stepper (show regions 1..i, optionally turning the view as the
// machine turns the part).
//
// The panel only shows and collects; MainWindow passes its settings on to the viewer.
#include <QWidget>

#include <vector>

#include "multidir/core/search/decomposition.h"
#include "multidir/core/supports/support_set.h"

class QCheckBox;
class QLabel;
class QSlider;
class QSpinBox;
class QTableWidget;
class QToolButton;

namespace multidir::ui {

class PlanPanel : public QWidget {
  Q_OBJECT

 public:
  explicit PlanPanel(QWidget* parent = nullptr);

  // Shows `plan`'s regions; `kind` chooses which machine angles are listed. Resets the stepper to show
  // every region and the exploded view to 0.
  void setPlan(const core::Decomposition& plan, core::MachineKind kind);
  // The same with the plan's supports (one set per region in printing order, or empty: none grown). The
  // Supports box is enabled only when some set has struts.
  void setPlan(const core::Decomposition& plan, core::MachineKind kind, const std::vector<core::SupportSet>& supports);
  void clearPlan();

  [[nodiscard]] QTableWidget* regionTable() const { return m_table; }
  [[nodiscard]] int shownRegions() const;
  void setShownRegions(int count);
  // Exploded view distance in mm for the slider's position.
  [[nodiscard]] double explodeDistanceMm() const;
  void setExplodeFraction(double fraction);  // 0..1 of the slider
  void setClippingPlanesShown(bool shown);
  void setSupportsShown(bool shown);
  // The table's column with each region's support volume, and the one that says what it holds up.
  static constexpr int kSupportVolumeColumn = 5;
  static constexpr int kSupportCauseColumn = 6;
  // Scales the exploded view's slider: at its end, regions move this far apart (per level).
  void setModelSize(double sizeMm);

 signals:
  void directionsVisibleChanged(bool visible);
  void clippingPlanesVisibleChanged(bool visible);
  void supportsVisibleChanged(bool visible);
  void explodeDistanceChanged(double distanceMm);
  void shownRegionsChanged(int count);
  void turnWithMachineChanged(bool turn);

 private:
  void updateStepLabel();

  QTableWidget* m_table = nullptr;
  QCheckBox* m_directions = nullptr;
  QCheckBox* m_planes = nullptr;
  QCheckBox* m_supports = nullptr;
  QCheckBox* m_turn = nullptr;
  QSlider* m_explode = nullptr;
  QSpinBox* m_step = nullptr;
  QToolButton* m_previous = nullptr;
  QToolButton* m_next = nullptr;
  QLabel* m_summary = nullptr;
  QLabel* m_stepLabel = nullptr;
  double m_modelSizeMm = 100.0;
  int m_regions = 0;
};

}  // namespace multidir::ui
