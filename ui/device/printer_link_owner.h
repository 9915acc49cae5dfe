#pragma once
// The Studio's handle on the printer: a QObject over one hardware::PrinterLink made from the address the
// operator typed (printer_url.h), with its status read on a timer and the staleness the panel shows.
//
// Threads: create, call and destroy on the GUI thread; every signal is emitted there. The link polls the
// printer on its own worker thread; status() is a copy under the link's mutex, cheap enough to read every
// readInterval on the GUI thread. connect() waits for the first status read and disconnect() for a request
// in flight, so both run on helper threads (in that order, for one link); the destructor waits for them.
//
// Lifetime: the link is shared (link()) with the print run, which may hold it after disconnectPrinter().
#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>
#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/printer_link.h"

class QThread;

namespace multidir::ui {

class PrinterLinkOwner : public QObject {
  Q_OBJECT

 public:
  explicit PrinterLinkOwner(QObject* parent = nullptr);
  // Disconnects and waits for the helper threads.
  ~PrinterLinkOwner() override;
  PrinterLinkOwner(const PrinterLinkOwner&) = delete;
  PrinterLinkOwner& operator=(const PrinterLinkOwner&) = delete;

  // Options of the next link (poll interval, timeouts, clocks); the defaults otherwise.
  void setLinkOptions(const hardware::PrinterLinkOptions& options) { m_options = options; }
  // How often status() is read from the link (100 ms by default).
  void setReadInterval(std::chrono::milliseconds interval);

  // Makes the link for `url` (InvalidParameter naming what is wrong, nothing started), closes any previous
  // one and connects in the background; connectFinished() tells the first read's outcome, after which the
  // link keeps polling on its own if it failed.
  core::Status connectPrinter(const QString& url, const QString& apiKey);
  // Closes the link without commanding the printer (a job goes on). Idempotent.
  void disconnectPrinter();
  // The printer's emergency stop, latched by the link and resent until the printer answers it; the latch's
  // state is in status().stop. Refused (commandFinished) without a link.
  void emergencyStop();
  // The operator allows jobs again after an emergency stop; the link's refusal (not confirmed yet) otherwise.
  core::Status clearStop();
  // Restarts the printer's firmware after an emergency stop shut it down (PrinterLink::restartFirmware: Klipper's
  // FIRMWARE_RESTART, OctoPrint's reconnect); firmwareRestartFinished() tells how it ended. Refused
  // (commandFailed) without a link.
  void restartFirmware();

  [[nodiscard]] bool isOpen() const { return m_link != nullptr; }
  [[nodiscard]] std::shared_ptr<hardware::PrinterLink> link() const { return m_link; }
  // "Moonraker printer at 127.0.0.1:7125"; empty without a link.
  [[nodiscard]] QString printerName() const;
  // The last status read (link Disconnected without a link).
  [[nodiscard]] const hardware::PrinterStatus& status() const { return m_status; }
  // A good status read since connectPrinter(): before it, the status holds no value of the printer's.
  [[nodiscard]] bool hasRead() const { return m_hasRead; }
  // The link was lost (status().linkLost after a good read) since this wall-clock time.
  [[nodiscard]] const std::optional<QDateTime>& staleSince() const { return m_staleSince; }

 signals:
  void statusChanged();
  // The first status read ended; `problem` is empty on success, else a translated sentence followed by the
  // link's own words (the link keeps polling).
  void connectFinished(bool connected, const QString& problem);
  // A command ended badly: `command` is its translated name, `problem` what went wrong in the link's words.
  void commandFailed(const QString& command, const QString& problem);
  // A firmware restart was answered: `problem` is empty when the printer took it, else the link's words.
  void firmwareRestartFinished(const QString& problem);
  // A link was opened (connectPrinter) or closed (disconnectPrinter).
  void openChanged(bool open);

 private:
  struct Session;

  void readStatus();
  void runInBackground(std::function<void()> work, std::function<void()> done = {});

  hardware::PrinterLinkOptions m_options;
  std::shared_ptr<Session> m_session;
  std::shared_ptr<hardware::PrinterLink> m_link;
  hardware::PrinterStatus m_status;
  bool m_hasRead = false;
  std::optional<QDateTime> m_staleSince;
  std::future<core::Status> m_stop;  // the latest emergency stop sent from here
  std::future<core::Status> m_restart;  // the latest firmware restart asked for from here
  QTimer m_readTimer;
  std::vector<QThread*> m_threads;
  std::uint64_t m_generation = 0;
};

}  // namespace multidir::ui
