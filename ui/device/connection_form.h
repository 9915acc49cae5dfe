#pragma once
// The connection settings of the Hardware panel: which device, over TCP (host, port, unit id) or serial RTU
// (port, baud, parity, data and stop bits), and the link's timeouts. Holds no connection itself. The robot
// cell is one of the devices: chosen, the Modbus fields hide (the panel shows the cell's own section instead).
#include <QWidget>

#include "multidir/hardware/connection.h"
#include "ui/device/device_snapshot.h"

class QComboBox;
class QFormLayout;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;
class QStackedWidget;

namespace multidir::ui {

class ConnectionForm : public QWidget {
  Q_OBJECT

 public:
  explicit ConnectionForm(QWidget* parent = nullptr);

  [[nodiscard]] DeviceKind kind() const;
  void setKind(DeviceKind kind);
  // The settings as entered; hardware::validate() checks them. The worker's cadence (poll, heartbeat and
  // reconnect intervals) is not shown: it keeps the defaults or what setSettings() gave.
  [[nodiscard]] hardware::ConnectionSettings settings() const;
  void setSettings(const hardware::ConnectionSettings& settings);
  // Motion speed the driver commands (applies at Connect): degrees per second for the rotary platform,
  // percent of the robot program's maximal speed for the arm.
  [[nodiscard]] double rotarySpeedDegreesPerSecond() const;
  void setRotarySpeedDegreesPerSecond(double speed);
  [[nodiscard]] int robotSpeedPercent() const;
  void setRobotSpeedPercent(int percent);
  // Keeps the TCP host and port entered for the device kind chosen (QSettings "device/<kind>/host", "port"), as
  // the Hardware panel does on Connect; a form made later (the next session) starts with them, and choosing a
  // kind brings back its own.
  void rememberTcpAddress() const;

 signals:
  void kindChanged(multidir::ui::DeviceKind kind);

 private:
  void onKindChanged();
  void onTransportChanged();
  void restoreTcpAddress();

  QComboBox* m_kind = nullptr;
  QFormLayout* m_kindForm = nullptr;      // device and transport
  QFormLayout* m_timeoutsForm = nullptr;  // timeouts and speeds
  QComboBox* m_transport = nullptr;
  QStackedWidget* m_transportPages = nullptr;
  QLineEdit* m_host = nullptr;
  QSpinBox* m_port = nullptr;
  QSpinBox* m_unit = nullptr;
  QLineEdit* m_serialDevice = nullptr;
  QComboBox* m_baud = nullptr;
  QComboBox* m_parity = nullptr;
  QSpinBox* m_dataBits = nullptr;
  QSpinBox* m_stopBits = nullptr;
  QSpinBox* m_slave = nullptr;
  QSpinBox* m_responseTimeout = nullptr;
  QSpinBox* m_byteTimeout = nullptr;
  QDoubleSpinBox* m_rotarySpeed = nullptr;
  QSpinBox* m_robotSpeed = nullptr;
  QWidget* m_rotarySpeedLabel = nullptr;
  QWidget* m_robotSpeedLabel = nullptr;
  hardware::ConnectionSettings m_cadence;  // the fields not shown
};

}  // namespace multidir::ui
