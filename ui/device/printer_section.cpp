#include "ui/device/printer_section.h"

#include <QDateTime>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>
#include <filesystem>
#include <utility>

#include "multidir/slicing/estimates.h"
#include "ui/device/device_reading.h"
#include "ui/device/job_eta.h"
#include "ui/device/print_run_driver.h"
#include "ui/device/printer_link_owner.h"

namespace multidir::ui {
namespace {

constexpr const char* kUrlKey = "printer/url";

QLabel* valueLabel(QWidget* parent, const QString& name) {
  auto* label = new QLabel(parent);
  label->setObjectName(name);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label->setWordWrap(true);
  return label;
}

QPushButton* button(QWidget* parent, const QString& name, const QString& text, const QString& tip) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  b->setToolTip(tip);
  return b;
}

QString heaterText(const hardware::HeaterReading& heater) {
  const QLocale locale;
  if (heater.targetC <= 0.0)
    return PrinterSection::tr("%1 °C (off)").arg(locale.toString(heater.actualC, 'f', 1));
  return PrinterSection::tr("%1 / %2 °C")
      .arg(locale.toString(heater.actualC, 'f', 1), locale.toString(heater.targetC, 'f', 1));
}

QString jobStateText(hardware::PrinterJobState state) {
  switch (state) {
    case hardware::PrinterJobState::Unknown:
      return PrinterSection::tr("unknown");
    case hardware::PrinterJobState::Standby:
      return PrinterSection::tr("standby (no job)");
    case hardware::PrinterJobState::Printing:
      return PrinterSection::tr("printing");
    case hardware::PrinterJobState::Paused:
      return PrinterSection::tr("paused");
    case hardware::PrinterJobState::Complete:
      return PrinterSection::tr("complete");
    case hardware::PrinterJobState::Cancelled:
      return PrinterSection::tr("cancelled");
    case hardware::PrinterJobState::Error:
      return PrinterSection::tr("error");
  }
  return {};
}

bool firmwareReady(const hardware::PrinterStatus& s) { return s.firmwareState == "ready"; }

}  // namespace

PrinterSection::PrinterSection(PrinterLinkOwner* printer, const PrintRunDriver* run, QWidget* parent)
    : QGroupBox(tr("Printer"), parent), m_printer(printer), m_run(run) {
  setObjectName(QStringLiteral("printerSection"));
  m_url = new QLineEdit(QSettings().value(QString::fromLatin1(kUrlKey)).toString(), this);
  m_url->setObjectName(QStringLiteral("printerUrl"));
  m_url->setPlaceholderText(tr("http://192.168.0.20:7125"));
  m_url->setToolTip(tr("The printer's address: Moonraker (Klipper) as http://HOST:PORT or HOST:PORT (port 7125)."));
  m_apiKey = new QLineEdit(this);
  m_apiKey->setObjectName(QStringLiteral("printerApiKey"));
  m_apiKey->setEchoMode(QLineEdit::Password);
  m_apiKey->setPlaceholderText(tr("none"));
  m_apiKey->setToolTip(tr("Only when the printer asks for one (Moonraker's [authorization]). Not remembered."));
  m_connect = button(this, QStringLiteral("printerConnectButton"), tr("Connect printer"),
                     tr("Connects to the printer; a print run then sends each region's G-code to it."));
  m_disconnect = button(this, QStringLiteral("printerDisconnectButton"), tr("Disconnect printer"),
                        tr("Closes the link without commanding the printer: a job on it goes on."));
  m_clearStop = button(this, QStringLiteral("printerClearStopButton"), tr("Clear printer E-STOP"),
                       tr("Allows jobs again once the printer confirmed the emergency stop. A printer whose "
                          "firmware the stop shut down also needs Restart firmware."));
  m_restartFirmware =
      button(this, QStringLiteral("printerRestartFirmwareButton"), tr("Restart firmware"),
             tr("After an emergency stop: Klipper's FIRMWARE_RESTART (through Moonraker), or OctoPrint connecting "
                "to the printer again (which resets its board). Asks first."));
  m_banner = valueLabel(this, QStringLiteral("printerBanner"));
  m_banner->hide();
  m_state = valueLabel(this, QStringLiteral("printerStateValue"));
  m_job = valueLabel(this, QStringLiteral("printerJobValue"));
  m_firmware = valueLabel(this, QStringLiteral("printerFirmwareValue"));
  m_says = valueLabel(this, QStringLiteral("printerSaysValue"));
  m_extruder = valueLabel(this, QStringLiteral("printerExtruderValue"));
  m_bed = valueLabel(this, QStringLiteral("printerBedValue"));
  m_file = valueLabel(this, QStringLiteral("printerFileValue"));
  m_progress = valueLabel(this, QStringLiteral("printerProgressValue"));
  m_eta = valueLabel(this, QStringLiteral("printerEtaValue"));
  m_problem = valueLabel(this, QStringLiteral("printerProblemValue"));
  m_message = valueLabel(this, QStringLiteral("printerMessage"));

  auto* address = new QFormLayout;
  address->addRow(tr("Address:"), m_url);
  address->addRow(tr("API key:"), m_apiKey);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_connect);
  buttons->addWidget(m_disconnect);
  auto* values = new QFormLayout;
  values->addRow(tr("State:"), m_state);
  values->addRow(tr("Job:"), m_job);
  values->addRow(tr("Firmware:"), m_firmware);
  values->addRow(tr("Printer says:"), m_says);
  values->addRow(tr("Extruder:"), m_extruder);
  values->addRow(tr("Bed:"), m_bed);
  values->addRow(tr("File:"), m_file);
  values->addRow(tr("Progress:"), m_progress);
  values->addRow(tr("Job time left:"), m_eta);
  values->addRow(tr("Last problem:"), m_problem);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(address);
  layout->addLayout(buttons);
  layout->addWidget(m_banner);
  layout->addLayout(values);
  auto* stopButtons = new QHBoxLayout;
  stopButtons->addWidget(m_clearStop);
  stopButtons->addWidget(m_restartFirmware);
  layout->addLayout(stopButtons);
  layout->addWidget(m_message);

  connect(m_connect, &QPushButton::clicked, this, &PrinterSection::connectPrinter);
  connect(m_disconnect, &QPushButton::clicked, this, &PrinterSection::disconnectPrinter);
  connect(m_clearStop, &QPushButton::clicked, this, &PrinterSection::clearStop);
  connect(m_restartFirmware, &QPushButton::clicked, this, &PrinterSection::askToRestartFirmware);
  connect(m_printer, &PrinterLinkOwner::firmwareRestartFinished, this, [this](const QString& problem) {
    if (problem.isEmpty())
      setMessage(tr("%1 is restarting its firmware; the Firmware line shows \"ready\" once it is back.")
                     .arg(m_printer->printerName()),
                 false, true);
    else
      setMessage(tr("Restart firmware refused: %1").arg(problem), true);
  });
  connect(m_printer, &PrinterLinkOwner::statusChanged, this, &PrinterSection::refresh);
  connect(m_printer, &PrinterLinkOwner::connectFinished, this, [this](bool connected, const QString& problem) {
    if (connected)
      setMessage(tr("Connected to %1.").arg(m_printer->printerName()), false);
    else
      setMessage(problem, true);
  });
  connect(m_printer, &PrinterLinkOwner::commandFailed, this,
          [this](const QString&, const QString& problem) { setMessage(problem, true); });
  refresh();
}

void PrinterSection::setRunEstimates(std::vector<double> seconds) {
  m_estimates = std::move(seconds);
  refresh();
}

QString PrinterSection::bannerText() const { return m_banner->isHidden() ? QString() : m_banner->text(); }

QString PrinterSection::linkLostText() const {
  if (!m_printer->isOpen() || !m_printer->staleSince()) return {};
  return tr("The link to %1 was lost at %2: its values are not the printer's any more, and it may still be "
            "printing. MultiDir keeps trying.")
      .arg(m_printer->printerName(), DeviceReading::clockTime(*m_printer->staleSince()));
}

QString PrinterSection::messageText() const { return m_message->text(); }

QString PrinterSection::url() const { return m_url->text(); }

void PrinterSection::setUrl(const QString& url) { m_url->setText(url); }

void PrinterSection::setApiKey(const QString& key) { m_apiKey->setText(key); }

void PrinterSection::connectPrinter() {
  const core::Status started = m_printer->connectPrinter(m_url->text(), m_apiKey->text());
  if (!started.ok()) {
    setMessage(tr("Cannot connect to the printer: %1").arg(QString::fromStdString(started.error().message)), true);
    return;
  }
  QSettings().setValue(QString::fromLatin1(kUrlKey), m_url->text().trimmed());
  setMessage(tr("Connecting to %1…").arg(m_printer->printerName()), false);
}

void PrinterSection::disconnectPrinter() {
  m_printer->disconnectPrinter();
  setMessage(tr("Printer disconnected."), false);
}

void PrinterSection::clearStop() {
  const core::Status cleared = m_printer->clearStop();
  if (cleared.ok() && firmwareReady(m_printer->status()))
    setMessage(tr("Printer E-STOP cleared."), false);
  else if (cleared.ok())
    setMessage(tr("Printer E-STOP cleared. Its firmware is %1: it needs Restart firmware (Klipper's "
                  "FIRMWARE_RESTART) before its next job.")
                   .arg(QString::fromStdString(m_printer->status().firmwareState)),
               false, true);
  else
    setMessage(tr("Clear printer E-STOP refused: %1").arg(QString::fromStdString(cleared.error().message)), true);
}

void PrinterSection::askToRestartFirmware() {
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Restart Printer Firmware"),
                              tr("Restart the firmware of %1?").arg(m_printer->printerName()), QMessageBox::NoButton,
                              this);
  box->setObjectName(QStringLiteral("restartFirmwareBox"));
  box->setInformativeText(tr("The firmware takes the heaters and motors back: make sure whatever caused the "
                             "emergency stop is fixed and nothing is in the printer's way."));
  QPushButton* restart = box->addButton(tr("&Restart Firmware"), QMessageBox::AcceptRole);
  restart->setObjectName(QStringLiteral("restartFirmwareConfirm"));
  box->addButton(QMessageBox::Cancel);
  box->setDefaultButton(QMessageBox::Cancel);
  box->setWindowModality(Qt::WindowModal);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [this, box, restart] {
    if (box->clickedButton() != restart) return;
    setMessage(tr("Restarting the firmware of %1…").arg(m_printer->printerName()), false, true);
    m_printer->restartFirmware();
  });
  box->open();
}

void PrinterSection::setMessage(const QString& text, bool error, bool awaitsReady) {
  m_messageAwaitsReady = awaitsReady;
  m_message->setText(text);
  m_message->setStyleSheet(error ? QString::fromLatin1(DeviceReading::kFaultStyle) : QString());
}

QString PrinterSection::progressText(double* stepProgress) const {
  *stepProgress = 0.0;
  const hardware::PrinterStatus& s = m_printer->status();
  const bool jobShown = s.state == hardware::PrinterJobState::Printing ||
                        s.state == hardware::PrinterJobState::Paused || s.state == hardware::PrinterJobState::Complete;
  const QString percent = QLocale().toString(100.0 * s.progress, 'f', 0) + QStringLiteral(" %");
  const hardware::PrintStep* step = m_run->currentPrintStep();
  if (m_run->isActive() && m_run->currentStepUsesPrinter() && step != nullptr) {
    const std::string remote = std::filesystem::path(step->gcodePath).filename().string();
    const bool ours = jobShown && s.currentFile == remote;
    if (ours && m_run->state() == hardware::PrintRunState::Printing) *stepProgress = s.progress;
    return tr("step %1 of %2: %3")
        .arg(m_run->currentStep() + 1)
        .arg(m_run->stepCount())
        .arg(ours ? percent : tr("not started"));
  }
  if (jobShown && !s.currentFile.empty())
    return tr("%1 of %2 (not a step of this run)").arg(percent, QString::fromStdString(s.currentFile));
  return QStringLiteral("—");
}

QString PrinterSection::etaText(double stepProgress) const {
  if (!m_run->hasRun()) return QStringLiteral("—");
  if (m_run->state() == hardware::PrintRunState::Completed) return tr("none: every step is printed");
  if (!m_run->isActive()) return QStringLiteral("—");
  const std::optional<double> left = remainingJobSeconds(m_estimates, m_run->currentStep(), stepProgress);
  if (!left) return tr("no estimate: slice the plan before starting the run");
  const QDateTime done = QDateTime::currentDateTime().addSecs(static_cast<qint64>(*left));
  return tr("%1 of printing (done about %2; platform moves not counted)")
      .arg(QString::fromStdString(slicing::durationText(*left)), done.toString(QStringLiteral("HH:mm")));
}

void PrinterSection::refresh() {
  const bool open = m_printer->isOpen();
  const hardware::PrinterStatus& s = m_printer->status();
  const bool read = m_printer->hasRead();
  const std::optional<QDateTime>& stale = m_printer->staleSince();

  if (!open)
    m_state->setText(tr("Disconnected"));
  else if (!read && !s.lastError.empty())
    m_state->setText(tr("Not reachable; MultiDir keeps trying…"));
  else if (!read)
    m_state->setText(tr("Connecting…"));
  else if (stale)
    m_state->setText(tr("Link lost at %1; MultiDir keeps trying…").arg(DeviceReading::clockTime(*stale)));
  else
    m_state->setText(tr("Connected to %1").arg(m_printer->printerName()));

  double stepProgress = 0.0;
  const QString progress = progressText(&stepProgress);
  QString firmware = QString::fromStdString(s.firmwareState);
  const std::pair<QLabel*, QString> fields[] = {
      {m_job, jobStateText(s.state)},
      {m_firmware, firmware.isEmpty() ? tr("unknown") : firmware},
      {m_says, s.message.empty() ? tr("nothing") : QString::fromStdString(s.message)},
      {m_extruder, heaterText(s.extruder)},
      {m_bed, heaterText(s.bed)},
      {m_file, s.currentFile.empty() ? tr("none") : QString::fromStdString(s.currentFile)},
      {m_progress, progress}};
  for (const auto& [label, value] : fields) DeviceReading::show(label, value, open, read, stale);
  if (open && read && !stale) {
    if (!firmwareReady(s)) m_firmware->setStyleSheet(QString::fromLatin1(DeviceReading::kFaultStyle));
    if (!firmwareReady(s) || s.state == hardware::PrinterJobState::Error)
      m_says->setStyleSheet(QString::fromLatin1(DeviceReading::kFaultStyle));
  }
  // With the link lost the printer's progress is not known: neither live nor the whole step's estimate.
  if (open && stale && m_run->isActive())
    m_eta->setText(tr("unknown since %1: the printer's link is lost").arg(DeviceReading::clockTime(*stale)));
  else
    m_eta->setText(etaText(stepProgress));
  m_eta->setStyleSheet(open && stale && m_run->isActive() ? QString::fromLatin1(DeviceReading::kStaleStyle) : QString());
  m_problem->setText(!open || s.lastError.empty() ? tr("none") : QString::fromStdString(s.lastError));
  m_problem->setStyleSheet(open && !s.lastError.empty() ? QString::fromLatin1(DeviceReading::kFaultStyle) : QString());

  m_url->setEnabled(!open);
  m_apiKey->setEnabled(!open);
  m_connect->setEnabled(!open);
  m_disconnect->setEnabled(open);
  m_clearStop->setEnabled(open && s.stop.latched());
  const bool ready = read && !stale && firmwareReady(s);
  m_restartFirmware->setEnabled(open && read && !stale && !firmwareReady(s));
  // A message that the firmware must restart is taken back once it reports ready again.
  if (m_messageAwaitsReady && ready) {
    m_messageAwaitsReady = false;
    m_message->setText(tr("%1's firmware is ready again.").arg(m_printer->printerName()));
    m_message->setStyleSheet(QString());
  }
  updateBanner();
}

void PrinterSection::updateBanner() {
  const hardware::PrinterStatus& s = m_printer->status();
  const bool open = m_printer->isOpen();
  const bool interrupted = m_run->hasRun() && m_run->printInterrupted() &&
                           m_run->state() == hardware::PrintRunState::Paused;
  QStringList lines;
  if (const QString lost = linkLostText(); !lost.isEmpty()) {
    lines << lost;
  } else if (open && !m_printer->hasRead() && !s.lastError.empty()) {
    lines << tr("%1 does not answer: %2").arg(m_printer->printerName(), QString::fromStdString(s.lastError));
  } else if (open && m_printer->hasRead() && !firmwareReady(s)) {
    lines << tr("The printer's firmware is %1: %2")
                 .arg(QString::fromStdString(s.firmwareState),
                      s.message.empty() ? tr("it says nothing more") : QString::fromStdString(s.message));
  }
  if (interrupted) lines << tr("The print run is paused: %1.").arg(m_run->lastProblem());
  const QString text = lines.join(QLatin1Char('\n'));
  m_banner->setText(text);
  m_banner->setStyleSheet(QStringLiteral("QLabel#printerBanner { background-color: #c62828; color: white; "
                                         "font-weight: bold; padding: 8px; }"));
  m_banner->setVisible(!text.isEmpty());
}

}  // namespace multidir::ui
