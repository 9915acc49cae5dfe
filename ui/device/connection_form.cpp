#include "ui/device/connection_form.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QIntValidator>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include "multidir/hardware/robot_arm.h"
#include "multidir/hardware/rotary_platform.h"

namespace multidir::ui {
namespace {

QSpinBox* spinBox(QWidget* parent, const QString& name, int low, int high, int value, const QString& suffix = {}) {
  auto* box = new QSpinBox(parent);
  box->setObjectName(name);
  box->setRange(low, high);
  box->setValue(value);
  box->setSuffix(suffix);
  return box;
}

}  // namespace

ConnectionForm::ConnectionForm(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("connectionForm"));
  const hardware::ConnectionSettings defaults;

  m_kind = new QComboBox(this);
  m_kind->setObjectName(QStringLiteral("deviceKind"));
  m_kind->addItem(tr("Rotary platform (4-DOF)"), static_cast<int>(DeviceKind::RotaryPlatform));
  m_kind->addItem(tr("Robot arm (5-DOF)"), static_cast<int>(DeviceKind::RobotArm));
  // Short in the list, so that the dock keeps its width on a small screen; the whole description as its tip.
  m_kind->addItem(tr("Robot cell (5-DOF, fixed extruder)"), static_cast<int>(DeviceKind::RobotCell));
  m_kind->setItemData(m_kind->count() - 1,
                      tr("Robot cell (5-DOF, Universal Robots: the arm carries the part under a fixed extruder)"),
                      Qt::ToolTipRole);

  m_transport = new QComboBox(this);
  m_transport->setObjectName(QStringLiteral("transport"));
  m_transport->addItem(tr("Modbus TCP"), static_cast<int>(hardware::Transport::Tcp));
  m_transport->addItem(tr("Modbus RTU (serial)"), static_cast<int>(hardware::Transport::Rtu));

  auto* tcpPage = new QWidget(this);
  auto* tcpForm = new QFormLayout(tcpPage);
  tcpForm->setContentsMargins(0, 0, 0, 0);
  m_host = new QLineEdit(QString::fromStdString(defaults.tcp.host), tcpPage);
  m_host->setObjectName(QStringLiteral("tcpHost"));
  m_port = spinBox(tcpPage, QStringLiteral("tcpPort"), 1, 65535, defaults.tcp.port);
  m_unit = spinBox(tcpPage, QStringLiteral("tcpUnit"), 0, 255, defaults.slaveId);
  tcpForm->addRow(tr("Host:"), m_host);
  tcpForm->addRow(tr("Port:"), m_port);
  tcpForm->addRow(tr("Unit id:"), m_unit);

  auto* rtuPage = new QWidget(this);
  auto* rtuForm = new QFormLayout(rtuPage);
  rtuForm->setContentsMargins(0, 0, 0, 0);
  m_serialDevice = new QLineEdit(QString::fromStdString(defaults.rtu.device), rtuPage);
  m_serialDevice->setObjectName(QStringLiteral("serialPort"));
  m_baud = new QComboBox(rtuPage);
  m_baud->setObjectName(QStringLiteral("baud"));
  m_baud->setEditable(true);
  m_baud->setValidator(new QIntValidator(1, 4000000, m_baud));
  for (int baud : {9600, 19200, 38400, 57600, 115200, 230400}) m_baud->addItem(QString::number(baud));
  m_baud->setCurrentText(QString::number(defaults.rtu.baud));
  m_parity = new QComboBox(rtuPage);
  m_parity->setObjectName(QStringLiteral("parity"));
  m_parity->addItem(tr("None"), static_cast<int>(hardware::Parity::None));
  m_parity->addItem(tr("Even"), static_cast<int>(hardware::Parity::Even));
  m_parity->addItem(tr("Odd"), static_cast<int>(hardware::Parity::Odd));
  m_dataBits = spinBox(rtuPage, QStringLiteral("dataBits"), 5, 8, defaults.rtu.dataBits);
  m_stopBits = spinBox(rtuPage, QStringLiteral("stopBits"), 1, 2, defaults.rtu.stopBits);
  m_slave = spinBox(rtuPage, QStringLiteral("rtuSlave"), 1, 247, defaults.slaveId);
  rtuForm->addRow(tr("Serial port:"), m_serialDevice);
  rtuForm->addRow(tr("Baud:"), m_baud);
  rtuForm->addRow(tr("Parity:"), m_parity);
  rtuForm->addRow(tr("Data bits:"), m_dataBits);
  rtuForm->addRow(tr("Stop bits:"), m_stopBits);
  rtuForm->addRow(tr("Slave id:"), m_slave);

  m_transportPages = new QStackedWidget(this);
  m_transportPages->addWidget(tcpPage);
  m_transportPages->addWidget(rtuPage);

  m_responseTimeout = spinBox(this, QStringLiteral("responseTimeout"), 10, 60000,
                              static_cast<int>(defaults.responseTimeout.count()), tr(" ms"));
  m_responseTimeout->setToolTip(tr("How long to wait for the first byte of a reply, and for a TCP connection."));
  m_byteTimeout =
      spinBox(this, QStringLiteral("byteTimeout"), 1, 10000, static_cast<int>(defaults.byteTimeout.count()), tr(" ms"));
  m_byteTimeout->setToolTip(tr("How long to wait between two bytes of one reply."));

  const hardware::RotaryPlatformOptions rotaryDefaults;
  const hardware::RobotArmOptions robotDefaults;
  m_rotarySpeed = new QDoubleSpinBox(this);
  m_rotarySpeed->setObjectName(QStringLiteral("rotarySpeed"));
  m_rotarySpeed->setRange(0.1, 655.0);
  m_rotarySpeed->setDecimals(1);
  m_rotarySpeed->setValue(rotaryDefaults.speedDegreesPerSecond);
  m_rotarySpeed->setSuffix(tr(" °/s"));
  m_robotSpeed = spinBox(this, QStringLiteral("robotSpeed"), 1, 100, robotDefaults.speedPercent, tr(" %"));
  m_robotSpeed->setToolTip(tr("Of the robot program's maximal rotation speed."));
  m_rotarySpeedLabel = new QLabel(tr("Speed:"), this);
  m_robotSpeedLabel = new QLabel(tr("Speed:"), this);

  auto* form = new QFormLayout;
  m_kindForm = form;
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow(tr("Device:"), m_kind);
  form->addRow(tr("Transport:"), m_transport);
  auto* timeouts = new QFormLayout;
  m_timeoutsForm = timeouts;
  timeouts->setContentsMargins(0, 0, 0, 0);
  timeouts->addRow(tr("Response timeout:"), m_responseTimeout);
  timeouts->addRow(tr("Byte timeout:"), m_byteTimeout);
  timeouts->addRow(m_rotarySpeedLabel, m_rotarySpeed);
  timeouts->addRow(m_robotSpeedLabel, m_robotSpeed);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(form);
  layout->addWidget(m_transportPages);
  layout->addLayout(timeouts);

  connect(m_kind, qOverload<int>(&QComboBox::currentIndexChanged), this, &ConnectionForm::onKindChanged);
  connect(m_transport, qOverload<int>(&QComboBox::currentIndexChanged), this, &ConnectionForm::onTransportChanged);
  onTransportChanged();
  onKindChanged();
}

DeviceKind ConnectionForm::kind() const { return static_cast<DeviceKind>(m_kind->currentData().toInt()); }

void ConnectionForm::setKind(DeviceKind kind) { m_kind->setCurrentIndex(m_kind->findData(static_cast<int>(kind))); }

hardware::ConnectionSettings ConnectionForm::settings() const {
  hardware::ConnectionSettings settings = m_cadence;
  settings.transport = static_cast<hardware::Transport>(m_transport->currentData().toInt());
  settings.tcp.host = m_host->text().trimmed().toStdString();
  settings.tcp.port = m_port->value();
  settings.rtu.device = m_serialDevice->text().trimmed().toStdString();
  settings.rtu.baud = m_baud->currentText().toInt();
  settings.rtu.parity = static_cast<hardware::Parity>(m_parity->currentData().toInt());
  settings.rtu.dataBits = m_dataBits->value();
  settings.rtu.stopBits = m_stopBits->value();
  settings.slaveId = settings.transport == hardware::Transport::Tcp ? m_unit->value() : m_slave->value();
  settings.responseTimeout = std::chrono::milliseconds(m_responseTimeout->value());
  settings.byteTimeout = std::chrono::milliseconds(m_byteTimeout->value());
  return settings;
}

void ConnectionForm::setSettings(const hardware::ConnectionSettings& settings) {
  m_cadence = settings;
  m_transport->setCurrentIndex(m_transport->findData(static_cast<int>(settings.transport)));
  m_host->setText(QString::fromStdString(settings.tcp.host));
  m_port->setValue(settings.tcp.port);
  m_serialDevice->setText(QString::fromStdString(settings.rtu.device));
  m_baud->setCurrentText(QString::number(settings.rtu.baud));
  m_parity->setCurrentIndex(m_parity->findData(static_cast<int>(settings.rtu.parity)));
  m_dataBits->setValue(settings.rtu.dataBits);
  m_stopBits->setValue(settings.rtu.stopBits);
  m_unit->setValue(settings.slaveId);
  m_slave->setValue(settings.slaveId);
  m_responseTimeout->setValue(static_cast<int>(settings.responseTimeout.count()));
  m_byteTimeout->setValue(static_cast<int>(settings.byteTimeout.count()));
}

double ConnectionForm::rotarySpeedDegreesPerSecond() const { return m_rotarySpeed->value(); }

void ConnectionForm::setRotarySpeedDegreesPerSecond(double speed) { m_rotarySpeed->setValue(speed); }

int ConnectionForm::robotSpeedPercent() const { return m_robotSpeed->value(); }

void ConnectionForm::setRobotSpeedPercent(int percent) { m_robotSpeed->setValue(percent); }

void ConnectionForm::onKindChanged() {
  const DeviceKind now = kind();
  // The robot cell is reached over UR's own interfaces (its address with the cell's run controls, in the
  // panel's robot cell section): none of the Modbus fields apply to it.
  const bool modbus = now != DeviceKind::RobotCell;
  m_kindForm->setRowVisible(m_transport, modbus);
  m_transportPages->setVisible(modbus);
  m_timeoutsForm->setRowVisible(m_responseTimeout, modbus);
  m_timeoutsForm->setRowVisible(m_byteTimeout, modbus);
  // The arm is reached through the robot's own Modbus TCP server, which answers any unit id (255 is usual).
  if (now == DeviceKind::RobotArm) {
    m_transport->setCurrentIndex(m_transport->findData(static_cast<int>(hardware::Transport::Tcp)));
    m_unit->setValue(255);
  } else if (m_unit->value() == 255) {
    m_unit->setValue(1);
  }
  m_transport->setEnabled(now == DeviceKind::RotaryPlatform);
  m_rotarySpeed->setVisible(now == DeviceKind::RotaryPlatform);
  m_rotarySpeedLabel->setVisible(now == DeviceKind::RotaryPlatform);
  m_robotSpeed->setVisible(now == DeviceKind::RobotArm);
  m_robotSpeedLabel->setVisible(now == DeviceKind::RobotArm);
  if (modbus) restoreTcpAddress();
  emit kindChanged(now);
}

namespace {

// The settings group of `kind`'s remembered address: a stable name, not the translated one.
QString addressGroup(DeviceKind kind) {
  return kind == DeviceKind::RobotArm ? QStringLiteral("device/robotArm") : QStringLiteral("device/rotaryPlatform");
}

}  // namespace

void ConnectionForm::rememberTcpAddress() const {
  QSettings settings;
  settings.beginGroup(addressGroup(kind()));
  settings.setValue(QStringLiteral("host"), m_host->text().trimmed());
  settings.setValue(QStringLiteral("port"), m_port->value());
}

void ConnectionForm::restoreTcpAddress() {
  QSettings settings;
  settings.beginGroup(addressGroup(kind()));
  const QString host = settings.value(QStringLiteral("host")).toString();
  bool portRead = false;
  const int port = settings.value(QStringLiteral("port")).toInt(&portRead);
  if (host.isEmpty() || !portRead || port < m_port->minimum() || port > m_port->maximum()) return;
  m_host->setText(host);
  m_port->setValue(port);
}

void ConnectionForm::onTransportChanged() {
  const int current = m_transport->currentIndex();
  // A stacked widget is as tall as its tallest page: let the hidden page take no room.
  for (int i = 0; i < m_transportPages->count(); ++i)
    m_transportPages->widget(i)->setSizePolicy(QSizePolicy::Preferred,
                                               i == current ? QSizePolicy::Preferred : QSizePolicy::Ignored);
  m_transportPages->setCurrentIndex(current);
  m_transportPages->adjustSize();
}

}  // namespace multidir::ui
