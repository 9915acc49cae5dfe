#include "ui/slicing/slice_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include "ui/project/dialog_folders.h"

namespace multidir::ui {
namespace {

// The built-in printers' names (resources/printers/*.ini, "multidir.name"), marked for translation; a printer
// profile of the user's own keeps the name it was given.
const char* const kBuiltinPrinterNames[] = {
    QT_TRANSLATE_NOOP("multidir::ui::SliceDialog", "Klipper with tilt and rotation steppers, 0.4 mm nozzle"),
    QT_TRANSLATE_NOOP("multidir::ui::SliceDialog", "Klipper with a rotary A axis, 0.4 mm nozzle"),
    QT_TRANSLATE_NOOP("multidir::ui::SliceDialog", "Generic Marlin 220x220, 0.4 mm nozzle (platform over Modbus)"),
    QT_TRANSLATE_NOOP("multidir::ui::SliceDialog",
                      "Open5x-like Prusa i3, RepRapFirmware U tilt + V rotation, 0.4 mm nozzle"),
    QT_TRANSLATE_NOOP("multidir::ui::SliceDialog", "Robot arm tilting the platform, printer head moving, 0.8 mm nozzle"),
    QT_TRANSLATE_NOOP("multidir::ui::SliceDialog", "UR5 robot cell, fixed 0.8 mm extruder"),
};

QString printerNameText(const std::string& name) {
  for (const char* builtin : kBuiltinPrinterNames)
    if (name == builtin) return QCoreApplication::translate("multidir::ui::SliceDialog", builtin);
  return QString::fromStdString(name);
}

const QString kGroup = QStringLiteral("slicing");
constexpr int kLoadIniRole = Qt::UserRole + 1;

std::string localPath(const QString& path) { return QFile::encodeName(path).toStdString(); }

QString defaultPrinterFor(core::MachineKind machine) {
  switch (machine) {
    case core::MachineKind::RotaryPlatform: return QStringLiteral("klipper-rotary");
    case core::MachineKind::TiltRotate: return QStringLiteral("robot-0.8");
    case core::MachineKind::ThreeAxis:
    case core::MachineKind::Apart: break;
  }
  return QStringLiteral("marlin-220");
}

// Why a printer cannot print a plan for `machine` (what sliceJob would refuse), or empty when it can.
QString unsuitableReason(const slicing::PrinterProfile& profile, core::MachineKind machine) {
  if (machine == core::MachineKind::Apart)
    return SliceDialog::tr("A plan printed apart is sliced part by part on plates: use Search > Print apart... "
                           "or 'multidir apart' (docs/apart.md).");
  switch (profile.platform) {
    case slicing::PlatformDrive::None:
      if (machine != core::MachineKind::ThreeAxis)
        return SliceDialog::tr("This printer cannot turn the part: it prints one-step (3-DOF) plans only.");
      break;
    case slicing::PlatformDrive::FirmwareAxis:
      if (machine == core::MachineKind::TiltRotate)
        return SliceDialog::tr("This printer turns the platform about one axis: it cannot print a 5-DOF plan. "
                               "Choose a printer with two firmware axes or a robot arm.");
      break;
    case slicing::PlatformDrive::Modbus:
    case slicing::PlatformDrive::FirmwareTwoAxis:
      break;
  }
  return {};
}

QString platformText(const slicing::PrinterProfile& profile) {
  switch (profile.platform) {
    case slicing::PlatformDrive::FirmwareAxis:
      return SliceDialog::tr("The firmware turns the platform (axis %1): one program, job.gcode, with every step.")
          .arg(QString::fromStdString(profile.rotaryAxis));
    case slicing::PlatformDrive::Modbus:
      return SliceDialog::tr("MultiDir turns the platform over Modbus (Hardware dock): one program per step.");
    case slicing::PlatformDrive::FirmwareTwoAxis:
      return SliceDialog::tr("The firmware tilts (axis %1) and rotates (axis %2) the platform: one program, job.gcode, "
                             "with every step and the turns between them.")
          .arg(QString::fromStdString(profile.twoAxis.tilt.letter), QString::fromStdString(profile.twoAxis.rotation.letter));
    case slicing::PlatformDrive::None:
      break;
  }
  return SliceDialog::tr("An ordinary printer: it cannot turn the part, so it prints one-step plans only.");
}

}  // namespace

SliceDialog::SliceDialog(core::MachineKind machine, QWidget* parent) : QDialog(parent), m_machine(machine) {
  setObjectName(QStringLiteral("sliceDialog"));
  setWindowTitle(tr("Slice the Plan"));
  m_printer = new QComboBox(this);
  m_printer->setObjectName(QStringLiteral("slicePrinter"));
  for (const std::string& name : slicing::builtinPrinterNames()) {
    const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(name);
    const QString id = QString::fromStdString(name);
    m_printer->addItem(profile ? printerNameText(profile->name) : id, id);
    // A printer that cannot print this plan is listed but cannot be chosen, and says why.
    const QString reason = profile ? unsuitableReason(*profile, machine) : QString();
    if (!reason.isEmpty()) {
      if (auto* model = qobject_cast<QStandardItemModel*>(m_printer->model()))
        model->item(m_printer->count() - 1)->setEnabled(false);
      m_printer->setItemData(m_printer->count() - 1, reason, Qt::ToolTipRole);
    }
  }
  m_printer->addItem(tr("Load a PrusaSlicer .ini..."));
  m_printer->setItemData(m_printer->count() - 1, true, kLoadIniRole);
  m_printerInfo = new QLabel(this);
  m_printerInfo->setObjectName(QStringLiteral("slicePrinterInfo"));
  m_printerInfo->setWordWrap(true);

  m_dialect = new QComboBox(this);
  m_dialect->setObjectName(QStringLiteral("sliceDialect"));
  for (const slicing::Dialect d : {slicing::Dialect::Klipper, slicing::Dialect::Marlin, slicing::Dialect::RepRapFirmware})
    m_dialect->addItem(QString::fromLatin1(slicing::dialectName(d)), static_cast<int>(d));
  m_dialect->setToolTip(tr("How the firmware turns the platform: Klipper's MANUAL_STEPPER, or G1 A on Marlin "
                           "and RepRapFirmware"));

  m_settings = new QLineEdit(this);
  m_settings->setObjectName(QStringLiteral("sliceSettings"));
  m_settings->setPlaceholderText(tr("layer_height=0.3 fill_density=10%"));
  m_settings->setToolTip(tr("PrusaSlicer settings over the profile's, KEY=VALUE separated by spaces"));
  m_comparison = new QCheckBox(tr("Also slice the whole model along up with the slicer's supports (comparison)"), this);
  m_comparison->setObjectName(QStringLiteral("sliceComparison"));
  m_slicer = new QLineEdit(this);
  m_slicer->setObjectName(QStringLiteral("slicerProgram"));
  m_slicer->setToolTip(tr("The prusa-slicer program: a name found on PATH, or a full path"));
  m_problem = new QLabel(this);
  m_problem->setObjectName(QStringLiteral("sliceDialogProblem"));
  m_problem->setWordWrap(true);
  m_problem->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_problem->hide();

  auto* form = new QFormLayout;
  form->addRow(tr("Printer:"), m_printer);
  form->addRow(QString(), m_printerInfo);
  form->addRow(tr("Dialect:"), m_dialect);
  form->addRow(tr("Slicer settings:"), m_settings);
  form->addRow(QString(), m_comparison);
  form->addRow(tr("Slicer program:"), m_slicer);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Slice"));
  connect(buttons, &QDialogButtonBox::accepted, this, &SliceDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &SliceDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(m_problem);
  layout->addWidget(buttons);

  QSettings settings;
  settings.beginGroup(kGroup);
  m_settings->setText(settings.value(QStringLiteral("settings")).toString());
  m_comparison->setChecked(settings.value(QStringLiteral("comparison"), true).toBool());
  m_slicer->setText(settings.value(QStringLiteral("slicerProgram"), QStringLiteral("prusa-slicer")).toString());
  const QString printer = settings.value(QStringLiteral("printer"), defaultPrinterFor(machine)).toString();
  const QString dialect = settings.value(QStringLiteral("dialect")).toString();
  settings.endGroup();
  connect(m_printer, QOverload<int>::of(&QComboBox::activated), this, &SliceDialog::onPrinterChosen);
  // The printer used last, when it suits this plan (a Klipper platform remembered from a 4-DOF plan cannot
  // print a 5-DOF one), else the one that suits the plan's machine.
  if (!selectPrinter(printer)) {
    selectPrinter(defaultPrinterFor(machine));
    m_problem->hide();
  }
  const int remembered = m_dialect->findText(dialect);
  if (remembered >= 0 && m_dialect->isEnabled()) m_dialect->setCurrentIndex(remembered);
}

bool SliceDialog::selectPrinter(const QString& pathOrName) {
  int index = m_printer->findData(pathOrName);
  const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(localPath(pathOrName));
  if (!profile) {
    m_problem->setText(tr("Cannot use the printer profile: %1").arg(QString::fromStdString(profile.error().describe())));
    m_problem->show();
    return false;
  }
  if (const QString reason = unsuitableReason(*profile, m_machine); !reason.isEmpty()) {
    m_problem->setText(tr("%1: %2").arg(QString::fromStdString(profile->name), reason));
    m_problem->show();
    return false;
  }
  if (index < 0) {
    m_printer->insertItem(m_printer->count() - 1, printerNameText(profile->name), pathOrName);
    m_printer->setItemData(m_printer->count() - 2, pathOrName, Qt::ToolTipRole);
    index = m_printer->count() - 2;
  }
  {
    const QSignalBlocker block(m_printer);
    m_printer->setCurrentIndex(index);
  }
  m_lastPrinter = index;
  m_profile = *profile;
  m_printerInfo->setText(platformText(*profile));
  const bool firmwareAxis = profile->platform == slicing::PlatformDrive::FirmwareAxis ||
                            profile->platform == slicing::PlatformDrive::FirmwareTwoAxis;
  m_dialect->setEnabled(firmwareAxis);
  m_dialect->setCurrentIndex(m_dialect->findData(static_cast<int>(profile->dialect)));
  m_problem->hide();
  return true;
}

void SliceDialog::onPrinterChosen(int index) {
  if (m_printer->itemData(index, kLoadIniRole).toBool()) {
    loadIni();
    return;
  }
  if (!selectPrinter(m_printer->itemData(index).toString())) {
    const QSignalBlocker block(m_printer);
    m_printer->setCurrentIndex(m_lastPrinter);
  }
}

void SliceDialog::loadIni() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Load a PrusaSlicer Printer Profile"),
                                                    rememberedDialogFolder(FileKind::MachineProfile),
                                                    tr("PrusaSlicer profiles (*.ini);;All files (*)"));
  if (path.isEmpty() || !selectPrinter(path)) {
    const QSignalBlocker block(m_printer);
    m_printer->setCurrentIndex(m_lastPrinter);
    return;
  }
  rememberDialogFolder(FileKind::MachineProfile, path);
}

void SliceDialog::setSettingsText(const QString& text) { m_settings->setText(text); }
void SliceDialog::setSlicerProgram(const QString& program) { m_slicer->setText(program); }
void SliceDialog::setComparison(bool on) { m_comparison->setChecked(on); }

std::optional<SliceChoice> SliceDialog::choice() {
  if (!m_profile) {
    m_problem->setText(tr("Choose a printer profile."));
    m_problem->show();
    return std::nullopt;
  }
  const auto settings = slicing::parseSettingAssignments(m_settings->text().toStdString());
  if (!settings) {
    m_problem->setText(tr("Slicer settings: %1").arg(QString::fromStdString(settings.error().message)));
    m_problem->show();
    return std::nullopt;
  }
  SliceChoice choice;
  choice.profile = *m_profile;
  choice.options.settings = *settings;
  choice.options.fixedDirection = m_comparison->isChecked();
  if (m_dialect->isEnabled()) choice.options.dialect = static_cast<slicing::Dialect>(m_dialect->currentData().toInt());
  const QString program = m_slicer->text().trimmed();
  choice.options.slicerExecutable = program.isEmpty() ? std::string("prusa-slicer") : localPath(program);
  return choice;
}

void SliceDialog::accept() {
  if (!choice()) return;
  remember();
  QDialog::accept();
}

void SliceDialog::remember() const {
  QSettings settings;
  settings.beginGroup(kGroup);
  settings.setValue(QStringLiteral("printer"), m_printer->currentData());
  settings.setValue(QStringLiteral("dialect"), m_dialect->currentText());
  settings.setValue(QStringLiteral("settings"), m_settings->text());
  settings.setValue(QStringLiteral("comparison"), m_comparison->isChecked());
  settings.setValue(QStringLiteral("slicerProgram"), m_slicer->text());
  settings.endGroup();
}

}  // namespace multidir::ui
