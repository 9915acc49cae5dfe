#pragma once
// The Print apart view (docs/apart.md, "The studio"): the plan shown printed apart on an ordinary printer. The
// printer (the shipped profiles), the dowel options with their defaults, Run (off the GUI thread, progress,
// Cancel); then the parts exploded along their joints with the dowels, each part in its colour with its number,
// or one plate with its parts laid out; the slicer's estimates per plate, for all plates and for the model in
// one piece with supports; and Export, which writes every file to a folder the user picks.
//
// What it shows is the document's (StudioDocument::apartPrint): the panel keeps no copy, so when the plan or the
// model changes the document drops the result and the view empties with it.
#include <QString>
#include <QWidget>

#include "multidir/apart/print_apart.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace multidir::ui {

class ApartJobRunner;
class MeshViewerWidget;
class StudioDocument;

class ApartPanel : public QWidget {
  Q_OBJECT

 public:
  ApartPanel(StudioDocument& document, QWidget* parent = nullptr);

  // Estimates table rows carry their kind in Qt::UserRole of column 0; column 1 the seconds, column 3 the
  // support cm^3 in Qt::UserRole.
  enum class RowKind { Plate = 1, AllPlates = 2, OnePiece = 3 };
  static constexpr int kTimeColumn = 1;
  static constexpr int kSupportColumn = 3;

  // What the Run button would print apart with: the printer chosen and the dowel options.
  [[nodiscard]] apart::PrintApartOptions options() const;
  // Starts printing the plan shown apart; false (the reason shown) when it cannot start.
  bool run();
  void cancel();
  // Writes every file of the result shown into `folder` (Export without its dialog); false with the reason
  // shown when there is nothing to export or it cannot be written.
  bool exportTo(const QString& folder);

  [[nodiscard]] QComboBox* printerBox() const { return m_printer; }
  [[nodiscard]] QCheckBox* sliceBox() const { return m_slice; }
  [[nodiscard]] QPushButton* runButton() const { return m_run; }
  [[nodiscard]] QPushButton* cancelButton() const { return m_cancel; }
  [[nodiscard]] QPushButton* exportButton() const { return m_export; }
  // "Parts exploded", then "Plate 1", "Plate 2", ...
  [[nodiscard]] QComboBox* viewBox() const { return m_view; }
  [[nodiscard]] MeshViewerWidget* viewer() const { return m_viewer; }
  [[nodiscard]] QTableWidget* estimatesTable() const { return m_table; }
  [[nodiscard]] QLabel* messageLabel() const { return m_message; }
  [[nodiscard]] ApartJobRunner* runner() const { return m_runner; }

 private:
  void showDocument();  // the document's plan and result, as they are now
  void showView(int index);
  void fillEstimates();
  void showMessage(const QString& text, bool error);
  void exportFromDialog();

  StudioDocument& m_document;
  ApartJobRunner* m_runner;
  QComboBox* m_printer = nullptr;
  QCheckBox* m_slice = nullptr;
  QDoubleSpinBox* m_minDiameter = nullptr;
  QDoubleSpinBox* m_maxDiameter = nullptr;
  QDoubleSpinBox* m_radialClearance = nullptr;
  QDoubleSpinBox* m_depthClearance = nullptr;
  QDoubleSpinBox* m_minWall = nullptr;
  QSpinBox* m_perJoint = nullptr;
  QPushButton* m_run = nullptr;
  QPushButton* m_cancel = nullptr;
  QProgressBar* m_progress = nullptr;
  QLabel* m_stage = nullptr;
  QLabel* m_message = nullptr;
  QLabel* m_summary = nullptr;
  QComboBox* m_view = nullptr;
  MeshViewerWidget* m_viewer = nullptr;
  QTableWidget* m_table = nullptr;
  QPushButton* m_export = nullptr;
};

}  // namespace multidir::ui
