#pragma once
// The Studio's handle on one device: a QObject over the hardware drivers (RotaryPlatform or RobotArm) that
// turns their worker-thread status callbacks into queued signals and their command futures into signals.
//
// Threads: create, call and destroy on the GUI thread; every signal is emitted there. The driver's status
// callback only stores the latest status and posts one queued call (coalescing bursts); connect() runs on
// a helper thread because the first attempt may wait for twice the response timeout. Command futures are
// watched by a timer that runs only while some are pending; a refusal (ready at once) is reported before
// the command call returns.
//
// Lifetime: disconnectDevice() stops the callbacks and the driver's worker. The driver itself lives as long
// as its session: until the connect thread ends and no positioner() handed out is held any more.
#include <QObject>
#include <QString>
#include <QTimer>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/print_run.h"
#include "ui/device/device_snapshot.h"

class QThread;

namespace multidir::ui {

class DeviceLink : public QObject {
  Q_OBJECT

 public:
  explicit DeviceLink(QObject* parent = nullptr);
  // Disconnects and waits for a connect attempt still running.
  ~DeviceLink() override;
  DeviceLink(const DeviceLink&) = delete;
  DeviceLink& operator=(const DeviceLink&) = delete;

  // Checks the settings (InvalidParameter naming the first bad one; nothing started), closes any previous
  // session and starts connecting in the background; connectFinished() tells the first attempt's outcome,
  // after which the driver keeps retrying on its own if it failed.
  core::Status connectDevice(const DeviceLinkSettings& settings);
  // Stops the driver without commanding the device (its heartbeat watchdog stops it). Idempotent.
  void disconnectDevice();

  [[nodiscard]] bool isOpen() const { return m_session != nullptr; }
  [[nodiscard]] const DeviceLinkSettings& settings() const { return m_settings; }
  // The last status received (state Disconnected when no session).
  [[nodiscard]] const DeviceSnapshot& snapshot() const { return m_snapshot; }
  // "rotary platform at 127.0.0.1:1502 (unit 1)", empty when no session.
  [[nodiscard]] QString deviceName() const;

  // Commands; the outcome comes through commandFinished(). Without a session they report "not connected".
  void enable();
  void home();  // rotary: enable first if needed is the operator's job; robot: level the platform (tilt 0)
  void moveToAngle(double angleDegrees);                              // rotary
  void moveToOrientation(double tiltDegrees, double azimuthDegrees);  // robot
  void stop();
  void emergencyStop();
  void clearFault();

  // The device as the print-run sequencer sees it; keeps the driver alive while held. Null without a session.
  [[nodiscard]] std::shared_ptr<hardware::Positioner> positioner() const;

 signals:
  void snapshotChanged(const multidir::ui::DeviceSnapshot& snapshot);
  void stateChanged(multidir::ui::DeviceState state);
  // The first connection attempt ended; `problem` is empty on success, else a translated sentence with the
  // driver's detail (the driver keeps retrying).
  void connectFinished(bool connected, const QString& problem);
  // A command ended: `command` is its translated name ("Home", "Go to 30°"), `problem` empty when the device
  // took it, else a translated sentence (refused, cancelled, failed) followed by the driver's detail.
  void commandFinished(const QString& command, bool ok, const QString& problem);

 private:
  struct Session;
  struct Mailbox;
  struct PendingCommand {
    QString name;
    std::future<core::Status> future;
    bool resolvesProblem = false;  // done, it resolves the device's last problem (Clear fault)
  };

  void submit(const QString& name, std::future<core::Status> future, bool resolvesProblem = false);
  void report(const QString& name, const core::Status& status);
  void reportNotConnected(const QString& name);
  void checkPending();
  void takeStatus();
  void setSnapshot(const DeviceSnapshot& snapshot);
  // The driver's last problem no longer applies (Clear fault done): the snapshot stops showing it.
  void problemResolved();

  DeviceLinkSettings m_settings;
  std::shared_ptr<Session> m_session;
  std::shared_ptr<Mailbox> m_mailbox;
  DeviceSnapshot m_snapshot;
  QString m_rawLastError;  // the driver's lastError as last received
  // The driver's lastError at the moment it stopped applying (the link came up, a fault was cleared);
  // unset while the link is down, when whatever the driver last reported is the cause.
  std::optional<QString> m_resolvedProblem;
  std::vector<PendingCommand> m_pending;
  QTimer m_pendingTimer;
  std::vector<QThread*> m_connectThreads;
  std::uint64_t m_generation = 0;
};

}  // namespace multidir::ui
