// The robot cell is one of the devices of the Hardware dock's connection form: chosen, the cell's address and
// run controls show and the printer's and the Modbus device's fields hide; it follows the document's machine
// when that is the robot cell.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

#include "ui/device/connection_form.h"
#include "ui/device/hardware_panel.h"
#include "ui/device/printer_section.h"
#include "ui/device/robot_cell_section.h"
#include "ui/document/studio_document.h"

namespace multidir::ui {
namespace {

class HardwareRobotCellKind : public ::testing::Test {
 protected:
  void SetUp() override {
    panel.resize(520, 1400);
    panel.show();
  }

  QWidget* named(const char* name) {
    auto* found = panel.findChild<QWidget*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
  }
  bool shown(const char* name) {
    QWidget* w = named(name);
    return w != nullptr && w->isVisibleTo(&panel);
  }
  // As the operator does: the device list's entry.
  void chooseDevice(DeviceKind kind) {
    auto* list = panel.findChild<QComboBox*>(QStringLiteral("deviceKind"));
    ASSERT_NE(list, nullptr);
    const int item = list->findData(static_cast<int>(kind));
    ASSERT_GE(item, 0);
    list->setCurrentIndex(item);
  }

  StudioDocument document;
  HardwarePanel panel{&document};
};

TEST_F(HardwareRobotCellKind, ChoosingTheRobotCellShowsItsAddressAndRunControlsAndHidesThePrinterAndModbusFields) {
  ASSERT_NO_FATAL_FAILURE(chooseDevice(DeviceKind::RobotCell));
  EXPECT_EQ(panel.connectionForm()->kind(), DeviceKind::RobotCell);
  for (const char* cellField : {"robotCellSection", "robotAddress", "robotConnect", "robotJobFolder", "robotStart",
                                "robotPause", "robotResume", "robotStopButton"})
    EXPECT_TRUE(shown(cellField)) << cellField;
  for (const char* notForTheCell : {"printerSection", "printerUrl", "transport", "tcpHost", "tcpPort", "tcpUnit",
                                    "responseTimeout", "connectButton", "startRunButton", "regionDoneButton",
                                    "goToButton"})
    EXPECT_FALSE(shown(notForTheCell)) << notForTheCell;

  // Another device brings its own fields back and hides the cell's.
  ASSERT_NO_FATAL_FAILURE(chooseDevice(DeviceKind::RotaryPlatform));
  for (const char* platformField : {"printerSection", "transport", "tcpHost", "connectButton", "startRunButton"})
    EXPECT_TRUE(shown(platformField)) << platformField;
  EXPECT_FALSE(shown("robotCellSection"));
}

TEST_F(HardwareRobotCellKind, ADocumentWhoseMachineIsTheRobotCellSelectsIt) {
  core::MachineSpec fiveDof;
  fiveDof.kind = core::MachineKind::TiltRotate;
  document.setMachine(fiveDof);
  ASSERT_EQ(panel.connectionForm()->kind(), DeviceKind::RobotArm);  // an arm tilting the platform under a printer

  document.setMachineIsRobotCell(true);
  EXPECT_EQ(panel.connectionForm()->kind(), DeviceKind::RobotCell);
  EXPECT_TRUE(shown("robotCellSection"));
  EXPECT_FALSE(shown("printerSection"));

  document.setMachineIsRobotCell(false);
  EXPECT_EQ(panel.connectionForm()->kind(), DeviceKind::RobotArm);
}

}  // namespace
}  // namespace multidir::ui
