// The Printer section of the Hardware panel against the Moonraker printer simulator and the platform
// simulator on 127.0.0.1: the printer's values shown in its own words, a whole job printed by the printer
// step by step with the timeline following it, faults pausing the run with the printer's message, a lost
// link marked stale, and E-STOP reaching both devices.
#include <gtest/gtest.h>

#include <QAction>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QToolBar>
#include <algorithm>

#include "ui/device/print_run_driver.h"
#include "ui/printer_panel_fixture.h"

namespace multidir::ui {
namespace {

// The printer's values in the Printer section (State and Last problem describe the link).
const char* const kPrinterFields[] = {"printerJobValue",      "printerFirmwareValue", "printerSaysValue",
                                      "printerExtruderValue", "printerBedValue",      "printerFileValue",
                                      "printerProgressValue"};

constexpr int kRotaryEmergencyStop = 6;  // the rotary controller's COMMAND value (device_simulator.h)

class PrinterSectionTest : public PrinterPanelTest {};

TEST_F(PrinterSectionTest, ConnectShowsThePrintersTemperaturesAndRemembersTheAddress) {
  startPrinter(1.0);
  QAction* windowEstop = panel.addEmergencyStopTo(new QToolBar(&panel));
  EXPECT_FALSE(windowEstop->isVisible());
  connectPrinter();
  // The platform is not connected, yet both E-STOPs are there for the printer.
  EXPECT_TRUE(windowEstop->isVisible());
  const hardware::SimulatedPrinterState s = printer->state();
  const QString ambient = QLocale().toString(s.extruder.actualC, 'f', 1);
  ASSERT_TRUE(QTest::qWaitFor([&] { return label("printerExtruderValue").startsWith(ambient); }, kWaitMs))
      << label("printerExtruderValue").toStdString();
  EXPECT_EQ(label("printerExtruderValue"), ambient + QStringLiteral(" °C (off)"));
  EXPECT_EQ(label("printerBedValue"), QLocale().toString(s.bed.actualC, 'f', 1) + QStringLiteral(" °C (off)"));
  EXPECT_EQ(label("printerJobValue"), QStringLiteral("standby (no job)"));
  EXPECT_EQ(label("printerFirmwareValue"), QStringLiteral("ready"));
  EXPECT_TRUE(label("printerStateValue").startsWith(QStringLiteral("Connected to Moonraker printer at 127.0.0.1:")))
      << label("printerStateValue").toStdString();
  EXPECT_TRUE(panel.printerSection()->bannerText().isEmpty());
  EXPECT_EQ(QSettings().value(QStringLiteral("printer/url")).toString(), QString::fromStdString(printer->address()));
  EXPECT_TRUE(buttonNamed("estopButton")->isEnabled());
  press("printerDisconnectButton");
  EXPECT_EQ(label("printerExtruderValue"), QStringLiteral("—"));
}

TEST_F(PrinterSectionTest, AnAddressMultiDirDoesNotSpeakIsRefusedSayingWhy) {
  panel.printerSection()->setUrl(QStringLiteral("ftp://printer:21"));
  press("printerConnectButton");
  EXPECT_FALSE(panel.printerLink()->isOpen());
  EXPECT_TRUE(panel.printerSection()->messageText().contains(QStringLiteral("'ftp://'")))
      << panel.printerSection()->messageText().toStdString();
}

TEST_F(PrinterSectionTest, APrinterThatDoesNotAnswerShowsNoValueAndTheLinksOwnWords) {
  startPrinter(1.0);
  const std::string address = printer->address();
  printer->stop();
  panel.printerSection()->setUrl(QString::fromStdString(address));
  press("printerConnectButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return !panel.printerSection()->bannerText().isEmpty(); }, kWaitMs));
  for (const char* field : kPrinterFields) EXPECT_EQ(label(field), QStringLiteral("unknown: not read yet")) << field;
  EXPECT_TRUE(label("printerStateValue").contains(QStringLiteral("Not reachable")));
  EXPECT_TRUE(panel.printerSection()->bannerText().contains(QStringLiteral("does not answer")))
      << panel.printerSection()->bannerText().toStdString();
  EXPECT_NE(label("printerProblemValue"), QStringLiteral("none"));
}

TEST_F(PrinterSectionTest, AWholeJobIsPrintedByThePrinterAndTheTimelineShowsEveryStepDone) {
  startPrinter(400.0);
  givePlanWithGcode(2);
  connectPanel();
  enableAndHome();
  connectPrinter();
  press("startRunButton");
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printRunDriver()->state() == hardware::PrintRunState::Completed; },
                              kWaitMs))
      << panel.messageText().toStdString() << " / " << panel.printerSection()->messageText().toStdString();

  std::vector<std::string> completed;
  for (const auto& e : printer->jobEvents())
    if (e.state == "complete") completed.push_back(e.file);
  EXPECT_EQ(completed, (std::vector<std::string>{"step-01.gcode", "step-02.gcode"}));
  ASSERT_EQ(timeline().size(), 2u);
  for (const TimelineRow& row : timeline()) {
    EXPECT_EQ(row.phase, StepPhase::Done) << row.region.toStdString();
    ASSERT_TRUE(row.started && row.ended) << row.region.toStdString();
    EXPECT_LE(*row.started, *row.ended);
  }
  EXPECT_EQ(timeline()[0].region, QStringLiteral("step-01.gcode"));
  EXPECT_LE(*timeline()[0].ended, *timeline()[1].started);
  EXPECT_EQ(label("printerEtaValue"), QStringLiteral("none: every step is printed"));
  EXPECT_FALSE(buttonNamed("regionDoneButton")->isEnabled());
}

TEST_F(PrinterSectionTest, WhilePrintingTheProgressAndTheJobsTimeLeftFollowTheEstimates) {
  startPrinter(20.0);
  givePlanWithGcode(2);
  ASSERT_NO_FATAL_FAILURE(runUntilPrinting());
  EXPECT_TRUE(panel.promptText().contains(QStringLiteral("is printed by Moonraker printer")))
      << panel.promptText().toStdString();
  EXPECT_FALSE(buttonNamed("regionDoneButton")->isEnabled());  // the printer says when the region is done
  EXPECT_TRUE(label("printerProgressValue").startsWith(QStringLiteral("step 1 of 2: ")))
      << label("printerProgressValue").toStdString();
  // Step 1 partly printed plus step 2: between one and two estimates left.
  const QRegularExpression eta(QStringLiteral("^(\\d+)h (\\d+)m (\\d+)s of printing \\(done about \\d\\d:\\d\\d"));
  const QString text = label("printerEtaValue");
  const QRegularExpressionMatch match = eta.match(text);
  ASSERT_TRUE(match.hasMatch()) << text.toStdString();
  const int seconds = match.captured(1).toInt() * 3600 + match.captured(2).toInt() * 60 + match.captured(3).toInt();
  EXPECT_GT(seconds, kStepEstimateSeconds);
  EXPECT_LT(seconds, 2 * kStepEstimateSeconds);
  EXPECT_EQ(timeline()[0].phase, StepPhase::Printing);
  EXPECT_EQ(timeline()[1].phase, StepPhase::Waiting);
  press("abortButton");
}

TEST_F(PrinterSectionTest, TheJobsTimeLeftIsUnknownWhileThePrinterLinkIsLost) {
  startPrinter(20.0);
  givePlanWithGcode(2);
  ASSERT_NO_FATAL_FAILURE(runUntilPrinting());
  ASSERT_TRUE(label("printerEtaValue").contains(QStringLiteral("of printing"))) << label("printerEtaValue").toStdString();
  printer->dropLink();
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printerLink()->staleSince().has_value(); }, kWaitMs));
  QTest::qWait(200);  // a few redraws while lost
  EXPECT_TRUE(label("printerEtaValue").startsWith(QStringLiteral("unknown since "))) << label("printerEtaValue").toStdString();
  EXPECT_FALSE(label("printerEtaValue").contains(QStringLiteral("of printing")));
  printer->restoreLink();
  ASSERT_TRUE(QTest::qWaitFor([&] { return !panel.printerLink()->staleSince(); }, kWaitMs));
  press("abortButton");
}

TEST_F(PrinterSectionTest, ThermalRunawayShowsThePrintersMessageAndTheRunPaused) {
  startPrinter(20.0);
  givePlanWithGcode(2);
  ASSERT_NO_FATAL_FAILURE(runUntilPrinting());
  printer->injectThermalRunaway();
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printRunDriver()->state() == hardware::PrintRunState::Paused; },
                              kWaitMs));
  EXPECT_TRUE(panel.printRunDriver()->printInterrupted());
  EXPECT_EQ(timeline()[0].phase, StepPhase::Paused);
  EXPECT_TRUE(timeline()[0].reason.contains(QStringLiteral("temperature fault"))) << timeline()[0].reason.toStdString();
  EXPECT_TRUE(panel.printerSection()->bannerText().contains(QStringLiteral("The print run is paused: temperature")))
      << panel.printerSection()->bannerText().toStdString();
  // Klipper then shuts down: its own words reach the panel.
  ASSERT_TRUE(QTest::qWaitFor([&] { return printer->state().firmwareState == "shutdown"; }, kWaitMs));
  const QString said = QString::fromStdString(printer->state().message);
  ASSERT_FALSE(said.isEmpty());
  ASSERT_TRUE(QTest::qWaitFor([&] { return label("printerSaysValue") == said; }, kWaitMs))
      << label("printerSaysValue").toStdString();
  EXPECT_EQ(label("printerFirmwareValue"), QStringLiteral("shutdown"));
  EXPECT_TRUE(panel.printerSection()->bannerText().contains(said)) << panel.printerSection()->bannerText().toStdString();
  // The region may be finished by hand.
  EXPECT_TRUE(buttonNamed("regionDoneButton")->isEnabled());
  press("abortButton");
}

// The printer restarts part way through step 1 (a power cycle: standby, no file): Resume has nothing to resume,
// and the panel says so under it and offers to print the step again, after the operator cleared the platform.
TEST_F(PrinterSectionTest, ResumeAfterThePrinterRestartedWithoutItsJobSaysSoAndRestartsTheStepOnceThePlatformIsClear) {
  startPrinter(10.0);
  givePlanWithGcode(2);
  ASSERT_NO_FATAL_FAILURE(runUntilPrinting());
  printer->restartPrinter();
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printRunDriver()->state() == hardware::PrintRunState::Paused; }, 5000))
      << runLog();
  EXPECT_TRUE(timeline()[0].reason.contains(QStringLiteral("no longer has the job"))) << timeline()[0].reason.toStdString();

  press("resumeButton");
  EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Paused);
  auto* gone = panel.findChild<QLabel*>(QStringLiteral("runJobGoneText"));
  ASSERT_NE(gone, nullptr);
  EXPECT_TRUE(gone->isVisible());
  EXPECT_TRUE(gone->text().contains(QStringLiteral("has no job of step 1 any more"))) << gone->text().toStdString();
  EXPECT_TRUE(gone->text().contains(QStringLiteral("nothing to resume"))) << gone->text().toStdString();
  QPushButton* restart = buttonNamed("restartStepButton");
  ASSERT_TRUE(restart->isVisible());
  ASSERT_TRUE(restart->isEnabled());

  // Asked first: nothing reaches the printer before the operator confirms the platform is clear.
  const auto starts = [&] {
    const auto requests = printer->requests();
    return std::count_if(requests.begin(), requests.end(), [](const hardware::PrinterRequestRecord& r) {
      return r.path == "/printer/print/start" && r.detail == "step-01.gcode";
    });
  };
  ASSERT_EQ(starts(), 1);
  restart->click();
  QMessageBox* box = nullptr;
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        box = panel.findChild<QMessageBox*>(QStringLiteral("restartStepBox"));
        return box != nullptr && box->isVisible();
      },
      kWaitMs));
  QTest::qWait(100);
  EXPECT_EQ(starts(), 1);
  EXPECT_EQ(printer->state().jobState, "standby");
  auto* confirm = box->findChild<QPushButton*>(QStringLiteral("restartStepConfirm"));
  ASSERT_NE(confirm, nullptr);
  confirm->click();

  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        const hardware::SimulatedPrinterState s = printer->state();
        return s.jobState == "printing" && s.file == "step-01.gcode";
      },
      kWaitMs))
      << runLog();
  EXPECT_EQ(starts(), 2);
  EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Printing);
  EXPECT_EQ(panel.printRunDriver()->currentStep(), 0u);
  EXPECT_FALSE(gone->isVisible());
  EXPECT_FALSE(restart->isVisible());
  press("abortButton");
}

TEST_F(PrinterSectionTest, ALostLinkMarksEveryPrinterValueStaleAndSaysSoInTheBanners) {
  startPrinter(1.0);
  connectPrinter();
  printer->dropLink();
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printerLink()->staleSince().has_value(); }, kWaitMs));
  const QRegularExpression staleText(QStringLiteral("^unknown since \\d\\d:\\d\\d:\\d\\d \\(last read: "));
  for (const char* field : kPrinterFields) {
    auto* value = panel.findChild<QLabel*>(QString::fromLatin1(field));
    ASSERT_NE(value, nullptr) << field;
    EXPECT_TRUE(staleText.match(value->text()).hasMatch()) << field << ": " << value->text().toStdString();
    EXPECT_TRUE(value->styleSheet().contains(QStringLiteral("#8a8a8a"))) << field << " is not greyed";
  }
  EXPECT_TRUE(label("printerStateValue").startsWith(QStringLiteral("Link lost at")));
  EXPECT_TRUE(panel.printerSection()->bannerText().contains(QStringLiteral("was lost at")));
  // The panel's banner above everything says it too.
  EXPECT_TRUE(panel.bannerText().contains(QStringLiteral("Moonraker printer"))) << panel.bannerText().toStdString();

  printer->restoreLink();
  ASSERT_TRUE(QTest::qWaitFor([&] { return !panel.printerLink()->staleSince(); }, kWaitMs));
  for (const char* field : kPrinterFields) EXPECT_FALSE(label(field).startsWith(QStringLiteral("unknown"))) << field;
  EXPECT_TRUE(panel.bannerText().isEmpty()) << panel.bannerText().toStdString();
}

TEST_F(PrinterSectionTest, TheLinkLostBannerIsDrawnInAlarmRedAcrossThePrinterSection) {
  startPrinter(1.0);
  connectPrinter();
  auto* section = panel.printerSection();
  auto* banner = section->findChild<QLabel*>(QStringLiteral("printerBanner"));
  ASSERT_NE(banner, nullptr);
  const QColor red(0xc6, 0x28, 0x28);
  const int before = pixelsNear(section->grab().toImage(), red);
  printer->dropLink();
  ASSERT_TRUE(QTest::qWaitFor([&] { return banner->isVisible(); }, kWaitMs));
  QTest::qWait(50);  // laid out
  const QImage picture = section->grab().toImage();
  // A band as wide as most of the section, at least two text lines high, where there was none.
  const int redPixels = pixelsNear(picture, red) - before;
  EXPECT_GT(redPixels, picture.width() * 8 / 10 * 30) << "red pixels: " << redPixels;
  const QImage bannerPicture = banner->grab().toImage();
  EXPECT_GT(pixelsNear(bannerPicture, red), bannerPicture.width() * bannerPicture.height() / 2);
}

TEST_F(PrinterSectionTest, EmergencyStopReachesBothSimulatorsAndThePanelShowsBothStopsConfirmed) {
  startPrinter(20.0);
  givePlanWithGcode(2);
  ASSERT_NO_FATAL_FAILURE(runUntilPrinting());
  press("estopButton");
  EXPECT_EQ(panel.printRunDriver()->state(), hardware::PrintRunState::Aborted);
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        return panel.stopsText().contains(QStringLiteral("Platform: stop confirmed")) &&
               panel.stopsText().contains(QStringLiteral("Printer: emergency stop confirmed"));
      },
      kWaitMs))
      << panel.stopsText().toStdString();
  const auto commands = sim.commandLog();
  EXPECT_TRUE(std::any_of(commands.begin(), commands.end(),
                          [](const hardware::SimulatedCommandRecord& r) { return r.command == kRotaryEmergencyStop; }));
  const auto requests = printer->requests();
  EXPECT_TRUE(std::any_of(requests.begin(), requests.end(), [](const hardware::PrinterRequestRecord& r) {
    return r.path == "/printer/emergency_stop";
  }));
  EXPECT_EQ(timeline()[0].phase, StepPhase::Aborted);
  EXPECT_TRUE(panel.messageText().contains(QStringLiteral("the platform and the printer")))
      << panel.messageText().toStdString();
}

TEST_F(PrinterSectionTest, EmergencyStopWithoutARunStillStopsBothDevices) {
  startPrinter(1.0);
  connectPanel();
  connectPrinter();
  press("estopButton");
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        return panel.stopsText().contains(QStringLiteral("Platform: stop confirmed")) &&
               panel.stopsText().contains(QStringLiteral("Printer: emergency stop confirmed"));
      },
      kWaitMs))
      << panel.stopsText().toStdString();
  EXPECT_EQ(printer->state().firmwareState, "shutdown");
  EXPECT_TRUE(buttonNamed("printerClearStopButton")->isEnabled());
  press("printerClearStopButton");
  EXPECT_FALSE(panel.stopsText().contains(QStringLiteral("Printer:"))) << panel.stopsText().toStdString();
}

TEST_F(PrinterSectionTest, AfterAnEmergencyStopRestartFirmwareAsksFirstThenTheKlipperPrinterIsReadyAndTheRestartTextGoes) {
  startPrinter(1.0);
  connectPanel();
  connectPrinter();
  EXPECT_FALSE(buttonNamed("printerRestartFirmwareButton")->isEnabled());  // ready: nothing to restart
  press("estopButton");
  ASSERT_TRUE(QTest::qWaitFor(
      [&] { return panel.stopsText().contains(QStringLiteral("Printer: emergency stop confirmed")); }, kWaitMs))
      << panel.stopsText().toStdString();
  ASSERT_TRUE(QTest::qWaitFor([&] { return label("printerFirmwareValue") == QStringLiteral("shutdown"); }, kWaitMs))
      << label("printerFirmwareValue").toStdString();
  press("printerClearStopButton");
  EXPECT_TRUE(panel.printerSection()->messageText().contains(QStringLiteral("FIRMWARE_RESTART")))
      << panel.printerSection()->messageText().toStdString();

  // Asked first: nothing reaches the printer before the operator confirms.
  press("printerRestartFirmwareButton");
  QMessageBox* box = nullptr;
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        box = panel.findChild<QMessageBox*>(QStringLiteral("restartFirmwareBox"));
        return box != nullptr && box->isVisible();
      },
      kWaitMs));
  QTest::qWait(100);
  EXPECT_EQ(printer->state().firmwareState, "shutdown");
  auto* confirm = box->findChild<QPushButton*>(QStringLiteral("restartFirmwareConfirm"));
  ASSERT_NE(confirm, nullptr);
  confirm->click();

  ASSERT_TRUE(QTest::qWaitFor([&] { return printer->state().firmwareState == "ready"; }, kWaitMs));
  ASSERT_TRUE(QTest::qWaitFor([&] { return label("printerFirmwareValue") == QStringLiteral("ready"); }, kWaitMs));
  const QString message = panel.printerSection()->messageText();
  EXPECT_FALSE(message.contains(QStringLiteral("FIRMWARE_RESTART"))) << message.toStdString();
  EXPECT_FALSE(message.contains(QStringLiteral("restart"), Qt::CaseInsensitive)) << message.toStdString();
  EXPECT_FALSE(panel.printerSection()->bannerText().contains(QStringLiteral("firmware")))
      << panel.printerSection()->bannerText().toStdString();
  EXPECT_FALSE(buttonNamed("printerRestartFirmwareButton")->isEnabled());
}

TEST_F(PrinterSectionTest, AnEmergencyStopThePrinterCannotHearIsShownAsBeingResentUntilItArrives) {
  startPrinter(1.0);
  connectPrinter();
  printer->dropLink();
  press("estopButton");  // enabled for the printer alone
  ASSERT_TRUE(QTest::qWaitFor(
      [&] { return panel.stopsText().contains(QStringLiteral("Printer: emergency stop not confirmed yet")); }, kWaitMs))
      << panel.stopsText().toStdString();
  EXPECT_TRUE(panel.stopsText().contains(QStringLiteral("keeps resending"))) << panel.stopsText().toStdString();
  press("printerClearStopButton");  // not before the printer has it
  EXPECT_TRUE(panel.printerSection()->messageText().startsWith(QStringLiteral("Clear printer E-STOP refused")))
      << panel.printerSection()->messageText().toStdString();
  printer->restoreLink();
  ASSERT_TRUE(QTest::qWaitFor(
      [&] { return panel.stopsText().contains(QStringLiteral("Printer: emergency stop confirmed")); }, kWaitMs))
      << panel.stopsText().toStdString();
  const auto requests = printer->requests();
  EXPECT_TRUE(std::any_of(requests.begin(), requests.end(), [](const hardware::PrinterRequestRecord& r) {
    return r.path == "/printer/emergency_stop";
  }));
  EXPECT_EQ(printer->state().firmwareState, "shutdown");
}

TEST_F(PrinterSectionTest, ALostPrinterLinkDuringARunPausesItAndTheTimelineSaysWhy) {
  startPrinter(20.0);
  givePlanWithGcode(2);
  ASSERT_NO_FATAL_FAILURE(runUntilPrinting());
  printer->dropLink();
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printRunDriver()->state() == hardware::PrintRunState::Paused; },
                              kWaitMs))
      << runLog();
  // The run reads the link itself; the section's next status read marks the values.
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printerLink()->staleSince().has_value(); }, kWaitMs));
  EXPECT_TRUE(label("printerExtruderValue").startsWith(QStringLiteral("unknown since")));
  EXPECT_EQ(timeline()[0].phase, StepPhase::Paused);
  EXPECT_TRUE(timeline()[0].reason.contains(QStringLiteral("is lost"))) << timeline()[0].reason.toStdString();
  EXPECT_EQ(timeline()[1].phase, StepPhase::Waiting);
  EXPECT_TRUE(panel.printerSection()->bannerText().contains(QStringLiteral("The print run is paused")))
      << panel.printerSection()->bannerText().toStdString();
  printer->restoreLink();
  press("abortButton");
}

}  // namespace
}  // namespace multidir::ui
