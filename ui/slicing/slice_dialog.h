#pragma once
// The Slice dialog: which printer (the shipped profiles, or a PrusaSlicer .ini the user loads), the dialect
// when the printer turns its platform by a firmware axis, extra slicer settings (as `multidir slice --set`),
// whether to slice the fixed-direction comparison, and the slicer program. The choices are remembered
// (QSettings group "slicing") for the next time.
#include <QDialog>
#include <QString>
#include <optional>

#include "multidir/core/search/machine.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/slice_job.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;

namespace multidir::ui {

// What the dialog collected: a loaded profile and the options for slicing::slicePlan.
struct SliceChoice {
  slicing::PrinterProfile profile;
  slicing::SliceJobOptions options;
};

class SliceDialog : public QDialog {
  Q_OBJECT

 public:
  // `machine`: the plan's machine; the printer first offered suits it (firmware axis for a 4-DOF platform,
  // the robot for 5-DOF, an ordinary printer for 3-DOF) unless the user chose another one before.
  explicit SliceDialog(core::MachineKind machine, QWidget* parent = nullptr);

  // The choice, read when accepted: nullopt (with the reason shown in the dialog) when the profile cannot
  // be loaded or the settings are not KEY=VALUE.
  [[nodiscard]] std::optional<SliceChoice> choice();

  // Selects the entry for `pathOrName` (a shipped name, or a .ini path, added when new); false when it cannot
  // be loaded (the reason is shown in the dialog).
  bool selectPrinter(const QString& pathOrName);
  void setSettingsText(const QString& text);
  void setSlicerProgram(const QString& program);
  void setComparison(bool on);

  void accept() override;

 private:
  void onPrinterChosen(int index);
  void loadIni();
  void remember() const;

  QComboBox* m_printer = nullptr;
  QLabel* m_printerInfo = nullptr;
  QComboBox* m_dialect = nullptr;
  QLineEdit* m_settings = nullptr;
  QCheckBox* m_comparison = nullptr;
  QLineEdit* m_slicer = nullptr;
  QLabel* m_problem = nullptr;
  int m_lastPrinter = 0;
  core::MachineKind m_machine = core::MachineKind::TiltRotate;  // the plan's
  std::optional<slicing::PrinterProfile> m_profile;  // of the entry selected
};

}  // namespace multidir::ui
