#include "ui/device/hardware_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <chrono>

#include "ui/device/connection_form.h"
#include "ui/device/device_link.h"
#include "ui/device/plan_steps.h"
#include "ui/device/print_run_driver.h"

namespace multidir::ui {
namespace {

using Clock = std::chrono::steady_clock;

QString degrees(double value) { return QLocale().toString(value, 'f', 2) + QStringLiteral("°"); }

QLabel* valueLabel(QWidget* parent, const QString& name) {
  auto* label = new QLabel(parent);
  label->setObjectName(name);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label->setWordWrap(true);
  return label;
}

QPushButton* button(QWidget* parent, const QString& name, const QString& text, const QString& tip = {}) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  if (!tip.isEmpty()) b->setToolTip(tip);
  return b;
}

QDoubleSpinBox* angleBox(QWidget* parent, const QString& name, double low, double high, double value) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setRange(low, high);
  box->setDecimals(2);
  box->setValue(value);
  box->setSuffix(QStringLiteral("°"));
  return box;
}

QString stateText(const DeviceSnapshot& s) {
  switch (s.state) {
    case DeviceState::Disconnected:
      return HardwarePanel::tr("Disconnected");
    case DeviceState::Connecting:
      return s.link == hardware::LinkState::Reconnecting ? HardwarePanel::tr("Reconnecting…")
                                                         : HardwarePanel::tr("Connecting…");
    case DeviceState::Connected:
      return HardwarePanel::tr("Connected");
    case DeviceState::Fault:
      return HardwarePanel::tr("Fault");
  }
  return {};
}

QString runStateText(hardware::PrintRunState state) {
  switch (state) {
    case hardware::PrintRunState::Idle:
      return HardwarePanel::tr("idle");
    case hardware::PrintRunState::Moving:
      return HardwarePanel::tr("turning the platform");
    case hardware::PrintRunState::Settling:
      return HardwarePanel::tr("settling");
    case hardware::PrintRunState::Printing:
      return HardwarePanel::tr("printing");
    case hardware::PrintRunState::Paused:
      return HardwarePanel::tr("paused");
    case hardware::PrintRunState::Completed:
      return HardwarePanel::tr("finished");
    case hardware::PrintRunState::Aborted:
      return HardwarePanel::tr("aborted");
    case hardware::PrintRunState::Faulted:
      return HardwarePanel::tr("stopped by a device problem");
  }
  return {};
}

QString orientationText(const hardware::PlatformOrientation& orientation) {
  if (orientation.kind == hardware::PlatformOrientation::Kind::Rotary)
    return HardwarePanel::tr("angle %1").arg(degrees(orientation.rotaryDegrees));
  return HardwarePanel::tr("tilt %1, azimuth %2")
      .arg(degrees(orientation.tiltDegrees), degrees(orientation.azimuthDegrees));
}

QString clockText(std::chrono::milliseconds elapsed) {
  const long long seconds = elapsed.count() / 1000;
  return QStringLiteral("%1:%2:%3")
      .arg(seconds / 3600)
      .arg((seconds / 60) % 60, 2, 10, QLatin1Char('0'))
      .arg(seconds % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace

HardwarePanel::HardwarePanel(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("hardwarePanel"));
  m_link = new DeviceLink(this);
  m_run = new PrintRunDriver(this);

  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  layout->addWidget(buildConnectionGroup());
  layout->addWidget(buildStatusGroup());
  layout->addWidget(buildControlsGroup());
  m_message = valueLabel(content, QStringLiteral("hardwareMessage"));
  layout->addWidget(m_message);
  layout->addWidget(buildRunGroup());
  layout->addStretch(1);

  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(content);
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  outer->addWidget(scroll);

  connect(m_link, &DeviceLink::snapshotChanged, this, &HardwarePanel::onSnapshot);
  connect(m_link, &DeviceLink::commandFinished, this, &HardwarePanel::onCommandFinished);
  connect(m_link, &DeviceLink::connectFinished, this, &HardwarePanel::onConnectFinished);
  connect(m_run, &PrintRunDriver::stateChanged, this, &HardwarePanel::onRunStateChanged);
  connect(m_run, &PrintRunDriver::printRequested, this, &HardwarePanel::onPrintRequested);
  connect(m_run, &PrintRunDriver::currentRegionChanged, this, &HardwarePanel::currentRegionChanged);
  connect(m_run, &PrintRunDriver::logged, m_runLog, &QPlainTextEdit::appendPlainText);
  connect(m_form, &ConnectionForm::kindChanged, this, [this] {
    updateKindWidgets();
    updateLimits();
  });

  m_clockTimer.setInterval(250);
  connect(&m_clockTimer, &QTimer::timeout, this, &HardwarePanel::updateClockTexts);

  onSnapshot(m_link->snapshot());
  updateKindWidgets();
  updateLimits();
  updateRunTexts();
}

HardwarePanel::~HardwarePanel() {
  // The run and the link report while they shut down; as children they would outlive this panel's members
  // (QWidget deletes children last), so they go first, without reporting to it. The run first: it holds
  // the link's positioner.
  QObject::disconnect(m_run, nullptr, this, nullptr);
  QObject::disconnect(m_link, nullptr, this, nullptr);
  delete m_run;
  delete m_link;
}

QGroupBox* HardwarePanel::buildConnectionGroup() {
  auto* group = new QGroupBox(tr("Connection"), this);
  m_form = new ConnectionForm(group);
  m_limits = valueLabel(group, QStringLiteral("limitsText"));
  m_connect = button(group, QStringLiteral("connectButton"), tr("Connect"));
  m_disconnect = button(group, QStringLiteral("disconnectButton"), tr("Disconnect"),
                        tr("Closes the link without commanding the device; its heartbeat watchdog stops it."));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_connect);
  buttons->addWidget(m_disconnect);
  auto* layout = new QVBoxLayout(group);
  layout->addWidget(m_form);
  layout->addWidget(m_limits);
  layout->addLayout(buttons);
  connect(m_connect, &QPushButton::clicked, this, &HardwarePanel::connectDevice);
  connect(m_disconnect, &QPushButton::clicked, this, &HardwarePanel::disconnectDevice);
  return group;
}

QGroupBox* HardwarePanel::buildStatusGroup() {
  auto* group = new QGroupBox(tr("Status"), this);
  m_state = valueLabel(group, QStringLiteral("stateValue"));
  m_position = valueLabel(group, QStringLiteral("positionValue"));
  m_moving = valueLabel(group, QStringLiteral("movingValue"));
  m_homed = valueLabel(group, QStringLiteral("homedValue"));
  m_fault = valueLabel(group, QStringLiteral("faultValue"));
  m_heartbeat = valueLabel(group, QStringLiteral("heartbeatValue"));
  m_linkProblem = valueLabel(group, QStringLiteral("linkProblemValue"));
  auto* form = new QFormLayout(group);
  form->addRow(tr("State:"), m_state);
  form->addRow(tr("Position:"), m_position);
  form->addRow(tr("Moving:"), m_moving);
  form->addRow(tr("Homed:"), m_homed);
  form->addRow(tr("Fault:"), m_fault);
  form->addRow(tr("Heartbeat:"), m_heartbeat);
  form->addRow(tr("Last problem:"), m_linkProblem);
  return group;
}

QGroupBox* HardwarePanel::buildControlsGroup() {
  auto* group = new QGroupBox(tr("Controls"), this);
  m_enable = button(group, QStringLiteral("enableButton"), tr("Enable"), tr("Switches the platform's drive on."));
  m_home = button(group, QStringLiteral("homeButton"), tr("Home"),
                  tr("Rotary platform: finds the home switch (0°). Robot arm: levels the platform (tilt 0°)."));
  m_clearFault = button(group, QStringLiteral("clearFaultButton"), tr("Clear fault"),
                        tr("Resets the device after a fault or an E-STOP; then enable and home again."));
  m_jogStep = angleBox(group, QStringLiteral("jogStep"), 0.01, 90.0, 1.0);
  m_jogAxis = new QComboBox(group);
  m_jogAxis->setObjectName(QStringLiteral("jogAxis"));
  m_jogAxis->addItem(tr("Tilt"));
  m_jogAxis->addItem(tr("Azimuth"));
  m_jogMinus = button(group, QStringLiteral("jogMinusButton"), tr("Jog −"));
  m_jogPlus = button(group, QStringLiteral("jogPlusButton"), tr("Jog +"));
  m_targetAngle = angleBox(group, QStringLiteral("targetAngle"), -360.0, 360.0, 0.0);
  m_targetTilt = angleBox(group, QStringLiteral("targetTilt"), 0.0, 180.0, 0.0);
  m_targetAzimuth = angleBox(group, QStringLiteral("targetAzimuth"), -180.0, 180.0, 0.0);
  m_targetAngleLabel = new QLabel(tr("Angle:"), group);
  m_targetTiltLabel = new QLabel(tr("Tilt:"), group);
  m_targetAzimuthLabel = new QLabel(tr("Azimuth:"), group);
  m_goTo = button(group, QStringLiteral("goToButton"), tr("Go to"));
  m_stop =
      button(group, QStringLiteral("stopButton"), tr("Stop"), tr("Decelerates and stops; cancels queued commands."));
  m_estop = button(group, QStringLiteral("estopButton"), tr("E-STOP"),
                   tr("Emergency stop: cuts the motion at once. Clear the fault, enable and home again afterwards."));
  m_estop->setMinimumHeight(48);
  m_estop->setStyleSheet(
      QStringLiteral("QPushButton { background-color: #c62828; color: white; font-weight: bold; font-size: 16pt; }"
                     "QPushButton:disabled { background-color: #e0a0a0; color: #f5f5f5; }"));

  auto* grid = new QGridLayout(group);
  grid->addWidget(m_enable, 0, 0);
  grid->addWidget(m_home, 0, 1);
  grid->addWidget(m_clearFault, 0, 2);
  grid->addWidget(new QLabel(tr("Jog step:"), group), 1, 0);
  grid->addWidget(m_jogStep, 1, 1);
  grid->addWidget(m_jogAxis, 1, 2);
  grid->addWidget(m_jogMinus, 2, 1);
  grid->addWidget(m_jogPlus, 2, 2);
  grid->addWidget(m_targetAngleLabel, 3, 0);
  grid->addWidget(m_targetAngle, 3, 1);
  grid->addWidget(m_targetTiltLabel, 4, 0);
  grid->addWidget(m_targetTilt, 4, 1);
  grid->addWidget(m_targetAzimuthLabel, 5, 0);
  grid->addWidget(m_targetAzimuth, 5, 1);
  grid->addWidget(m_goTo, 3, 2);
  grid->addWidget(m_stop, 6, 0, 1, 3);
  grid->addWidget(m_estop, 7, 0, 1, 3);

  connect(m_enable, &QPushButton::clicked, m_link, &DeviceLink::enable);
  connect(m_home, &QPushButton::clicked, m_link, &DeviceLink::home);
  connect(m_clearFault, &QPushButton::clicked, m_link, &DeviceLink::clearFault);
  connect(m_jogMinus, &QPushButton::clicked, this, [this] { jog(-1.0); });
  connect(m_jogPlus, &QPushButton::clicked, this, [this] { jog(1.0); });
  connect(m_goTo, &QPushButton::clicked, this, &HardwarePanel::goTo);
  connect(m_stop, &QPushButton::clicked, m_link, &DeviceLink::stop);
  connect(m_estop, &QPushButton::clicked, m_link, &DeviceLink::emergencyStop);
  return group;
}

QGroupBox* HardwarePanel::buildRunGroup() {
  auto* group = new QGroupBox(tr("Print run"), this);
  m_planSummary = valueLabel(group, QStringLiteral("planSummaryText"));
  m_startRun = button(group, QStringLiteral("startRunButton"), tr("Start run"),
                      tr("Turns the platform to each region's orientation in printing order and asks for each "
                         "region to be printed."));
  m_runStep = valueLabel(group, QStringLiteral("runStepText"));
  m_runElapsed = valueLabel(group, QStringLiteral("runElapsedText"));
  m_prompt = valueLabel(group, QStringLiteral("runPrompt"));
  QFont bold = m_prompt->font();
  bold.setBold(true);
  bold.setPointSizeF(bold.pointSizeF() * 1.2);
  m_prompt->setFont(bold);
  m_regionDone = button(group, QStringLiteral("regionDoneButton"), tr("Region done"),
                        tr("Press when the region asked for has been printed."));
  m_pause = button(group, QStringLiteral("pauseButton"), tr("Pause"));
  m_resume = button(group, QStringLiteral("resumeButton"), tr("Resume"),
                    tr("Continues a paused run, or retries the current step after a device problem."));
  m_abort = button(group, QStringLiteral("abortButton"), tr("Abort"));
  m_runLog = new QPlainTextEdit(group);
  m_runLog->setObjectName(QStringLiteral("runLog"));
  m_runLog->setReadOnly(true);
  m_runLog->setMaximumBlockCount(1000);
  m_runLog->setMinimumHeight(80);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_regionDone);
  buttons->addWidget(m_pause);
  buttons->addWidget(m_resume);
  buttons->addWidget(m_abort);
  auto* form = new QFormLayout;
  form->addRow(tr("Step:"), m_runStep);
  form->addRow(tr("Elapsed:"), m_runElapsed);
  auto* layout = new QVBoxLayout(group);
  layout->addWidget(m_planSummary);
  layout->addWidget(m_startRun);
  layout->addLayout(form);
  layout->addWidget(m_prompt);
  layout->addLayout(buttons);
  layout->addWidget(m_runLog);

  connect(m_startRun, &QPushButton::clicked, this, &HardwarePanel::startRun);
  connect(m_regionDone, &QPushButton::clicked, this, [this] { runEvent(tr("Region done"), m_run->regionDone()); });
  connect(m_pause, &QPushButton::clicked, this, [this] { runEvent(tr("Pause"), m_run->pause()); });
  connect(m_resume, &QPushButton::clicked, this, [this] { runEvent(tr("Resume"), m_run->resume()); });
  connect(m_abort, &QPushButton::clicked, this, [this] { runEvent(tr("Abort"), m_run->abort()); });
  return group;
}

QString HardwarePanel::messageText() const { return m_message->text(); }

QString HardwarePanel::promptText() const { return m_prompt->text(); }

core::MachineSpec HardwarePanel::machineForNextConnection() const {
  return machineForDevice(m_form->kind(), m_profile);
}

void HardwarePanel::setMachineProfile(const core::MachineSpec& profile) {
  m_profile = profile;
  updateLimits();
}

void HardwarePanel::setPlan(const core::Decomposition& plan) {
  m_planAngles = regionAngles(plan);
  updateRunTexts();
  updateControls();
}

void HardwarePanel::clearPlan() {
  m_planAngles.clear();
  updateRunTexts();
  updateControls();
}

void HardwarePanel::connectDevice() {
  emit connectRequested();
  DeviceLinkSettings settings;
  settings.kind = m_form->kind();
  settings.connection = m_form->settings();
  settings.rotarySpeedDegreesPerSecond = m_form->rotarySpeedDegreesPerSecond();
  settings.robotSpeedPercent = m_form->robotSpeedPercent();
  settings.machine = machineForDevice(settings.kind, m_profile, &m_linkUsesProfile);
  const core::Status started = m_link->connectDevice(settings);
  if (!started.ok()) {
    setMessage(tr("Cannot connect with these settings: %1").arg(QString::fromStdString(started.error().describe())),
               true);
    return;
  }
  setMessage(tr("Connecting to %1…").arg(m_link->deviceName()), false);
  m_clockTimer.start();
  updateLimits();
}

void HardwarePanel::disconnectDevice() {
  m_link->disconnectDevice();
  if (!m_run->isActive()) m_clockTimer.stop();
  setMessage(tr("Disconnected."), false);
  updateLimits();
}

void HardwarePanel::onSnapshot(const DeviceSnapshot& s) {
  m_state->setText(stateText(s));
  const bool open = s.state != DeviceState::Disconnected;
  if (!open) {
    m_position->setText(QStringLiteral("—"));
    m_moving->setText(QStringLiteral("—"));
    m_homed->setText(QStringLiteral("—"));
  } else if (s.kind == DeviceKind::RotaryPlatform) {
    m_position->setText(tr("%1 (target %2)").arg(degrees(s.angleDegrees), degrees(s.targetAngleDegrees)));
    m_moving->setText(s.homing ? tr("homing") : s.moving ? tr("yes") : tr("no"));
    m_homed->setText(s.homed ? tr("yes") : tr("no"));
  } else {
    m_position->setText(tr("tilt %1, azimuth %2").arg(degrees(s.tiltDegrees), degrees(s.azimuthDegrees)));
    m_moving->setText(s.moving ? tr("yes") : tr("no"));
    m_homed->setText(tr("not needed (robot arm)"));
  }
  m_fault->setText(s.faultText.isEmpty() ? (open ? tr("none") : QStringLiteral("—")) : s.faultText);
  m_fault->setStyleSheet(s.faultText.isEmpty() ? QString() : QStringLiteral("color: #c62828;"));
  m_linkProblem->setText(s.lastError.isEmpty() ? tr("none") : s.lastError);
  updateClockTexts();
  updateControls();
}

void HardwarePanel::onCommandFinished(const QString& command, bool ok, const QString& problem) {
  if (ok)
    setMessage(tr("%1: sent to the device.").arg(command), false);
  else
    setMessage(problem, true);
}

void HardwarePanel::onConnectFinished(bool connected, const QString& problem) {
  if (connected)
    setMessage(tr("Connected to %1.").arg(m_link->deviceName()), false);
  else
    setMessage(problem, true);
  updateControls();
}

void HardwarePanel::onRunStateChanged(hardware::PrintRunState state) {
  if (state != hardware::PrintRunState::Printing) m_prompt->clear();
  if (state == hardware::PrintRunState::Faulted)
    setMessage(tr("The print run stopped: %1. Fix the device (Clear fault, Enable, Home), then press Resume to "
                  "retry this step, or Abort.")
                   .arg(m_run->lastProblem()),
               true);
  else if (state == hardware::PrintRunState::Completed)
    setMessage(tr("The print run is finished: every region was printed."), false);
  else if (state == hardware::PrintRunState::Aborted)
    setMessage(tr("The print run was aborted."), false);
  if (m_run->isActive()) m_clockTimer.start();
  updateRunTexts();
  updateControls();
}

void HardwarePanel::onPrintRequested(int region, const QString& regionFile) {
  m_prompt->setText(tr("Print region %1 (file %2), then press Region done.").arg(region + 1).arg(regionFile));
  updateRunTexts();
  updateControls();
}

void HardwarePanel::jog(double direction) {
  const DeviceSnapshot& s = m_link->snapshot();
  const double step = direction * m_jogStep->value();
  if (s.kind == DeviceKind::RotaryPlatform) {
    // From the target the controller holds: it is on the stepper's grid, the actual angle may not be yet.
    m_link->moveToAngle(s.targetAngleDegrees + step);
  } else if (m_jogAxis->currentIndex() == 0) {
    m_link->moveToOrientation(s.targetTiltDegrees + step, s.targetAzimuthDegrees);
  } else {
    m_link->moveToOrientation(s.targetTiltDegrees, s.targetAzimuthDegrees + step);
  }
}

void HardwarePanel::goTo() {
  if (m_link->snapshot().kind == DeviceKind::RotaryPlatform)
    m_link->moveToAngle(m_targetAngle->value());
  else
    m_link->moveToOrientation(m_targetTilt->value(), m_targetAzimuth->value());
}

void HardwarePanel::startRun() {
  if (!m_link->isOpen()) {
    setMessage(tr("Start run refused: not connected; connect to the device first."), true);
    return;
  }
  // The limits the driver enforces are those it was connected with.
  const DeviceLinkSettings& settings = m_link->settings();
  auto steps = printSteps(m_planAngles, settings.kind, settings.machine);
  if (!steps) {
    setMessage(tr("Start run refused: %1").arg(QString::fromStdString(steps.error().message)), true);
    return;
  }
  m_runLog->clear();
  m_prompt->clear();
  const core::Status started = m_run->start(m_link->positioner(), std::move(steps.value()), m_runOptions);
  runEvent(tr("Start run"), started);
}

void HardwarePanel::runEvent(const QString& event, const core::Status& status) {
  if (!status.ok()) setMessage(tr("%1 refused: %2").arg(event, QString::fromStdString(status.error().message)), true);
  updateRunTexts();
  updateControls();
}

void HardwarePanel::setMessage(const QString& text, bool error) {
  m_message->setText(text);
  m_messageIsError = error;
  m_message->setStyleSheet(error ? QStringLiteral("color: #c62828;") : QString());
}

void HardwarePanel::updateLimits() {
  const bool open = m_link->isOpen();
  const DeviceKind kind = open ? m_link->settings().kind : m_form->kind();
  bool fromProfile = m_linkUsesProfile;
  const core::MachineSpec spec = open ? m_link->settings().machine : machineForDevice(kind, m_profile, &fromProfile);
  QString limits =
      kind == DeviceKind::RotaryPlatform
          ? tr("Limits: %1 to %2 in steps of %3")
                .arg(degrees(spec.minAngleDegrees), degrees(spec.maxAngleDegrees), degrees(spec.angleStepDegrees))
          : tr("Limits: tilt up to %1, %n forbidden cone(s)", nullptr, static_cast<int>(spec.forbiddenCones.size()))
                .arg(degrees(spec.maxTiltDegrees));
  if (fromProfile)
    limits += tr(" (machine profile)");
  else if (m_profile)
    limits += tr(" (defaults: the machine profile is for a %1 machine)")
                  .arg(QString::fromLatin1(core::machineKindName(m_profile->kind)));
  else
    limits += tr(" (defaults: no machine profile)");
  if (open) limits += tr("; a changed profile applies at the next Connect");
  m_limits->setText(limits);
}

void HardwarePanel::updateKindWidgets() {
  const DeviceKind kind = m_link->isOpen() ? m_link->settings().kind : m_form->kind();
  const bool rotary = kind == DeviceKind::RotaryPlatform;
  m_targetAngle->setVisible(rotary);
  m_targetAngleLabel->setVisible(rotary);
  m_targetTilt->setVisible(!rotary);
  m_targetTiltLabel->setVisible(!rotary);
  m_targetAzimuth->setVisible(!rotary);
  m_targetAzimuthLabel->setVisible(!rotary);
  m_jogAxis->setVisible(!rotary);
  m_enable->setVisible(rotary);
}

void HardwarePanel::updateControls() {
  const DeviceSnapshot& s = m_link->snapshot();
  const bool open = m_link->isOpen();
  const bool connected = open && s.state == DeviceState::Connected;
  const bool linkUp = open && (s.state == DeviceState::Connected || s.state == DeviceState::Fault);
  const hardware::PrintRunState runState = m_run->state();
  // Manual moves would pull the platform away from the region being run; allowed when the run waits.
  const bool runHoldsDevice =
      m_run->isActive() && runState != hardware::PrintRunState::Paused && runState != hardware::PrintRunState::Faulted;
  const bool manual = connected && !runHoldsDevice;

  m_form->setEnabled(!open);
  m_connect->setEnabled(!open);
  m_disconnect->setEnabled(open);
  m_enable->setEnabled(manual);
  m_home->setEnabled(manual);
  m_jogMinus->setEnabled(manual);
  m_jogPlus->setEnabled(manual);
  m_goTo->setEnabled(manual);
  m_clearFault->setEnabled(linkUp && !runHoldsDevice);
  m_stop->setEnabled(open);
  m_estop->setEnabled(open);  // whenever there is a session, even while reconnecting

  m_startRun->setEnabled(connected && !m_planAngles.empty() && !m_run->isActive());
  m_regionDone->setEnabled(runState == hardware::PrintRunState::Printing);
  const bool pausable = runState == hardware::PrintRunState::Moving || runState == hardware::PrintRunState::Settling ||
                        runState == hardware::PrintRunState::Printing;
  m_pause->setEnabled(pausable);
  m_resume->setEnabled(runState == hardware::PrintRunState::Paused || runState == hardware::PrintRunState::Faulted);
  m_abort->setEnabled(m_run->isActive());
  updateKindWidgets();
}

void HardwarePanel::updateClockTexts() {
  const DeviceSnapshot& s = m_link->snapshot();
  if (s.state == DeviceState::Disconnected) {
    m_heartbeat->setText(QStringLiteral("—"));
  } else if (!s.lastAlive) {
    m_heartbeat->setText(tr("not seen yet"));
  } else {
    const auto age = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - *s.lastAlive);
    m_heartbeat->setText(tr("%1 s ago").arg(QLocale().toString(age.count() / 1000.0, 'f', 1)));
  }
  m_runElapsed->setText(m_run->hasRun() ? clockText(m_run->elapsed()) : QStringLiteral("—"));
  if (!m_link->isOpen() && !m_run->isActive()) m_clockTimer.stop();
}

void HardwarePanel::updateRunTexts() {
  const int regions = planRegionCount();
  m_planSummary->setText(regions == 0 ? tr("No plan: run a search or open a plan first.")
                                      : tr("Plan with %n region(s).", nullptr, regions));
  if (!m_run->hasRun()) {
    m_runStep->setText(QStringLiteral("—"));
  } else {
    const hardware::PrintRunState state = m_run->state();
    const std::size_t count = m_run->stepCount();
    if (state == hardware::PrintRunState::Completed) {
      m_runStep->setText(tr("all %n region(s) printed: finished", nullptr, static_cast<int>(count)));
    } else {
      QString text = tr("%1 of %2: %3").arg(m_run->currentStep() + 1).arg(count).arg(runStateText(state));
      if (const hardware::PrintStep* step = m_run->currentPrintStep())
        text += tr(" (%1, %2)").arg(QString::fromStdString(step->regionFile), orientationText(step->orientation));
      if (m_run->pausePending()) text += tr("; pausing after this region");
      m_runStep->setText(text);
    }
  }
  updateClockTexts();
}

}  // namespace multidir::ui
