// The Hardware panel remembers the device's host and port between sessions (QSettings, here in a temporary
// folder of the test's own).
#include <gtest/gtest.h>

#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>

#include "ui/hardware_panel_fixture.h"

namespace multidir::ui {
namespace {

// Points QSettings at a temporary folder while it lives, then back where it was.
class TemporarySettingsPath {
 public:
  TemporarySettingsPath() : m_previous(QFileInfo(QFileInfo(QSettings().fileName()).path()).path()) {
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_folder.path());
  }
  ~TemporarySettingsPath() { QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_previous); }
  TemporarySettingsPath(const TemporarySettingsPath&) = delete;
  TemporarySettingsPath& operator=(const TemporarySettingsPath&) = delete;
  [[nodiscard]] QString folder() const { return m_folder.path(); }

 private:
  QTemporaryDir m_folder;
  QString m_previous;
};

class DeviceAddressMemoryTest : public HardwarePanelTest {
 protected:
  TemporarySettingsPath settingsPath;  // before the panel's next session reads it
};

TEST_F(DeviceAddressMemoryTest, ConnectRemembersHostAndPortForTheNextSession) {
  ASSERT_NE(sim.port(), hardware::ConnectionSettings{}.tcp.port) << "the simulator's port must differ from the default";
  ASSERT_NO_FATAL_FAILURE(connectPanel());
  EXPECT_TRUE(QSettings().fileName().startsWith(settingsPath.folder())) << QSettings().fileName().toStdString();

  StudioDocument nextDocument;
  HardwarePanel nextSession(&nextDocument);
  nextSession.connectionForm()->setKind(DeviceKind::RotaryPlatform);
  EXPECT_EQ(nextSession.connectionForm()->settings().tcp.host, "127.0.0.1");
  EXPECT_EQ(nextSession.connectionForm()->settings().tcp.port, sim.port());
}

TEST_F(DeviceAddressMemoryTest, EachDeviceKindKeepsItsOwnAddress) {
  ASSERT_NO_FATAL_FAILURE(connectPanel());  // the rotary platform at the simulator's port
  const int armPort = sim.port() == 1502 ? 1503 : 1502;
  {
    StudioDocument document;
    HardwarePanel armSession(&document);
    armSession.connectionForm()->setKind(DeviceKind::RobotArm);
    hardware::ConnectionSettings arm = armSession.connectionForm()->settings();
    arm.tcp.port = armPort;
    armSession.connectionForm()->setSettings(arm);
    armSession.connectionForm()->rememberTcpAddress();
  }
  StudioDocument nextDocument;
  HardwarePanel nextSession(&nextDocument);
  ConnectionForm* form = nextSession.connectionForm();
  form->setKind(DeviceKind::RobotArm);
  EXPECT_EQ(form->settings().tcp.port, armPort);
  form->setKind(DeviceKind::RotaryPlatform);
  EXPECT_EQ(form->settings().tcp.port, sim.port());
}

}  // namespace
}  // namespace multidir::ui
