// The Slice dialog offers the printers that can print the plan: for a 5-DOF plan the two-axis printers (their
// program is one job.gcode) and the robot, not a one-axis platform, which stays listed, greyed, saying why; a
// printer remembered from another plan that cannot print this one is not chosen (issue 29: Klipper remembered
// for a 5-DOF plan failed "A setting is out of its allowed range"; issue 26 item 6).
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLabel>
#include <QSettings>
#include <QStandardItemModel>

#include "ui/slicing/slice_dialog.h"

using namespace multidir;
using multidir::ui::SliceDialog;

namespace {

bool enabledEntry(QComboBox* box, const QString& id) {
  const int index = box->findData(id);
  auto* model = qobject_cast<QStandardItemModel*>(box->model());
  return index >= 0 && model && model->item(index)->isEnabled();
}

}  // namespace

TEST(SliceDialogPrinters, AFiveDofPlanCanChooseTheTwoAxisPrintersAndTheRobotButNotAOneAxisPlatform) {
  SliceDialog dialog(core::MachineKind::TiltRotate);
  auto* printers = dialog.findChild<QComboBox*>(QStringLiteral("slicePrinter"));
  ASSERT_NE(printers, nullptr);
  EXPECT_TRUE(enabledEntry(printers, QStringLiteral("open5x-rrf")));
  EXPECT_TRUE(enabledEntry(printers, QStringLiteral("klipper-2axis")));
  EXPECT_TRUE(enabledEntry(printers, QStringLiteral("robot-0.8")));
  EXPECT_FALSE(enabledEntry(printers, QStringLiteral("klipper-rotary")));
  const int oneAxis = printers->findData(QStringLiteral("klipper-rotary"));
  ASSERT_GE(oneAxis, 0) << "the one-axis printer stays listed";
  EXPECT_TRUE(printers->itemData(oneAxis, Qt::ToolTipRole).toString().contains(QStringLiteral("5-DOF")));

  ASSERT_TRUE(dialog.selectPrinter(QStringLiteral("open5x-rrf")));
  auto* info = dialog.findChild<QLabel*>(QStringLiteral("slicePrinterInfo"));
  ASSERT_NE(info, nullptr);
  EXPECT_TRUE(info->text().contains(QStringLiteral("job.gcode"))) << info->text().toStdString();
  EXPECT_TRUE(dialog.findChild<QComboBox*>(QStringLiteral("sliceDialect"))->isEnabled())
      << "the two axes are driven in the chosen dialect";
  EXPECT_FALSE(dialog.selectPrinter(QStringLiteral("klipper-rotary")));
  EXPECT_EQ(printers->currentData().toString(), QStringLiteral("open5x-rrf"));
}

TEST(SliceDialogPrinters, APrinterRememberedFromAnotherPlanThatCannotPrintThisOneIsNotChosen) {
  {
    QSettings settings;
    settings.setValue(QStringLiteral("slicing/printer"), QStringLiteral("klipper-rotary"));
  }
  SliceDialog fiveDof(core::MachineKind::TiltRotate);
  EXPECT_EQ(fiveDof.findChild<QComboBox*>(QStringLiteral("slicePrinter"))->currentData().toString(),
            QStringLiteral("robot-0.8"));
  SliceDialog fourDof(core::MachineKind::RotaryPlatform);
  EXPECT_EQ(fourDof.findChild<QComboBox*>(QStringLiteral("slicePrinter"))->currentData().toString(),
            QStringLiteral("klipper-rotary"))
      << "where it suits the plan the remembered printer is kept";
  QSettings().remove(QStringLiteral("slicing/printer"));
}
