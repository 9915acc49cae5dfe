#pragma once
// The Printer section of the Hardware panel: connect to the printer by its address (and API key), watch it
// live (job, firmware and its message, extruder and bed temperatures, file, the current step's progress, the
// whole job's time left from the slicer's estimates), clear its emergency stop and, once the operator confirmed
// it ("restartFirmwareBox"), restart the firmware an emergency stop shut down (Klipper's FIRMWARE_RESTART,
// OctoPrint's reconnect; a Marlin printer is told to press its reset button).
//
// Truthfulness, as for the platform: no printer value is shown before the first good read; once the link is
// lost every value is greyed and marked "unknown since HH:MM:SS" and a banner says so; the printer's
// messages are shown in its own words.
//
// The address is remembered (QSettings "printer/url"); the API key is not, since QSettings keeps it as
// plain text: it is typed again after a restart.
//
// Thread: GUI thread. The values come from PrinterLinkOwner's status reads and from the run's driver.
#include <QGroupBox>
#include <QString>
#include <vector>

class QLabel;
class QLineEdit;
class QPushButton;

namespace multidir::ui {

class PrinterLinkOwner;
class PrintRunDriver;

class PrinterSection : public QGroupBox {
  Q_OBJECT

 public:
  // `printer` and `run` must outlive the section.
  PrinterSection(PrinterLinkOwner* printer, const PrintRunDriver* run, QWidget* parent = nullptr);

  // The slicer's printing time of each step of the run under way (seconds); empty: no estimates (the ETA
  // then says so).
  void setRunEstimates(std::vector<double> seconds);
  // The banner above the printer's values; empty when hidden.
  [[nodiscard]] QString bannerText() const;
  // The sentence the panel's own banner repeats while the printer's link is lost ("" otherwise).
  [[nodiscard]] QString linkLostText() const;
  // The latest outcome or problem of the section's own commands.
  [[nodiscard]] QString messageText() const;
  [[nodiscard]] QString url() const;
  void setUrl(const QString& url);
  void setApiKey(const QString& key);

 public slots:
  void connectPrinter();
  void disconnectPrinter();
  // Redraws every value from the printer's last status and the run.
  void refresh();

 private:
  void clearStop();
  void askToRestartFirmware();
  // `awaitsReady`: the message says the firmware must restart; refresh() takes it back once it is ready.
  void setMessage(const QString& text, bool error, bool awaitsReady = false);
  void updateBanner();
  QString progressText(double* stepProgress) const;
  QString etaText(double stepProgress) const;

  PrinterLinkOwner* m_printer;
  const PrintRunDriver* m_run;
  std::vector<double> m_estimates;

  QLineEdit* m_url = nullptr;
  QLineEdit* m_apiKey = nullptr;
  QPushButton* m_connect = nullptr;
  QPushButton* m_disconnect = nullptr;
  QPushButton* m_clearStop = nullptr;
  QPushButton* m_restartFirmware = nullptr;
  bool m_messageAwaitsReady = false;
  QLabel* m_banner = nullptr;
  QLabel* m_state = nullptr;
  QLabel* m_job = nullptr;
  QLabel* m_firmware = nullptr;
  QLabel* m_says = nullptr;
  QLabel* m_extruder = nullptr;
  QLabel* m_bed = nullptr;
  QLabel* m_file = nullptr;
  QLabel* m_progress = nullptr;
  QLabel* m_eta = nullptr;
  QLabel* m_problem = nullptr;
  QLabel* m_message = nullptr;
};

}  // namespace multidir::ui
