// The Hardware dock's texts after the links are lost (issue 29, [cosmetic]): at 1280x720 and 1600x1000, once
// the platform's and the printer's links are lost, every label in the dock shows its whole text: on one line
// within its rectangle, wrapped within its height, or elided with the whole text in its tooltip; never cut.
#include <gtest/gtest.h>

#include <QDockWidget>
#include <QFontMetrics>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QTest>
#include <QTextDocument>
#include <memory>

#include "hardware/hardware_test_support.h"
#include "hardware/printer_test_support.h"
#include "multidir/hardware/device_simulator.h"
#include "multidir/hardware/moonraker_simulator.h"
#include "ui/device/connection_form.h"
#include "ui/device/device_link.h"
#include "ui/device/hardware_panel.h"
#include "ui/device/printer_link_owner.h"
#include "ui/device/printer_section.h"
#include "ui/main_window.h"
#include "ui/studio_startup.h"

namespace multidir::ui {
namespace {

constexpr int kWaitMs = 5000;

// Why `label` does not show its whole text; empty when it does. `panel` is the dock's panel: no part of the label
// may lie beyond its right edge, nor, inside the scrolled part, beyond the scroll area's viewport (sideways).
QString cutText(const QLabel& label, const QWidget& panel) {
  const auto* scroll = panel.findChild<const QScrollArea*>(QStringLiteral("hardwareScroll"));
  const QWidget* frame = scroll != nullptr && scroll->isAncestorOf(&label) ? scroll->viewport() : &panel;
  const QRect inFrame(label.mapTo(frame, QPoint(0, 0)), label.size());
  if (inFrame.left() < 0 || inFrame.right() >= frame->width())
    return QStringLiteral("columns %1 to %2 of a %3 px wide %4")
        .arg(inFrame.left())
        .arg(inFrame.right())
        .arg(frame->width())
        .arg(frame == &panel ? QStringLiteral("dock") : QStringLiteral("scroll area"));
  const QString text = label.text();
  const QString tip = label.toolTip();
  // Elided: the start of the text and an ellipsis, the whole text in the tooltip.
  if (text.endsWith(QChar(0x2026)) && tip.startsWith(text.chopped(1))) return {};
  if (label.wordWrap() || Qt::mightBeRichText(text)) {
    const int needed = label.heightForWidth(label.width());
    if (needed > label.height())
      return QStringLiteral("needs %1 px of height at its width %2, has %3").arg(needed).arg(label.width()).arg(label.height());
    if (!label.wordWrap() && label.sizeHint().width() > label.width())
      return QStringLiteral("needs %1 px of width, has %2").arg(label.sizeHint().width()).arg(label.width());
    return {};
  }
  const int margin = label.margin();
  const QRect room = label.contentsRect().adjusted(margin, margin, -margin, -margin);
  const QRect needed = QFontMetrics(label.font()).boundingRect(QRect(0, 0, 100000, 100000), Qt::AlignLeft, text);
  if (needed.width() > room.width() || needed.height() > room.height())
    return QStringLiteral("needs %1x%2 px, has %3x%4")
        .arg(needed.width())
        .arg(needed.height())
        .arg(room.width())
        .arg(room.height());
  return {};
}

class HardwareDockText : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { ASSERT_TRUE(installTranslations(QString::fromLatin1(GetParam()))); }
  void TearDown() override { installTranslations(QStringLiteral("en")); }
};

TEST_P(HardwareDockText, EveryLabelShowsItsWholeTextAfterThePrinterAndPlatformLinksAreLost) {
  for (const QSize& screen : {QSize(1280, 720), QSize(1600, 1000)}) {
    SCOPED_TRACE(QStringLiteral("%1x%2").arg(screen.width()).arg(screen.height()).toStdString());
    hardware::DeviceSimulator platform;
    ASSERT_TRUE(platform.start().ok());
    hardware::MoonrakerSimulator printer;
    ASSERT_TRUE(printer.start().ok());

    MainWindow window;
    window.resize(screen);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    window.findChild<QDockWidget*>(QStringLiteral("hardwareDock"))->raise();
    auto* panel = window.findChild<HardwarePanel*>();
    ASSERT_NE(panel, nullptr);
    hardware::PrinterLinkOptions printerOptions = hardware::test::fastPrinterOptions();
    panel->setPrinterLinkOptions(printerOptions);
    panel->connectionForm()->setKind(DeviceKind::RotaryPlatform);
    panel->connectionForm()->setSettings(hardware::test::fastSettings(platform.port(), 1));
    panel->connectDevice();
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->deviceLink()->snapshot().state == DeviceState::Connected; },
                                kWaitMs));
    panel->printerSection()->setUrl(QString::fromStdString(printer.address()));
    auto* connectPrinter = panel->findChild<QPushButton*>(QStringLiteral("printerConnectButton"));
    ASSERT_NE(connectPrinter, nullptr);
    connectPrinter->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->printerLink()->hasRead(); }, kWaitMs));

    platform.stop();
    printer.dropLink();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return panel->deviceLink()->snapshot().staleSince && panel->printerLink()->staleSince(); }, kWaitMs));
    ASSERT_FALSE(panel->bannerText().isEmpty());
    QTest::qWait(300);  // the clock's redraws and the layouts settle

    int checked = 0;
    for (const QLabel* label : panel->findChildren<QLabel*>()) {
      if (!label->isVisible() || label->text().isEmpty()) continue;
      ++checked;
      const QString cut = cutText(*label, *panel);
      EXPECT_TRUE(cut.isEmpty()) << label->objectName().toStdString() << " \"" << label->text().toStdString()
                                 << "\": " << cut.toStdString();
    }
    EXPECT_GT(checked, 20);
    panel->disconnectDevice();
    panel->printerLink()->disconnectPrinter();
  }
}

INSTANTIATE_TEST_SUITE_P(Languages, HardwareDockText, ::testing::Values("en", "de", "zh_CN"));

}  // namespace
}  // namespace multidir::ui
