// What the translations show: no raw ids ("5dof") or English printer names in German and Chinese, and German
// names the risky area with one term, "Risikofläche", throughout.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QRegularExpression>

#include "multidir/core/search/machine.h"
#include "multidir/slicing/printer_profile.h"
#include "ui/device/connection_form.h"
#include "ui/device/hardware_panel.h"
#include "ui/document/studio_document.h"
#include "ui/slicing/slice_dialog.h"
#include "ui/studio_startup.h"

namespace multidir::ui {
namespace {

class TranslationTerms : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { ASSERT_TRUE(installTranslations(QString::fromLatin1(GetParam()))); }
  void TearDown() override { installTranslations(QStringLiteral("en")); }
};

TEST_P(TranslationTerms, SliceDialogListsTheBuiltInPrintersInTheLanguage) {
  SliceDialog dialog(core::MachineKind::RotaryPlatform);
  auto* printers = dialog.findChild<QComboBox*>(QStringLiteral("slicePrinter"));
  ASSERT_NE(printers, nullptr);
  int builtIn = 0;
  for (const std::string& id : slicing::builtinPrinterNames()) {
    const core::Result<slicing::PrinterProfile> profile = slicing::loadPrinterProfile(id);
    ASSERT_TRUE(profile.ok()) << id;
    const int index = printers->findData(QString::fromStdString(id));
    ASSERT_GE(index, 0) << id;
    EXPECT_NE(printers->itemText(index), QString::fromStdString(profile->name)) << "English: " << profile->name;
    ++builtIn;
  }
  EXPECT_GT(builtIn, 0);
}

TEST_P(TranslationTerms, HardwareDockNamesTheMachineKindInWords) {
  StudioDocument document;
  core::MachineSpec arm;
  arm.kind = core::MachineKind::TiltRotate;
  document.setMachine(arm);
  HardwarePanel panel(&document);
  panel.connectionForm()->setKind(DeviceKind::RotaryPlatform);  // a profile of another kind: the defaults apply
  auto* limits = panel.findChild<QLabel*>(QStringLiteral("limitsText"));
  ASSERT_NE(limits, nullptr);
  EXPECT_FALSE(limits->text().contains(QRegularExpression(QStringLiteral("\\b[345]dof\\b"))))
      << limits->text().toStdString();
}

INSTANTIATE_TEST_SUITE_P(Languages, TranslationTerms, ::testing::Values("de", "zh_CN"));

// Every German text that names the risky area says "Risikofläche" (the area is one quantity: singular).
TEST(TranslationTermsGerman, RiskyAreaIsRisikoflaecheThroughout) {
  QFile file(QStringLiteral(MULTIDIR_SOURCE_DIR "/translations/multidir_de.ts"));
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  const QString ts = QString::fromUtf8(file.readAll());
  EXPECT_FALSE(ts.contains(QStringLiteral("Risikoflächen"))) << "plural of the risky area";
  const QRegularExpression message(QStringLiteral("<source>([^<]*)</source>\\s*<translation>([^<]*)</translation>"));
  int named = 0;
  for (auto it = message.globalMatch(ts); it.hasNext();) {
    const QRegularExpressionMatch match = it.next();
    if (!match.captured(1).contains(QStringLiteral("isky"))) continue;
    ++named;
    EXPECT_TRUE(match.captured(2).contains(QStringLiteral("Risikofläche")))
        << match.captured(1).toStdString() << " -> " << match.captured(2).toStdString();
  }
  EXPECT_GT(named, 10);
}

}  // namespace
}  // namespace multidir::ui
