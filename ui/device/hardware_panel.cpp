#include "ui/device/hardware_panel.h"

#include <QAction>
#include <QComboBox>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QToolBar>
#include <QVBoxLayout>
#include <chrono>
#include <filesystem>
#include <utility>

#include "ui/common/follow_newest_line.h"
#include "ui/common/machine_kind_text.h"
#include "ui/device/connection_form.h"
#include "ui/device/device_link.h"
#include "ui/device/device_reading.h"
#include "ui/device/job_timeline.h"
#include "ui/device/plan_steps.h"
#include "ui/device/print_run_driver.h"
#include "ui/device/printer_link_owner.h"
#include "ui/device/printer_section.h"
#include "ui/device/robot_cell_section.h"
#include "ui/document/studio_document.h"

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

// How to get a device going again after a fault or an E-STOP: the rotary platform's drive must be switched on
// and homed again; the robot program takes moves again once reset (the arm has no Enable, and its Home is
// only "level the platform").
QString recoveryText(DeviceKind kind) {
  return kind == DeviceKind::RotaryPlatform
             ? HardwarePanel::tr("Clear fault, then Enable and Home")
             : HardwarePanel::tr("Clear fault; the robot program then takes moves again");
}

QString clockText(std::chrono::milliseconds elapsed) {
  const long long seconds = elapsed.count() / 1000;
  return QStringLiteral("%1:%2:%3")
      .arg(seconds / 3600)
      .arg((seconds / 60) % 60, 2, 10, QLatin1Char('0'))
      .arg(seconds % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace

HardwarePanel::HardwarePanel(StudioDocument* document, QWidget* parent) : QWidget(parent), m_document(document) {
  setObjectName(QStringLiteral("hardwarePanel"));
  m_link = new DeviceLink(this);
  m_run = new PrintRunDriver(this);
  m_printerLink = new PrinterLinkOwner(this);

  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  layout->addWidget(buildConnectionGroup());
  m_statusGroup = buildStatusGroup();
  layout->addWidget(m_statusGroup);
  m_controlsGroup = buildControlsGroup();
  layout->addWidget(m_controlsGroup);
  m_message = valueLabel(content, QStringLiteral("hardwareMessage"));
  layout->addWidget(m_message);
  m_printerSection = new PrinterSection(m_printerLink, m_run, content);
  layout->addWidget(m_printerSection);
  m_runGroup = buildRunGroup();
  layout->addWidget(m_runGroup);
  // The robot cell, the connection form's device "Robot cell": its own link and run (hardware's robot run), the
  // same timeline, banner, stop line and E-STOP.
  m_robotCell = new RobotCellSection(m_document, m_timeline, content);
  layout->addWidget(m_robotCell);
  layout->addStretch(1);

  auto* scroll = new QScrollArea(this);
  scroll->setObjectName(QStringLiteral("hardwareScroll"));
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(content);
  // The banner and the safety buttons stay above the scrolled part: never below the fold.
  m_banner = valueLabel(this, QStringLiteral("linkBanner"));  // styled and shown by updateBanner()
  m_banner->hide();
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  outer->addWidget(m_banner);
  outer->addWidget(buildSafetyBar());
  m_stops = valueLabel(this, QStringLiteral("stopsText"));  // shown by updateStops() while a stop is latched
  m_stops->setContentsMargins(9, 0, 9, 0);
  m_stops->hide();
  outer->addWidget(m_stops);
  outer->addWidget(scroll, 1);

  connect(m_link, &DeviceLink::snapshotChanged, this, &HardwarePanel::onSnapshot);
  connect(m_link, &DeviceLink::commandFinished, this, &HardwarePanel::onCommandFinished);
  connect(m_link, &DeviceLink::connectFinished, this, &HardwarePanel::onConnectFinished);
  connect(m_run, &PrintRunDriver::stateChanged, this, &HardwarePanel::onRunStateChanged);
  connect(m_run, &PrintRunDriver::stateChanged, this, &HardwarePanel::updateBanner);
  connect(m_run, &PrintRunDriver::printRequested, this, &HardwarePanel::onPrintRequested);
  connect(m_run, &PrintRunDriver::currentRegionChanged, this, &HardwarePanel::currentRegionChanged);
  connect(m_run, &PrintRunDriver::logged, m_runLog, &QPlainTextEdit::appendPlainText);
  connect(m_run, &PrintRunDriver::pausedForLostLink, this, [this] {
    updateBanner();
    updateRunTexts();
    updateControls();
  });
  connect(m_run, &PrintRunDriver::runStarting, m_timeline, &JobTimeline::reset);
  connect(m_run, &PrintRunDriver::runEvent, m_timeline, &JobTimeline::apply);
  connect(m_run, &PrintRunDriver::stateChanged, m_printerSection, &PrinterSection::refresh);
  connect(m_printerLink, &PrinterLinkOwner::statusChanged, this, [this] {
    updateBanner();
    updateControls();
    updateStops();
  });
  connect(m_robotCell, &RobotCellSection::statusChanged, this, [this] {
    updateBanner();
    updateStops();
    updateControls();
  });
  connect(m_form, &ConnectionForm::kindChanged, this, [this] {
    updateKindWidgets();
    updateLimits();
  });

  m_clockTimer.setInterval(250);
  connect(&m_clockTimer, &QTimer::timeout, this, &HardwarePanel::updateClockTexts);
  connect(m_document, &StudioDocument::sessionJobChanged, this, [this] {
    updateRunTexts();
    updateControls();
  });
  connect(m_document, &StudioDocument::machineChanged, this, &HardwarePanel::onMachineChanged);
  connect(m_robotCell, &RobotCellSection::statusChanged, this, &HardwarePanel::onMachineChanged);
  onMachineChanged();

  onSnapshot(m_link->snapshot());
  updateKindWidgets();
  updateLimits();
  updateRunTexts();
}

HardwarePanel::~HardwarePanel() {
  // The run and the link report while they shut down; as children they would outlive this panel's members
  // (QWidget deletes children last), so they go first, without reporting to it. The run first: it holds
  // the link's positioner.
  QObject::disconnect(m_run, nullptr, nullptr, nullptr);
  QObject::disconnect(m_link, nullptr, this, nullptr);
  QObject::disconnect(m_printerLink, nullptr, nullptr, nullptr);
  delete m_run;
  delete m_link;
  delete m_printerLink;
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
  m_enabled = valueLabel(group, QStringLiteral("enabledValue"));
  m_position = valueLabel(group, QStringLiteral("positionValue"));
  m_moving = valueLabel(group, QStringLiteral("movingValue"));
  m_homed = valueLabel(group, QStringLiteral("homedValue"));
  m_fault = valueLabel(group, QStringLiteral("faultValue"));
  m_heartbeat = valueLabel(group, QStringLiteral("heartbeatValue"));
  m_linkProblem = valueLabel(group, QStringLiteral("linkProblemValue"));
  auto* form = new QFormLayout(group);
  m_statusForm = form;
  form->addRow(tr("State:"), m_state);
  // The rotary platform's drive must be switched on before it homes or moves; the arm has no such step.
  form->addRow(tr("Enabled:"), m_enabled);
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

  connect(m_enable, &QPushButton::clicked, m_link, &DeviceLink::enable);
  connect(m_home, &QPushButton::clicked, m_link, &DeviceLink::home);
  connect(m_clearFault, &QPushButton::clicked, m_link, &DeviceLink::clearFault);
  connect(m_jogMinus, &QPushButton::clicked, this, [this] { jog(-1.0); });
  connect(m_jogPlus, &QPushButton::clicked, this, [this] { jog(1.0); });
  connect(m_goTo, &QPushButton::clicked, this, &HardwarePanel::goTo);
  return group;
}

QWidget* HardwarePanel::buildSafetyBar() {
  auto* bar = new QWidget(this);
  bar->setObjectName(QStringLiteral("safetyBar"));
  m_stop = button(bar, QStringLiteral("stopButton"), tr("Stop"), tr("Decelerates and stops; cancels queued commands."));
  m_estop = button(bar, QStringLiteral("estopButton"), tr("E-STOP"));
  styleEmergencyStop(m_estop);
  m_estop->setMinimumHeight(48);
  m_stop->setMinimumHeight(48);
  auto* layout = new QHBoxLayout(bar);
  layout->setContentsMargins(9, 6, 9, 6);
  layout->addWidget(m_stop, 1);
  layout->addWidget(m_estop, 2);
  connect(m_stop, &QPushButton::clicked, m_link, &DeviceLink::stop);
  connect(m_estop, &QPushButton::clicked, this, &HardwarePanel::emergencyStopAll);
  return bar;
}

void HardwarePanel::styleEmergencyStop(QPushButton* estop) const {
  estop->setStyleSheet(
      QStringLiteral("QPushButton { background-color: #c62828; color: white; font-weight: bold; font-size: 16pt; "
                     "padding: 4px 12px; }"
                     "QPushButton:disabled { background-color: #e0a0a0; color: #f5f5f5; }"));
}

QAction* HardwarePanel::addEmergencyStopTo(QToolBar* bar) {
  m_windowEstop = button(bar, QStringLiteral("windowEstopButton"), tr("E-STOP"));
  styleEmergencyStop(m_windowEstop);
  connect(m_windowEstop, &QPushButton::clicked, this, &HardwarePanel::emergencyStopAll);
  m_windowEstopAction = bar->addWidget(m_windowEstop);
  updateKindWidgets();
  updateControls();
  return m_windowEstopAction;
}

QGroupBox* HardwarePanel::buildRunGroup() {
  auto* group = new QGroupBox(tr("Print run"), this);
  m_planSummary = valueLabel(group, QStringLiteral("planSummaryText"));
  m_startRun = button(group, QStringLiteral("startRunButton"), tr("Start run"),
                      tr("Turns the platform to each region's orientation in printing order and asks for each "
                         "region to be printed."));
  // Why Start run was refused, right under the button the operator just pressed (the panel's message line is
  // far above it, often out of view).
  m_startRunRefusal = valueLabel(group, QStringLiteral("startRunRefusal"));
  m_startRunRefusal->setStyleSheet(QStringLiteral("color: #c62828;"));
  m_startRunRefusal->hide();
  m_runStep = valueLabel(group, QStringLiteral("runStepText"));
  m_runElapsed = valueLabel(group, QStringLiteral("runElapsedText"));
  m_prompt = valueLabel(group, QStringLiteral("runPrompt"));
  QFont bold = m_prompt->font();
  bold.setBold(true);
  bold.setPointSizeF(bold.pointSizeF() * 1.2);
  m_prompt->setFont(bold);
  m_regionDone = button(group, QStringLiteral("regionDoneButton"), tr("Region done"),
                        tr("Press when the region asked for has been printed (by hand: a region the connected "
                           "printer prints goes on by itself)."));
  m_pause = button(group, QStringLiteral("pauseButton"), tr("Pause"));
  m_resume = button(group, QStringLiteral("resumeButton"), tr("Resume"),
                    tr("Continues a paused run, or retries the current step after a device problem."));
  m_abort = button(group, QStringLiteral("abortButton"), tr("Abort"));
  // The printer lost the interrupted step's job (it restarted): said right under Resume, which can do nothing.
  m_jobGone = valueLabel(group, QStringLiteral("runJobGoneText"));
  m_jobGone->setStyleSheet(QStringLiteral("color: #c62828;"));
  m_jobGone->hide();
  m_restartStep = button(group, QStringLiteral("restartStepButton"), tr("Restart step"),
                         tr("Prints the current step again from the start of its G-code, once you have cleared "
                            "the platform of what the interrupted print left."));
  m_restartStep->hide();
  m_timeline = new JobTimeline(group);
  m_runLog = new QPlainTextEdit(group);
  m_runLog->setObjectName(QStringLiteral("runLog"));
  m_runLog->setReadOnly(true);
  m_runLog->setMaximumBlockCount(1000);
  m_runLog->setMinimumHeight(80);
  new FollowNewestLine(m_runLog);  // the newest line in view, unless the operator scrolled up

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
  layout->addWidget(m_startRunRefusal);
  layout->addLayout(form);
  layout->addWidget(m_prompt);
  layout->addLayout(buttons);
  layout->addWidget(m_jobGone);
  layout->addWidget(m_restartStep);
  layout->addWidget(m_timeline);
  layout->addWidget(m_runLog);

  connect(m_startRun, &QPushButton::clicked, this, &HardwarePanel::startRun);
  connect(m_regionDone, &QPushButton::clicked, this, [this] { runEvent(tr("Region done"), m_run->regionDone()); });
  connect(m_pause, &QPushButton::clicked, this, [this] { runEvent(tr("Pause"), m_run->pause()); });
  connect(m_resume, &QPushButton::clicked, this, [this] { runEvent(tr("Resume"), m_run->resume()); });
  connect(m_abort, &QPushButton::clicked, this, [this] { runEvent(tr("Abort"), m_run->abort()); });
  connect(m_restartStep, &QPushButton::clicked, this, &HardwarePanel::restartStep);
  connect(m_run, &PrintRunDriver::printerJobGoneChanged, this, &HardwarePanel::updateJobGone);
  return group;
}

QString HardwarePanel::messageText() const { return m_message->text(); }

QString HardwarePanel::promptText() const { return m_prompt->text(); }

QString HardwarePanel::bannerText() const { return m_banner->isHidden() ? QString() : m_banner->text(); }

void HardwarePanel::updateBanner() {
  const DeviceSnapshot& s = m_link->snapshot();
  const bool open = m_link->isOpen();
  const bool held = m_run->isActive() && m_run->heldForLostLink();
  QString text;
  bool alarm = true;
  if (open && s.staleSince) {
    text = tr("The link to %1 was lost at %2. The values below are not the device's any more; MultiDir keeps "
              "trying to reconnect.")
               .arg(m_link->deviceName(), DeviceReading::clockTime(*s.staleSince));
    if (held)
      text += QLatin1Char(' ') + tr("The print run is paused: a region being printed may finish, no new region "
                                    "starts. Press Resume once the link is back.");
  } else if (open && !s.hasRead && !s.lastError.isEmpty()) {
    text = tr("%1 does not answer: %2").arg(m_link->deviceName(), s.lastError);
  } else if (held) {
    alarm = false;
    text = tr("The link is back. The print run is still paused since the link was lost: check the platform, "
              "then press Resume.");
  }
  for (const QString& lost : {m_printerSection->linkLostText(), m_robotCell->linkLostText()}) {
    if (lost.isEmpty()) continue;
    text = text.isEmpty() ? lost : text + QLatin1Char('\n') + lost;
    alarm = true;
  }
  m_banner->setText(text);
  m_banner->setStyleSheet(QStringLiteral("QLabel#linkBanner { background-color: %1; color: %2; font-weight: bold; "
                                         "padding: 8px; }")
                              .arg(alarm ? QStringLiteral("#c62828") : QStringLiteral("#ffb300"),
                                   alarm ? QStringLiteral("white") : QStringLiteral("black")));
  m_banner->setVisible(!text.isEmpty());
}

core::MachineSpec HardwarePanel::machineForNextConnection() const {
  return machineForDevice(m_form->kind(), m_document->machine());
}

int HardwarePanel::planRegionCount() const {
  const PrintJob job = m_document->sessionJob();
  return job.plan ? static_cast<int>(job.plan->regions.size()) : 0;
}

std::vector<StepGcode> HardwarePanel::jobGcode() const { return m_document->sessionJob().steps; }

void HardwarePanel::setPrinterLinkOptions(const hardware::PrinterLinkOptions& options) {
  m_printerLink->setLinkOptions(options);
}

void HardwarePanel::emergencyStopAll() {
  // Both devices first, before anything else: through the run when one is under way (it sends both stops at
  // once and ends Aborted), else each device's own emergency stop.
  const bool active = m_run->isActive();
  const bool runStopsPrinter = active && m_run->hasPrinter();
  if (active)
    (void)m_run->emergencyStop();
  else if (m_link->isOpen())
    m_link->emergencyStop();
  if (!runStopsPrinter && m_printerLink->isOpen()) m_printerLink->emergencyStop();
  const bool robotOpen = m_robotCell->isConnected();
  if (robotOpen) m_robotCell->emergencyStop();
  QStringList devices;
  if (m_link->isOpen() || active) devices << tr("the platform");
  if (m_printerLink->isOpen()) devices << tr("the printer");
  if (robotOpen) devices << tr("the robot cell");
  if (!devices.isEmpty())
    setMessage(tr("E-STOP sent to %1. To go on: %2%3.")
                   .arg(devices.join(tr(" and ")), recoveryText(m_link->settings().kind),
                        m_printerLink->isOpen() ? tr("; for the printer, Clear printer E-STOP and restart its firmware")
                                                : QString()),
               false);
  updateStops();
  updateRunTexts();
  updateControls();
}

QString HardwarePanel::stopsText() const { return m_stops->isHidden() ? QString() : m_stops->text(); }

void HardwarePanel::updateStops() {
  QStringList lines;
  if (const std::shared_ptr<hardware::Positioner> positioner = m_link->positioner()) {
    const hardware::PositionerSnapshot p = positioner->snapshot();
    if (p.stopLatched)
      lines << (p.stopConfirmed ? tr("Platform: stop confirmed by the device.")
                                : tr("Platform: stop not confirmed yet; MultiDir keeps resending it."));
  }
  if (m_printerLink->isOpen()) {
    const hardware::StopLatch& stop = m_printerLink->status().stop;
    if (stop.latched())
      lines << (stop.confirmed ? tr("Printer: emergency stop confirmed by the printer.")
                               : tr("Printer: emergency stop not confirmed yet (%1); MultiDir keeps resending it.")
                                     .arg(QString::fromStdString(stop.problem)));
  }
  if (const QString robot = m_robotCell->stopText(); !robot.isEmpty()) lines << robot;
  m_stops->setText(lines.join(QLatin1Char('\n')));
  m_stops->setVisible(!lines.isEmpty());
}

void HardwarePanel::onMachineChanged() {
  // The device choice follows the machine the plans are made for when its kind changes; any other edit of the
  // machine (and Connect) leaves the device, transport and unit the operator chose as they are. An open
  // session keeps its device.
  const MachineFollowed machine{m_document->machine().kind, m_document->machineIsRobotCell()};
  if (machine != m_followedMachine && !m_link->isOpen() && !m_robotCell->isConnected()) {
    if (machine.robotCell) m_form->setKind(DeviceKind::RobotCell);
    else if (machine.kind == core::MachineKind::RotaryPlatform) m_form->setKind(DeviceKind::RotaryPlatform);
    else if (machine.kind == core::MachineKind::TiltRotate) m_form->setKind(DeviceKind::RobotArm);
    m_followedMachine = machine;
  }
  updateLimits();
}

void HardwarePanel::connectDevice() {
  if (m_form->kind() == DeviceKind::RobotCell) {  // not a Modbus device: the cell's section connects it
    m_robotCell->connectRobot();
    return;
  }
  DeviceLinkSettings settings;
  settings.kind = m_form->kind();
  settings.connection = m_form->settings();
  settings.rotarySpeedDegreesPerSecond = m_form->rotarySpeedDegreesPerSecond();
  settings.robotSpeedPercent = m_form->robotSpeedPercent();
  settings.machine = machineForDevice(settings.kind, m_document->machine(), &m_linkUsesProfile);
  const core::Status started = m_link->connectDevice(settings);
  if (!started.ok()) {
    setMessage(tr("Cannot connect with these settings: %1").arg(QString::fromStdString(started.error().describe())),
               true);
    return;
  }
  if (settings.connection.transport == hardware::Transport::Tcp) m_form->rememberTcpAddress();  // the next session's
  setMessage(tr("Connecting to %1…").arg(m_link->deviceName()), false);
  m_clockTimer.start();
  updateLimits();
  emit sessionOpenChanged(true);
}

void HardwarePanel::disconnectDevice() {
  m_link->disconnectDevice();
  if (!m_run->isActive()) m_clockTimer.stop();
  setMessage(tr("Disconnected."), false);
  updateLimits();
  emit sessionOpenChanged(false);
}

void HardwarePanel::onSnapshot(const DeviceSnapshot& s) {
  const bool open = s.state != DeviceState::Disconnected;
  if (!open) {
    m_state->setText(stateText(s));
  } else if (!s.hasRead && !s.lastError.isEmpty()) {
    m_state->setText(tr("Not reachable; MultiDir keeps trying…"));
  } else if (s.staleSince) {
    m_state->setText(tr("Link lost at %1; reconnecting…").arg(DeviceReading::clockTime(*s.staleSince)));
  } else {
    m_state->setText(stateText(s));
  }

  QString enabled;
  QString position;
  QString moving;
  QString homed;
  if (s.kind == DeviceKind::RotaryPlatform) {
    enabled = s.enabled ? tr("yes") : tr("no: press Enable");
    position = tr("%1 (target %2)").arg(degrees(s.angleDegrees), degrees(s.targetAngleDegrees));
    moving = s.homing ? tr("homing") : s.moving ? tr("yes") : tr("no");
    homed = s.homed ? tr("yes") : tr("no");
  } else {
    position = tr("tilt %1, azimuth %2").arg(degrees(s.tiltDegrees), degrees(s.azimuthDegrees));
    moving = s.moving ? tr("yes") : tr("no");
    homed = tr("not needed (robot arm)");
  }
  const QString fault = s.faultText.isEmpty() ? tr("none") : s.faultText;
  const std::pair<QLabel*, QString> fields[] = {
      {m_enabled, enabled}, {m_position, position}, {m_moving, moving}, {m_homed, homed}, {m_fault, fault}};
  for (const auto& [label, value] : fields) DeviceReading::show(label, value, open, s.hasRead, s.staleSince);
  if (s.isFresh() && !s.faultText.isEmpty()) m_fault->setStyleSheet(QString::fromLatin1(DeviceReading::kFaultStyle));
  m_linkProblem->setText(s.lastError.isEmpty() ? tr("none") : s.lastError);
  m_linkProblem->setStyleSheet(s.lastError.isEmpty() ? QString() : QString::fromLatin1(DeviceReading::kFaultStyle));
  // The link dropped: what the panel said before (a command sent, a run finished) is no longer the news.
  if (s.staleSince && !m_wasStale && m_messageTopic == MessageTopic::General) m_message->clear();
  m_wasStale = s.staleSince.has_value();
  updateBanner();
  updateClockTexts();
  updateControls();
}

void HardwarePanel::onCommandFinished(const QString& command, bool ok, const QString& problem) {
  if (!ok) {
    setMessage(problem, true);
  } else if (command == DeviceLink::tr("E-STOP")) {  // the name DeviceLink gave the command
    setMessage(tr("%1: sent to the device. To go on: %2.").arg(command, recoveryText(m_link->settings().kind)), false);
  } else {
    setMessage(tr("%1: sent to the device.").arg(command), false);
  }
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
    setMessage(tr("The print run stopped: %1. Fix the device (%2), then press Resume to retry this step, or Abort.")
                   .arg(m_run->lastProblem(), recoveryText(m_link->settings().kind)),
               true, MessageTopic::Run);
  else if (state == hardware::PrintRunState::Completed)
    setMessage(tr("The print run is finished: every region was printed."), false, MessageTopic::Run);
  else if (state == hardware::PrintRunState::Aborted)
    setMessage(tr("The print run was aborted."), false, MessageTopic::Run);
  else if (m_messageTopic == MessageTopic::Run)
    m_message->clear();  // the run went on: the previous run's outcome or stop no longer applies
  if (m_run->isActive()) m_clockTimer.start();
  // An aborted run can be resumed from the first step it did not finish, while the job is the same one.
  if (state == hardware::PrintRunState::Aborted)
    m_aborted = AbortedRun{m_document->sessionJob().plan, m_run->currentStep(), m_run->stepCount()};
  else if (state == hardware::PrintRunState::Completed)
    m_aborted.reset();
  // The run is over (finished, aborted): the session's job follows the plan shown again.
  if (!m_run->isActive()) m_document->unpinSessionJob();
  updateRunTexts();
  updateControls();
}

void HardwarePanel::onPrintRequested(int region, const QString& regionFile) {
  if (m_run->currentStepUsesPrinter())
    m_prompt->setText(tr("Region %1 is printed by %2 (%3); the run goes on when the printer reports it complete.")
                          .arg(region + 1)
                          .arg(m_printerLink->printerName(),
                               QString::fromStdString(m_run->currentPrintStep()->gcodePath)));
  else
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

bool HardwarePanel::isRunUnderWay() const { return m_run->isActive() || m_robotCell->isRunUnderWay(); }

QString HardwarePanel::runStepText() const {
  return m_robotCell->isRunUnderWay() ? m_robotCell->runStepText() : m_runStep->text();
}

void HardwarePanel::stopDevicesForQuit() {
  if (m_run->isActive()) runEvent(tr("Abort"), m_run->abort());
  if (m_link->isOpen()) m_link->stop();
  // The robot run ends through its stop (latched until the robot confirms it); the section waits for it, so
  // no run is under way when the unsaved-changes question comes.
  m_robotCell->stopForQuit();
}

std::optional<std::size_t> HardwarePanel::resumableStep() const {
  if (!m_aborted || !m_aborted->plan || m_aborted->plan != m_document->sessionJob().plan) return std::nullopt;
  return m_aborted->firstStepNotDone;
}

void HardwarePanel::startRun() {
  const std::optional<std::size_t> resumable = resumableStep();
  if (!resumable || !m_link->isOpen()) {
    startRunFrom(0);
    return;
  }
  // After an abort the platform may hold a half-printed region or whatever stopped the run: the operator
  // confirms it is clear before anything moves, and chooses where to go on from.
  const auto step = static_cast<int>(*resumable) + 1;
  auto* box = new QMessageBox(QMessageBox::Question, tr("Start Run"),
                              tr("The last run of this plan was aborted at step %1 of %2.")
                                  .arg(step)
                                  .arg(static_cast<int>(m_aborted->stepCount)),
                              QMessageBox::NoButton, this);
  box->setObjectName(QStringLiteral("restartRunBox"));
  box->setInformativeText(
      step > 1 ? tr("Steps 1 to %1 were printed. Before the platform moves, make sure it is clear: take off what "
                    "step %2 left half printed and anything in the platform's way.")
                     .arg(step - 1)
                     .arg(step)
               : tr("Before the platform moves, make sure it is clear: take off what step 1 left half printed and "
                    "anything in the platform's way."));
  QPushButton* resume = nullptr;
  if (step > 1) {
    resume = box->addButton(tr("Platform Clear: &Resume from Step %1").arg(step), QMessageBox::AcceptRole);
    resume->setObjectName(QStringLiteral("resumeFromStepButton"));
  }
  QPushButton* restart = box->addButton(tr("Platform Clear: &Start from Step 1"), QMessageBox::AcceptRole);
  restart->setObjectName(QStringLiteral("startFromFirstStepButton"));
  box->addButton(QMessageBox::Cancel);
  box->setDefaultButton(QMessageBox::Cancel);
  box->setWindowModality(Qt::WindowModal);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [this, box, resume, restart, first = *resumable] {
    const QAbstractButton* clicked = box->clickedButton();
    if (clicked == nullptr || (clicked != resume && clicked != restart)) return;
    const std::size_t from = clicked == resume ? first : 0;
    QTimer::singleShot(0, this, [this, from] {
      // The job may have changed while the question was open: a resume is only for the job it was asked of.
      if (from > 0 && resumableStep() != from) {
        refuseStart(tr("Start run refused: the plan changed since the question was asked; press Start run again."));
        return;
      }
      startRunFrom(from);
    });
  });
  box->open();
}

void HardwarePanel::updateJobGone() {
  const bool gone = m_run->interruptedJobGone();
  if (gone) {
    const auto step = static_cast<int>(m_run->currentStep()) + 1;
    m_jobGone->setText(tr("%1 has no job of step %2 any more: it may have restarted, so there is nothing to "
                          "resume. Restart step prints step %2 again from its start, once you have cleared the "
                          "platform of what the interrupted print left. Or finish the region by hand and press "
                          "Region done, or Abort.")
                           .arg(m_printerLink->printerName())
                           .arg(step));
    m_restartStep->setText(tr("Restart Step %1").arg(step));
  }
  m_jobGone->setVisible(gone);
  m_restartStep->setVisible(gone);
  m_restartStep->setEnabled(gone);
}

void HardwarePanel::restartStep() {
  if (!m_run->interruptedJobGone()) return;
  const auto step = static_cast<int>(m_run->currentStep()) + 1;
  auto* box = new QMessageBox(QMessageBox::Question, tr("Restart Step"),
                              tr("Print step %1 again from its start?").arg(step), QMessageBox::NoButton, this);
  box->setObjectName(QStringLiteral("restartStepBox"));
  box->setInformativeText(tr("The printer lost the job of step %1 part way. Before it prints the step again, "
                             "take off what the interrupted print left of region %1 (the regions printed before "
                             "it stay) and make sure the nozzle's way is clear.")
                              .arg(step));
  QPushButton* confirm = box->addButton(tr("Platform Clear: &Restart Step %1").arg(step), QMessageBox::AcceptRole);
  confirm->setObjectName(QStringLiteral("restartStepConfirm"));
  box->addButton(QMessageBox::Cancel);
  box->setDefaultButton(QMessageBox::Cancel);
  box->setWindowModality(Qt::WindowModal);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [this, box, confirm, step] {
    if (box->clickedButton() != confirm) return;
    QTimer::singleShot(0, this, [this, step] {
      // The run may have moved on while the question was open: only the step it was asked of is restarted.
      if (static_cast<int>(m_run->currentStep()) + 1 != step) return;
      runEvent(tr("Restart step"), m_run->restartStep());
    });
  });
  box->open();
}

void HardwarePanel::refuseStart(const QString& text) {
  setMessage(text, true);
  m_startRunRefusal->setText(text);
  m_startRunRefusal->show();
}

void HardwarePanel::startRunFrom(std::size_t firstStep) {
  m_startRunRefusal->hide();
  if (!m_link->isOpen()) {
    refuseStart(tr("Start run refused: not connected; connect to the device first."));
    return;
  }
  // The limits the driver enforces are those it was connected with; the job is the document's, pinned there
  // for as long as the run lasts.
  const DeviceLinkSettings& settings = m_link->settings();
  const core::Result<PrintJob> pinned = m_document->pinSessionJob();
  if (!pinned) {
    refuseStart(tr("Start run refused: %1").arg(QString::fromStdString(pinned.error().message)));
    return;
  }
  const PrintJob& job = pinned.value();
  auto steps = printSteps(regionTargets(*job.plan), settings.kind, settings.machine);
  if (!steps) {
    m_document->unpinSessionJob();
    refuseStart(tr("Start run refused: %1").arg(QString::fromStdString(steps.error().message)));
    return;
  }
  // The printer prints the regions when it is connected and the sliced job has G-code for every region.
  std::shared_ptr<hardware::PrinterLink> printer = m_printerLink->link();
  const bool gcodeFits = !job.steps.empty() && job.steps.size() == steps->size();
  std::vector<double> estimates;
  if (gcodeFits) {
    for (std::size_t k = 0; k < steps->size(); ++k) {
      (*steps)[k].gcodePath = job.steps[k].path;
      (*steps)[k].regionFile = std::filesystem::path(job.steps[k].path).filename().string();
      estimates.push_back(job.steps[k].estimateSeconds);
    }
  }
  m_runLog->clear();
  m_prompt->clear();
  if (m_messageTopic == MessageTopic::Run) m_message->clear();
  m_printerSection->setRunEstimates(estimates);
  m_runFiles = gcodeFits ? job.files : nullptr;
  const core::Status started = m_run->start(m_link->positioner(), std::move(steps.value()), m_runOptions,
                                            gcodeFits ? printer : nullptr, firstStep);
  if (!started.ok() || !m_run->isActive()) m_document->unpinSessionJob();
  if (!started.ok()) refuseStart(tr("Start run refused: %1").arg(QString::fromStdString(started.error().message)));
  runEvent(tr("Start run"), started);
  if (started.ok() && printer && !gcodeFits)
    setMessage(job.steps.empty()
                   ? tr("The plan is not sliced: each region is printed by hand (Region done). Slice the plan "
                        "to have the printer print them.")
                   : tr("The sliced job has %1 steps, the plan %2 regions: each region is printed by hand "
                        "(Region done). Slice the plan again.")
                         .arg(job.steps.size())
                         .arg(job.plan->regions.size()),
               false, MessageTopic::Run);
}

void HardwarePanel::runEvent(const QString& event, const core::Status& status) {
  if (!status.ok()) setMessage(tr("%1 refused: %2").arg(event, QString::fromStdString(status.error().message)), true);
  updateRunTexts();
  updateControls();
}

void HardwarePanel::setMessage(const QString& text, bool error, MessageTopic topic) {
  m_message->setText(text);
  m_messageIsError = error;
  m_messageTopic = topic;
  m_message->setStyleSheet(error ? QStringLiteral("color: #c62828;") : QString());
}

void HardwarePanel::updateLimits() {
  const bool open = m_link->isOpen();
  const DeviceKind kind = open ? m_link->settings().kind : m_form->kind();
  bool fromProfile = m_linkUsesProfile;
  const core::MachineSpec& machine = m_document->machine();
  const core::MachineSpec spec = open ? m_link->settings().machine : machineForDevice(kind, machine, &fromProfile);
  QString limits =
      kind == DeviceKind::RotaryPlatform
          ? tr("Limits: %1 to %2 in steps of %3")
                .arg(degrees(spec.minAngleDegrees), degrees(spec.maxAngleDegrees), degrees(spec.angleStepDegrees))
          : tr("Limits: tilt up to %1, %n forbidden cone(s)", nullptr, static_cast<int>(spec.forbiddenCones.size()))
                .arg(degrees(spec.maxTiltDegrees));
  if (fromProfile)
    limits += tr(" (machine profile)");
  else
    limits += tr(" (defaults: the machine profile is for a %1 machine)")
                  .arg(machineKindText(machine.kind));
  if (open) limits += tr("; a changed profile applies at the next Connect");
  m_limits->setText(limits);
}

void HardwarePanel::updateKindWidgets() {
  const DeviceKind kind = m_link->isOpen() ? m_link->settings().kind : m_form->kind();
  const bool rotary = kind == DeviceKind::RotaryPlatform;
  // The robot cell chosen: its section (address, job, run controls) in place of the Modbus device's connect
  // buttons, status, controls and print run, and of the printer (the cell's extruder follows its program). A
  // connected cell stays in view whatever is chosen.
  const bool cell = kind == DeviceKind::RobotCell;
  for (QWidget* modbusOnly : std::initializer_list<QWidget*>{m_limits, m_connect, m_disconnect, m_statusGroup,
                                                             m_controlsGroup, m_runGroup, m_printerSection})
    modbusOnly->setVisible(!cell);
  m_robotCell->setVisible(cell || m_robotCell->isConnected() || m_robotCell->isRunUnderWay());
  m_targetAngle->setVisible(rotary);
  m_targetAngleLabel->setVisible(rotary);
  m_targetTilt->setVisible(!rotary);
  m_targetTiltLabel->setVisible(!rotary);
  m_targetAzimuth->setVisible(!rotary);
  m_targetAzimuthLabel->setVisible(!rotary);
  m_jogAxis->setVisible(!rotary);
  m_enable->setVisible(rotary);
  m_statusForm->setRowVisible(m_enabled, rotary);
  // What to do after a fault or an E-STOP depends on the device: say only what applies to it.
  const QString recovery = recoveryText(kind);
  const QString estopTip = rotary ? tr("Emergency stop: cuts the platform's power stage at once. Afterwards: %1.")
                                        .arg(recovery)
                                  : tr("Emergency stop: halts the robot program at maximal deceleration. "
                                       "Afterwards: %1.")
                                        .arg(recovery);
  m_estop->setToolTip(estopTip);
  if (m_windowEstop) m_windowEstop->setToolTip(estopTip);
  m_clearFault->setToolTip(rotary ? tr("Resets the platform after a fault or an E-STOP; then Enable and Home again.")
                                  : tr("Resets the robot program after a fault or an E-STOP; it then takes moves "
                                       "again."));
  m_home->setToolTip(rotary ? tr("Finds the home switch (0°); the drive must be enabled.")
                            : tr("Levels the platform (tilt 0°)."));
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

  // The device choice stays while a device (the cell included) has a session.
  m_form->setEnabled(!open && !m_robotCell->isConnected() && !m_robotCell->isRunUnderWay());
  m_connect->setEnabled(!open);
  m_disconnect->setEnabled(open);
  m_enable->setEnabled(manual);
  m_home->setEnabled(manual);
  m_jogMinus->setEnabled(manual);
  m_jogPlus->setEnabled(manual);
  m_goTo->setEnabled(manual);
  m_clearFault->setEnabled(linkUp && !runHoldsDevice);
  m_stop->setEnabled(open);
  // Whenever either device has a session, even while reconnecting.
  const bool anyOpen = open || m_printerLink->isOpen() || m_robotCell->isConnected();
  m_estop->setEnabled(anyOpen);
  if (m_windowEstop) m_windowEstop->setEnabled(anyOpen);
  if (m_windowEstopAction) m_windowEstopAction->setVisible(anyOpen);

  m_startRun->setEnabled(connected && planRegionCount() > 0 && !m_run->isActive());
  // By hand: a region without a printer, or one whose print the printer interrupted (finished by hand).
  m_regionDone->setEnabled((runState == hardware::PrintRunState::Printing && !m_run->currentStepUsesPrinter()) ||
                           (runState == hardware::PrintRunState::Paused && m_run->printInterrupted()));
  const bool pausable = runState == hardware::PrintRunState::Moving || runState == hardware::PrintRunState::Settling ||
                        runState == hardware::PrintRunState::Printing;
  m_pause->setEnabled(pausable);
  m_resume->setEnabled(runState == hardware::PrintRunState::Paused || runState == hardware::PrintRunState::Faulted);
  m_abort->setEnabled(m_run->isActive());
  updateKindWidgets();
}

void HardwarePanel::updateClockTexts() {
  const DeviceSnapshot& s = m_link->snapshot();
  m_heartbeat->setStyleSheet(s.staleSince ? QString::fromLatin1(DeviceReading::kStaleStyle) : QString());
  if (s.state == DeviceState::Disconnected) {
    m_heartbeat->setText(QStringLiteral("—"));
  } else if (s.staleSince) {
    m_heartbeat->setText(tr("unknown since %1").arg(DeviceReading::clockTime(*s.staleSince)));
  } else if (!s.lastAlive) {
    m_heartbeat->setText(tr("not seen yet"));
  } else {
    const auto age = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - *s.lastAlive);
    m_heartbeat->setText(tr("%1 s ago").arg(QLocale().toString(age.count() / 1000.0, 'f', 1)));
  }
  m_runElapsed->setText(m_run->hasRun() ? clockText(m_run->elapsed()) : QStringLiteral("—"));
  updateStops();
  if (!m_link->isOpen() && !m_run->isActive()) m_clockTimer.stop();
}

void HardwarePanel::updateRunTexts() {
  const int regions = planRegionCount();
  QString summary = regions == 0 ? tr("No plan: run a search or open a plan first.")
                                 : tr("Plan with %n region(s).", nullptr, regions);
  if (regions > 0 && static_cast<int>(jobGcode().size()) == regions)
    summary += QLatin1Char(' ') + tr("Sliced: a connected printer prints each region's G-code.");
  m_planSummary->setText(summary);
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
