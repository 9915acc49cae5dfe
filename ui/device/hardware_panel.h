#pragma once
// The Hardware panel: connect to the rotary platform or the robot arm, watch its live status, move it by
// hand (enable, home, jog, go to, stop, E-STOP), and run a plan region by region with the operator.
//
// Threads: GUI thread only. The device's status reaches the panel as queued signals from DeviceLink (the
// panel reads only the last snapshot); the print run is ticked by PrintRunDriver's timer. Errors (refusals,
// timeouts, faults) are shown in the panel in plain words, never in a modal dialog.
//
// Truthfulness: no device value is shown before the first good read; when the link drops every value is
// greyed and marked "unknown since HH:MM:SS", a banner above everything says so, and the print run pauses.
// Stop and E-STOP sit above the scrolled part, so they stay in view at any dock height; the main window
// can put a second E-STOP in a toolbar (addEmergencyStopTo) that shows while a device is connected.
//
// What it runs: the studio document's device-session job (StudioDocument::sessionJob: the plan shown and its
// sliced G-code), read when needed and never copied; a print run pins that job in the document while it runs,
// so no other model or plan shown meanwhile can change what the devices do. Without a plan Start run is
// disabled.
//
// The printer (PrinterSection, PrinterLinkOwner): when one is connected, a print run has it print every step
// the sliced job gave G-code for and follows its job; without a printer or G-code the operator
// prints each region and presses Region done. The job timeline lists every step with its state and times.
// E-STOP covers both devices: it sends the platform's and the printer's emergency stops at once, and the
// line under it shows each device's stop confirmed or still being resent.
//
// The robot cell (RobotCellSection), the connection form's device "Robot cell" (chosen, its section shows in place
// of the Modbus device's status, controls and print run and of the printer; it follows the document's machine
// when that is the robot cell): a Universal Robots arm carrying the part under a fixed extruder runs a
// robot job (`multidir robot-program` OUT) with hardware's robot run; its steps go to the same job timeline, its
// lost link to the banner, its stop to the line under E-STOP, and E-STOP stops it with the other devices.
//
// Limits: commands are checked by the driver against the document's machine when it fits the device (a rotary
// platform profile for the platform, a tilt-rotate one for the arm), otherwise against a default profile of
// the device's kind; the choice is made at Connect. The device chosen follows the machine when its kind
// changes; Connect connects exactly the device, transport and unit entered.
#include <QString>
#include <QTimer>
#include <QWidget>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "multidir/core/search/decomposition.h"
#include "multidir/hardware/print_run.h"
#include "ui/device/device_snapshot.h"
#include "ui/device/plan_steps.h"
#include "ui/document/print_job.h"

class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QAction;
class QFormLayout;
class QPlainTextEdit;
class QPushButton;
class QToolBar;

namespace multidir::ui {

class ConnectionForm;
class DeviceLink;
class JobTimeline;
class PrintRunDriver;
class PrinterLinkOwner;
class PrinterSection;
class RobotCellSection;
class StudioDocument;

class HardwarePanel : public QWidget {
  Q_OBJECT

 public:
  // Shows and runs `document`'s job; `document` (not owned) must outlive the panel.
  explicit HardwarePanel(StudioDocument* document, QWidget* parent = nullptr);
  ~HardwarePanel() override;
  HardwarePanel(const HardwarePanel&) = delete;
  HardwarePanel& operator=(const HardwarePanel&) = delete;

  [[nodiscard]] DeviceLink* deviceLink() const { return m_link; }
  [[nodiscard]] PrintRunDriver* printRunDriver() const { return m_run; }
  [[nodiscard]] ConnectionForm* connectionForm() const { return m_form; }
  [[nodiscard]] PrinterLinkOwner* printerLink() const { return m_printerLink; }
  [[nodiscard]] PrinterSection* printerSection() const { return m_printerSection; }
  [[nodiscard]] JobTimeline* jobTimeline() const { return m_timeline; }
  [[nodiscard]] RobotCellSection* robotCellSection() const { return m_robotCell; }
  // The latest outcome or problem shown under the controls.
  [[nodiscard]] QString messageText() const;
  [[nodiscard]] bool messageIsError() const { return m_messageIsError; }
  // The operator prompt of the print run ("Print region 1 (file region-01.stl), then press Region done.").
  [[nodiscard]] QString promptText() const;
  // The limits the next Connect uses (see the header comment).
  [[nodiscard]] core::MachineSpec machineForNextConnection() const;
  // Regions of the job the next (or running) print run runs; 0 without a plan.
  [[nodiscard]] int planRegionCount() const;
  // Options of the next print run (settle time, move timeout, clocks).
  void setPrintRunOptions(const hardware::PrintRunOptions& options) { m_runOptions = options; }
  // Options of the next printer link (poll interval, timeouts).
  void setPrinterLinkOptions(const hardware::PrinterLinkOptions& options);
  // The G-code of every region of the job, in printing order (the document's session job). Empty: no G-code
  // (the operator prints each region).
  [[nodiscard]] std::vector<StepGcode> jobGcode() const;
  // Each device's stop under the E-STOP ("Platform: E-STOP confirmed. Printer: E-STOP being resent…"); empty
  // when no stop is latched.
  [[nodiscard]] QString stopsText() const;
  // The banner above the panel (link lost, device not reachable, run held); empty when hidden.
  [[nodiscard]] QString bannerText() const;
  // A print run is under way: started and neither finished nor aborted (paused and faulted runs too).
  [[nodiscard]] bool isRunUnderWay() const;
  // Where the run is, as the Step line says it ("2 of 3: paused (region-02.stl, ...)").
  [[nodiscard]] QString runStepText() const;
  // Before the studio quits during a run: the run is aborted through its own stop path (the platform's stop
  // latched, the printer's job cancelled and its heaters off) and the platform is sent Stop as well; a robot
  // job run is stopped and waited for (RobotCellSection::stopForQuit).
  void stopDevicesForQuit();
  // The step (0-based) a run of the session's job would resume from: the first one the last run of this same
  // job did not finish before it was aborted; nullopt when the last run of it was not aborted.
  [[nodiscard]] std::optional<std::size_t> resumableStep() const;
  // Adds an E-STOP button to `bar` that is shown while a device is connected; returns its action.
  QAction* addEmergencyStopTo(QToolBar* bar);

 public slots:
  // The Connect and Disconnect buttons.
  void connectDevice();
  void disconnectDevice();
  // The E-STOP buttons: the platform's and the printer's emergency stops at once (through the print run when
  // one is under way, so that it ends Aborted).
  void emergencyStopAll();

 signals:
  // The region (index from 0) the run is at, for the viewer to highlight; -1 when no run is under way.
  void currentRegionChanged(int region);
  // A device session opened (Connect) or closed (Disconnect).
  void sessionOpenChanged(bool open);

 private:
  enum class MessageTopic { General, Run };

  QWidget* buildSafetyBar();
  QGroupBox* buildConnectionGroup();
  QGroupBox* buildStatusGroup();
  QGroupBox* buildControlsGroup();
  QGroupBox* buildRunGroup();
  void onSnapshot(const DeviceSnapshot& snapshot);
  void onCommandFinished(const QString& command, bool ok, const QString& problem);
  void onConnectFinished(bool connected, const QString& problem);
  void onRunStateChanged(hardware::PrintRunState state);
  void onPrintRequested(int region, const QString& regionFile);
  void jog(double direction);
  void goTo();
  // Start run: after an aborted run of the same job, asks first (resume from the first step not done, or
  // start again, either once the operator confirmed the platform is clear: "restartRunBox").
  void startRun();
  void startRunFrom(std::size_t firstStep);
  // Restart step: the printer lost the interrupted step's job; asks the operator to clear the platform of what
  // the first attempt printed ("restartStepBox"), then prints the step again from its start.
  void restartStep();
  // Shows, under the run's buttons, that the printer has no job to resume, and offers Restart step.
  void updateJobGone();
  // Says why Start run was refused, in the message line and under the button.
  void refuseStart(const QString& text);
  void runEvent(const QString& event, const core::Status& status);
  void setMessage(const QString& text, bool error, MessageTopic topic = MessageTopic::General);
  void updateBanner();
  void styleEmergencyStop(QPushButton* estop) const;
  void updateLimits();
  void updateKindWidgets();
  void updateControls();
  void updateClockTexts();
  void updateRunTexts();
  void updateStops();
  void onMachineChanged();

  DeviceLink* m_link = nullptr;
  PrintRunDriver* m_run = nullptr;
  PrinterLinkOwner* m_printerLink = nullptr;
  PrinterSection* m_printerSection = nullptr;
  JobTimeline* m_timeline = nullptr;
  RobotCellSection* m_robotCell = nullptr;
  QLabel* m_stops = nullptr;
  StudioDocument* m_document;
  std::shared_ptr<const void> m_runFiles;  // the G-code files of the last run started, kept until the next
  ConnectionForm* m_form = nullptr;
  QLabel* m_limits = nullptr;
  QPushButton* m_connect = nullptr;
  QPushButton* m_disconnect = nullptr;

  QGroupBox* m_statusGroup = nullptr;
  QGroupBox* m_controlsGroup = nullptr;
  QGroupBox* m_runGroup = nullptr;
  QLabel* m_banner = nullptr;
  QFormLayout* m_statusForm = nullptr;
  QLabel* m_state = nullptr;
  QLabel* m_enabled = nullptr;
  QLabel* m_position = nullptr;
  QLabel* m_moving = nullptr;
  QLabel* m_homed = nullptr;
  QLabel* m_fault = nullptr;
  QLabel* m_heartbeat = nullptr;
  QLabel* m_linkProblem = nullptr;

  QPushButton* m_enable = nullptr;
  QPushButton* m_home = nullptr;
  QPushButton* m_clearFault = nullptr;
  QDoubleSpinBox* m_jogStep = nullptr;
  QComboBox* m_jogAxis = nullptr;
  QPushButton* m_jogMinus = nullptr;
  QPushButton* m_jogPlus = nullptr;
  QDoubleSpinBox* m_targetAngle = nullptr;
  QDoubleSpinBox* m_targetTilt = nullptr;
  QDoubleSpinBox* m_targetAzimuth = nullptr;
  QLabel* m_targetAngleLabel = nullptr;
  QLabel* m_targetTiltLabel = nullptr;
  QLabel* m_targetAzimuthLabel = nullptr;
  QPushButton* m_goTo = nullptr;
  QPushButton* m_stop = nullptr;
  QPushButton* m_estop = nullptr;
  QPushButton* m_windowEstop = nullptr;  // in the main window's toolbar, when added
  QAction* m_windowEstopAction = nullptr;
  QLabel* m_message = nullptr;
  bool m_messageIsError = false;
  MessageTopic m_messageTopic = MessageTopic::General;
  bool m_wasStale = false;  // the last snapshot was stale

  QLabel* m_planSummary = nullptr;
  QPushButton* m_startRun = nullptr;
  QLabel* m_startRunRefusal = nullptr;
  QLabel* m_runStep = nullptr;
  QLabel* m_runElapsed = nullptr;
  QLabel* m_prompt = nullptr;
  QPushButton* m_regionDone = nullptr;
  QPushButton* m_pause = nullptr;
  QPushButton* m_resume = nullptr;
  QPushButton* m_abort = nullptr;
  QLabel* m_jobGone = nullptr;
  QPushButton* m_restartStep = nullptr;
  QPlainTextEdit* m_runLog = nullptr;

  QTimer m_clockTimer;  // refreshes the heartbeat age and the run's elapsed time from the last snapshot
  // The machine the device choice last followed: only a change of kind (or to or from the robot cell) moves
  // the choice.
  struct MachineFollowed {
    core::MachineKind kind = core::MachineKind::ThreeAxis;
    bool robotCell = false;
    bool operator!=(const MachineFollowed& other) const { return kind != other.kind || robotCell != other.robotCell; }
  };
  std::optional<MachineFollowed> m_followedMachine;
  bool m_linkUsesProfile = false;  // the open link's limits are the profile's (not defaults)
  hardware::PrintRunOptions m_runOptions;
  // The last run that was aborted: its job's plan and the first step it did not finish.
  struct AbortedRun {
    std::shared_ptr<const core::Decomposition> plan;
    std::size_t firstStepNotDone = 0;
    std::size_t stepCount = 0;
  };
  std::optional<AbortedRun> m_aborted;
};

}  // namespace multidir::ui
