#pragma once
// The Hardware panel with a printer: the platform simulator of HardwarePanelTest plus the Moonraker printer
// simulator on 127.0.0.1 (ephemeral port), the printer tests' fast link options, and a two-region plan whose
// G-code (the printer tests' short program) the panel is given as the sliced job's.
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <memory>
#include <vector>

#include "hardware/printer_test_support.h"
#include "multidir/hardware/moonraker_simulator.h"
#include "ui/device/job_timeline.h"
#include "ui/device/printer_link_owner.h"
#include "ui/device/printer_section.h"
#include "ui/hardware_panel_fixture.h"

namespace multidir::ui {

// The slicer's estimate the tests give each step (seconds): the short program takes about 28.
inline constexpr double kStepEstimateSeconds = 30.0;

class PrinterPanelTest : public HardwarePanelTest {
 protected:
  void SetUp() override {
    HardwarePanelTest::SetUp();
    // The printer tests' fast polling, with a lost link declared after 1.5 s rather than 0.4 s: GUI tests
    // share a loaded machine, and a run that pauses for a slow reply would fail a test about something else.
    hardware::PrinterLinkOptions options = hardware::test::fastPrinterOptions();
    options.linkLostAfter = std::chrono::milliseconds(1500);
    panel.setPrinterLinkOptions(options);
    ASSERT_TRUE(files.isValid());
  }

  // Starts the printer simulator, `speed` times faster than real time.
  void startPrinter(double speed) {
    hardware::MoonrakerSimulatorOptions options;
    options.speed = speed;
    printer = std::make_unique<hardware::MoonrakerSimulator>(options);
    ASSERT_TRUE(printer->start().ok());
  }

  // Types the simulator's address into the Printer section and connects; waits for the first status read.
  void connectPrinter() {
    panel.printerSection()->setUrl(QString::fromStdString(printer->address()));
    press("printerConnectButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.printerLink()->hasRead(); }, kWaitMs))
        << panel.printerSection()->messageText().toStdString();
  }

  // A plan of `regions` regions (0, 10, 20 degrees ...) with the short program as every region's G-code.
  void givePlanWithGcode(int regions) {
    std::vector<double> angles;
    std::vector<StepGcode> steps;
    for (int k = 0; k < regions; ++k) {
      angles.push_back(10.0 * k);
      const std::string path = files.filePath(QStringLiteral("step-%1.gcode").arg(k + 1, 2, 10, QLatin1Char('0')))
                                   .toStdString();
      hardware::test::writeFile(path, hardware::test::shortGcode());
      steps.push_back({path, kStepEstimateSeconds});
    }
    givePlan(planWithAngles(angles));
    PrintJob job;
    job.plan = document.plan()->plan;
    job.steps = std::move(steps);
    ASSERT_TRUE(document.setSlicedJob(std::move(job)).ok());
  }

  // Connects both devices and starts the run; waits until the printer prints step 1 past its heating.
  void runUntilPrinting() {
    connectPanel();
    enableAndHome();
    connectPrinter();
    press("startRunButton");
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
          const hardware::SimulatedPrinterState s = printer->state();
          return s.jobState == "printing" && s.progress > 0.1 && panel.printerLink()->status().progress > 0.1;
        },
        kWaitMs))
        << runLog();
  }

  // The run's log as the panel shows it, for failure messages.
  std::string runLog() {
    auto* log = panel.findChild<QPlainTextEdit*>(QStringLiteral("runLog"));
    return (panel.messageText() + QLatin1Char('\n') + (log ? log->toPlainText() : QString())).toStdString();
  }

  const std::vector<TimelineRow>& timeline() { return panel.jobTimeline()->rows(); }

  QTemporaryDir files;
  std::unique_ptr<hardware::MoonrakerSimulator> printer;
};

}  // namespace multidir::ui
