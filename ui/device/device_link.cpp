#include "ui/device/device_link.h"

#include <QDateTime>
#include <QLocale>
#include <QMetaObject>
#include <QThread>
#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <utility>

#include "multidir/hardware/robot_arm.h"
#include "multidir/hardware/rotary_platform.h"

namespace multidir::ui {
namespace {

using Clock = std::chrono::steady_clock;

QString degreesText(double degrees) { return QLocale().toString(degrees, 'f', 2) + QStringLiteral("°"); }

QString rotaryFaultText(const hardware::RotaryStatus& status) {
  QString text;
  switch (status.fault) {
    case hardware::RotaryFault::None:
      return {};
    case hardware::RotaryFault::Stall:
      text = status.stallDetectedByHost ? DeviceLink::tr("stall: the platform made no progress, so MultiDir stopped it")
                                        : DeviceLink::tr("stall: the controller lost its position (following error)");
      break;
    case hardware::RotaryFault::HeartbeatLost:
      text = DeviceLink::tr("heartbeat lost: the controller stopped because MultiDir went silent");
      break;
    case hardware::RotaryFault::LimitSwitch:
      text = DeviceLink::tr("a limit switch was hit");
      break;
    case hardware::RotaryFault::RejectedCommand:
      text = DeviceLink::tr("the controller rejected a command (not homed, or beyond its own limits)");
      break;
    case hardware::RotaryFault::EmergencyStop:
      text = DeviceLink::tr("emergency stop: the power stage is off");
      break;
    case hardware::RotaryFault::Unknown:
      text = DeviceLink::tr("unknown fault code %1").arg(status.faultCode);
      break;
  }
  return text + DeviceLink::tr("; press Clear fault, then Enable and Home");
}

QString robotFaultText(const hardware::RobotStatus& status) {
  switch (status.state) {
    case hardware::RobotProgramState::NotRunning:
      return DeviceLink::tr("the robot program is not running: start it on the teach pendant");
    case hardware::RobotProgramState::Halted:
      return DeviceLink::tr("halted by an emergency stop: press Clear fault before moving again");
    case hardware::RobotProgramState::Fault:
      switch (status.faultCode) {
        case 1:
          return DeviceLink::tr("the target was beyond the robot program's limits; press Clear fault");
        case 2:
          return DeviceLink::tr("the robot stopped because MultiDir's heartbeat was lost; press Clear fault");
        case 3:
          return DeviceLink::tr("the robot program got an unknown command; press Clear fault");
        default:
          return DeviceLink::tr("robot program fault code %1; press Clear fault").arg(status.faultCode);
      }
    default:
      return {};
  }
}

DeviceState stateFor(hardware::LinkState link, bool faulted) {
  switch (link) {
    case hardware::LinkState::Disconnected:
      return DeviceState::Disconnected;
    case hardware::LinkState::Connecting:
    case hardware::LinkState::Reconnecting:
      return DeviceState::Connecting;
    case hardware::LinkState::Connected:
      break;
  }
  return faulted ? DeviceState::Fault : DeviceState::Connected;
}

}  // namespace

// The drivers of one connection. Declared so that the positioner (which refers to a driver) goes first.
struct DeviceLink::Session {
  std::unique_ptr<hardware::RotaryPlatform> rotary;
  std::unique_ptr<hardware::RobotArm> robot;
  std::unique_ptr<hardware::Positioner> positioner;

  core::Status connect() { return rotary ? rotary->connect() : robot->connect(); }
  // Blocks until a callback in progress has returned, so none runs afterwards.
  void clearCallback() {
    if (rotary) rotary->setStatusCallback({});
    if (robot) robot->setStatusCallback({});
  }
  void disconnect() {
    clearCallback();
    if (rotary) rotary->disconnect();
    if (robot) robot->disconnect();
  }
  [[nodiscard]] std::string name() const { return rotary ? rotary->name() : robot->name(); }
};

// The latest status from the worker thread, waiting for the GUI thread to take it.
struct DeviceLink::Mailbox {
  std::mutex mutex;
  std::optional<hardware::RotaryStatus> rotary;
  std::optional<hardware::RobotStatus> robot;
  bool posted = false;
};

DeviceLink::DeviceLink(QObject* parent) : QObject(parent) {
  static const int registered = qRegisterMetaType<multidir::ui::DeviceSnapshot>();
  (void)registered;
  m_pendingTimer.setInterval(15);
  connect(&m_pendingTimer, &QTimer::timeout, this, &DeviceLink::checkPending);
}

DeviceLink::~DeviceLink() {
  disconnectDevice();
  for (QThread* thread : m_connectThreads) {
    thread->wait();
    delete thread;
  }
}

core::Status DeviceLink::connectDevice(const DeviceLinkSettings& settings) {
  if (core::Status valid = hardware::validate(settings.connection); !valid.ok()) return valid;
  if (core::Status valid = core::validate(settings.machine); !valid.ok()) return valid;
  const core::MachineKind wanted =
      settings.kind == DeviceKind::RotaryPlatform ? core::MachineKind::RotaryPlatform : core::MachineKind::TiltRotate;
  if (settings.machine.kind != wanted)
    return core::Error{core::ErrorCode::InvalidParameter,
                       std::string("the machine profile is a ") + core::machineKindName(settings.machine.kind) +
                           " machine, not a " + core::machineKindName(wanted) + " one as the device needs",
                       "machine profile"};
  disconnectDevice();
  m_settings = settings;
  m_rawLastError.clear();
  m_resolvedProblem.reset();
  const std::uint64_t generation = ++m_generation;

  auto session = std::make_shared<Session>();
  if (settings.kind == DeviceKind::RotaryPlatform) {
    hardware::RotaryPlatformOptions options;
    options.connection = settings.connection;
    options.machine = settings.machine;
    options.speedDegreesPerSecond = settings.rotarySpeedDegreesPerSecond;
    session->rotary = std::make_unique<hardware::RotaryPlatform>(options);
    session->positioner = hardware::makePositioner(*session->rotary);
  } else {
    hardware::RobotArmOptions options;
    options.connection = settings.connection;
    options.machine = settings.machine;
    options.speedPercent = settings.robotSpeedPercent;
    session->robot = std::make_unique<hardware::RobotArm>(options);
    session->positioner = hardware::makePositioner(*session->robot);
  }
  m_session = session;
  m_mailbox = std::make_shared<Mailbox>();

  // Runs on the driver's worker thread: keep it short, never touch widgets.
  auto post = [this, mailbox = m_mailbox](auto store) {
    std::lock_guard<std::mutex> lock(mailbox->mutex);
    store(*mailbox);
    if (mailbox->posted) return;
    mailbox->posted = true;
    QMetaObject::invokeMethod(
        this, [this] { takeStatus(); }, Qt::QueuedConnection);
  };
  if (session->rotary)
    session->rotary->setStatusCallback(
        [post](const hardware::RotaryStatus& status) { post([&](Mailbox& box) { box.rotary = status; }); });
  else
    session->robot->setStatusCallback(
        [post](const hardware::RobotStatus& status) { post([&](Mailbox& box) { box.robot = status; }); });

  DeviceSnapshot connecting;
  connecting.kind = settings.kind;
  connecting.state = DeviceState::Connecting;
  connecting.link = hardware::LinkState::Connecting;
  setSnapshot(connecting);

  auto outcome = std::make_shared<core::Status>(core::Done{});
  QThread* thread = QThread::create([session, outcome] {
    try {
      *outcome = session->connect();
    } catch (const std::exception& e) {
      *outcome = core::Error{core::ErrorCode::Internal, e.what(), "connect"};
    } catch (...) {
      *outcome = core::Error{core::ErrorCode::Internal, "unexpected error while connecting", "connect"};
    }
  });
  m_connectThreads.push_back(thread);
  connect(thread, &QThread::finished, this, [this, thread, outcome, generation] {
    m_connectThreads.erase(std::remove(m_connectThreads.begin(), m_connectThreads.end(), thread),
                           m_connectThreads.end());
    thread->deleteLater();
    if (generation != m_generation || !m_session) return;  // superseded or disconnected meanwhile
    if (outcome->ok()) {
      emit connectFinished(true, {});
      return;
    }
    const QString detail = QString::fromStdString(outcome->error().describe());
    if (outcome->error().code == core::ErrorCode::InvalidParameter) {
      // Bad options: the driver started nothing and will not retry.
      disconnectDevice();
      emit connectFinished(false, tr("Cannot connect with these settings: %1").arg(detail));
      return;
    }
    emit connectFinished(false, tr("Could not connect yet; MultiDir keeps trying. %1").arg(detail));
  });
  thread->start();
  return core::Done{};
}

void DeviceLink::disconnectDevice() {
  if (!m_session) return;
  ++m_generation;
  m_session->disconnect();  // no callback runs after this; queued commands end (Cancelled)
  checkPending();
  m_pending.clear();  // whatever did not end with the worker will not be reported
  m_session.reset();
  m_mailbox.reset();
  m_pendingTimer.stop();
  DeviceSnapshot disconnected;
  disconnected.kind = m_settings.kind;
  setSnapshot(disconnected);
}

QString DeviceLink::deviceName() const { return m_session ? QString::fromStdString(m_session->name()) : QString(); }

std::shared_ptr<hardware::Positioner> DeviceLink::positioner() const {
  if (!m_session) return nullptr;
  return std::shared_ptr<hardware::Positioner>(m_session, m_session->positioner.get());
}

void DeviceLink::enable() {
  const QString name = tr("Enable");
  if (m_session && m_session->robot) {
    emit commandFinished(name, false,
                         tr("%1 does not apply to the robot arm: its program enables the arm; start it on the "
                            "teach pendant.")
                             .arg(name));
    return;
  }
  if (!m_session) return reportNotConnected(name);
  submit(name, m_session->rotary->enable());
}

void DeviceLink::home() {
  const QString name = tr("Home");
  if (!m_session) return reportNotConnected(name);
  if (m_session->rotary) return submit(name, m_session->rotary->home());
  submit(name, m_session->robot->moveTo(0.0, 0.0));  // the arm's "home" is the level platform
}

void DeviceLink::moveToAngle(double angleDegrees) {
  const QString name = tr("Go to %1").arg(degreesText(angleDegrees));
  if (!m_session) return reportNotConnected(name);
  if (!m_session->rotary) {
    emit commandFinished(name, false, tr("%1 refused: the robot arm takes a tilt and an azimuth.").arg(name));
    return;
  }
  submit(name, m_session->rotary->moveTo(angleDegrees));
}

void DeviceLink::moveToOrientation(double tiltDegrees, double azimuthDegrees) {
  const QString name = tr("Go to tilt %1, azimuth %2").arg(degreesText(tiltDegrees), degreesText(azimuthDegrees));
  if (!m_session) return reportNotConnected(name);
  if (!m_session->robot) {
    emit commandFinished(name, false, tr("%1 refused: the rotary platform takes one angle.").arg(name));
    return;
  }
  submit(name, m_session->robot->moveTo(tiltDegrees, azimuthDegrees));
}

void DeviceLink::stop() {
  const QString name = tr("Stop");
  if (!m_session) return reportNotConnected(name);
  submit(name, m_session->rotary ? m_session->rotary->stop() : m_session->robot->stop());
}

void DeviceLink::emergencyStop() {
  const QString name = tr("E-STOP");
  if (!m_session) return reportNotConnected(name);
  submit(name, m_session->rotary ? m_session->rotary->emergencyStop() : m_session->robot->emergencyStop());
}

void DeviceLink::clearFault() {
  const QString name = tr("Clear fault");
  if (!m_session) return reportNotConnected(name);
  // Also the operator clearing a latched stop or e-stop (docs/hardware.md): refused until the device confirmed it.
  const core::Status cleared = m_session->rotary ? m_session->rotary->clearStop() : m_session->robot->clearStop();
  if (!cleared.ok()) return report(name, cleared);
  submit(name, m_session->rotary ? m_session->rotary->clearFault() : m_session->robot->clearFault(), true);
}

void DeviceLink::submit(const QString& name, std::future<core::Status> future, bool resolvesProblem) {
  if (future.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    report(name, future.get());  // refused: nothing was sent
    return;
  }
  m_pending.push_back(PendingCommand{name, std::move(future), resolvesProblem});
  if (!m_pendingTimer.isActive()) m_pendingTimer.start();
}

void DeviceLink::reportNotConnected(const QString& name) {
  emit commandFinished(name, false, tr("%1 refused: not connected; connect to the device first.").arg(name));
}

void DeviceLink::report(const QString& name, const core::Status& status) {
  if (status.ok()) {
    emit commandFinished(name, true, {});
    return;
  }
  const core::Error& error = status.error();
  const QString detail = QString::fromStdString(error.message);
  QString problem;
  if (error.code == core::ErrorCode::InvalidParameter)
    problem = tr("%1 refused, nothing was sent: %2").arg(name, detail);
  else if (error.code == core::ErrorCode::Cancelled)
    problem = tr("%1 cancelled by Stop, E-STOP or Disconnect: %2").arg(name, detail);
  else
    problem = tr("%1 failed at the device or on the link: %2").arg(name, detail);
  emit commandFinished(name, false, problem);
}

void DeviceLink::checkPending() {
  // Collected first: a slot of commandFinished may issue a new command.
  std::vector<std::pair<QString, core::Status>> finished;
  bool resolved = false;
  for (auto it = m_pending.begin(); it != m_pending.end();) {
    if (it->future.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++it;
      continue;
    }
    core::Status status = core::Done{};
    try {
      status = it->future.get();
    } catch (const std::exception& e) {  // a broken promise: the driver went away
      status = core::Error{core::ErrorCode::Cancelled, e.what(), ""};
    }
    resolved = resolved || (it->resolvesProblem && status.ok());
    finished.emplace_back(it->name, std::move(status));
    it = m_pending.erase(it);
  }
  if (m_pending.empty()) m_pendingTimer.stop();
  if (resolved) problemResolved();
  for (const auto& [name, status] : finished) report(name, status);
}

void DeviceLink::takeStatus() {
  if (!m_mailbox) return;  // disconnected since the call was posted
  std::optional<hardware::RotaryStatus> rotary;
  std::optional<hardware::RobotStatus> robot;
  {
    std::lock_guard<std::mutex> lock(m_mailbox->mutex);
    rotary = std::move(m_mailbox->rotary);
    robot = std::move(m_mailbox->robot);
    m_mailbox->rotary.reset();
    m_mailbox->robot.reset();
    m_mailbox->posted = false;
  }
  DeviceSnapshot next;
  next.kind = m_settings.kind;
  next.lastAlive = m_snapshot.lastAlive;
  if (rotary) {
    const hardware::RotaryStatus& s = *rotary;
    next.link = s.link;
    next.faultText = rotaryFaultText(s);
    next.state = stateFor(s.link, s.fault != hardware::RotaryFault::None);
    next.enabled = s.enabled;
    next.homed = s.homed;
    next.homing = s.homing;
    next.moving = s.moving;
    next.atTarget = s.atTarget;
    next.angleDegrees = s.angleDegrees;
    next.targetAngleDegrees = s.targetAngleDegrees;
    next.lastError = QString::fromStdString(s.lastError);
    next.deviceAlive = s.controllerAlive;
    next.polls = s.polls;
  } else if (robot) {
    const hardware::RobotStatus& s = *robot;
    next.link = s.link;
    next.faultText = robotFaultText(s);
    next.state = stateFor(s.link, !next.faultText.isEmpty());
    next.enabled = next.faultText.isEmpty();
    next.homed = true;
    next.moving = s.state == hardware::RobotProgramState::Moving;
    next.atTarget = s.state == hardware::RobotProgramState::Reached;
    next.tiltDegrees = s.tiltDegrees;
    next.azimuthDegrees = s.azimuthDegrees;
    next.targetTiltDegrees = s.targetTiltDegrees;
    next.targetAzimuthDegrees = s.targetAzimuthDegrees;
    next.lastError = QString::fromStdString(s.lastError);
    next.deviceAlive = s.programAlive;
    next.polls = s.polls;
  } else {
    return;
  }
  const bool linkUp = next.link == hardware::LinkState::Connected;
  if (linkUp && next.deviceAlive) next.lastAlive = Clock::now();
  // Before the first read with the link up the status holds the driver's defaults (angle 0, program "not
  // running"): not the device's state, so nothing of it is shown; afterwards a lost link makes it stale.
  next.hasRead = m_snapshot.hasRead || linkUp;
  if (!next.hasRead) next.faultText.clear();
  if (!linkUp && next.hasRead)
    next.staleSince = m_snapshot.staleSince ? m_snapshot.staleSince : std::optional(QDateTime::currentDateTime());
  // The driver keeps its last problem until another one comes; what it reported before the link came (back)
  // up is resolved by the link being up.
  m_rawLastError = next.lastError;
  if (!linkUp)
    m_resolvedProblem.reset();
  else if (!m_resolvedProblem)
    m_resolvedProblem = next.lastError;
  if (m_resolvedProblem && next.lastError == *m_resolvedProblem) next.lastError.clear();
  setSnapshot(next);
}

void DeviceLink::problemResolved() {
  if (!m_session || m_snapshot.link != hardware::LinkState::Connected) return;
  m_resolvedProblem = m_rawLastError;
  if (m_snapshot.lastError.isEmpty()) return;
  DeviceSnapshot next = m_snapshot;
  next.lastError.clear();
  setSnapshot(next);
}

void DeviceLink::setSnapshot(const DeviceSnapshot& snapshot) {
  const DeviceState before = m_snapshot.state;
  m_snapshot = snapshot;
  emit snapshotChanged(m_snapshot);
  if (snapshot.state != before) emit stateChanged(snapshot.state);
}

}  // namespace multidir::ui
