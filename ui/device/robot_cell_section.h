#pragma once
// The robot cell section of the Hardware panel ("Robot cell (Universal Robots)"): the arm carries the part under
// the cell's fixed extruder (docs/robot-cell.md). Connect to the controller by host[:port] and watch it live
// (robot mode, safety mode, the program's state, the joint angles); open a robot job folder (`multidir
// robot-program` OUT) or convert the document's sliced job for the document's cell (robot::planRobotJob and
// writeRobotJob, as robot-program does, on a CellJob thread with progress and Cancel, into a folder the section
// keeps); Start runs it with hardware's robot run on a worker thread (RobotCellRun): the panel's job
// timeline lists its steps, the Step line says where it is with the movel under way and the job's time left;
// Pause brings the arm to a safe point, Resume goes on; Stop and E-STOP latch the robot's stop until it confirms
// it (UrLink resends it, also after a reconnect); a fault ends the run with the robot's own words.
//
// Start is refused, saying which, when the job's cell (its cell.json) is not the document's cell (the Machine
// tab's), when no plan is shown, when the job's step count is not the plan's region count, or when the job was
// converted here from another plan than the one shown; a run pins the document's session job
// (StudioDocument::pinSessionJob) until it ends.
//
// Truthfulness: no robot value is shown before the link's first real-time package; once the link is lost the
// values are marked unknown and linkLostText() gives the panel's banner its sentence.
//
// Thread: GUI thread. The link's status is read every 100 ms by a timer; connecting runs on a thread of its own.
#include <QGroupBox>
#include <QString>
#include <QTimer>
#include <memory>
#include <thread>

#include "multidir/core/search/decomposition.h"
#include "multidir/hardware/robot_run.h"
#include "multidir/hardware/ur_link.h"

class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTemporaryDir;

namespace multidir::ui {

class CellJob;
class JobTimeline;
class RobotCellRun;
class StudioDocument;

class RobotCellSection : public QGroupBox {
  Q_OBJECT

 public:
  // `document` and `timeline` (the panel's) must outlive the section.
  RobotCellSection(StudioDocument* document, JobTimeline* timeline, QWidget* parent = nullptr);
  ~RobotCellSection() override;
  RobotCellSection(const RobotCellSection&) = delete;
  RobotCellSection& operator=(const RobotCellSection&) = delete;

  void setAddress(const QString& hostPort);
  void setJobFolder(const QString& folder);
  // Options of the next link (timeouts), for tests and slow networks.
  void setLinkSettings(const hardware::UrLinkSettings& settings) { m_linkTemplate = settings; }
  [[nodiscard]] bool isConnected() const { return m_link != nullptr && m_connected; }
  [[nodiscard]] bool isRunUnderWay() const;
  [[nodiscard]] bool isConverting() const;
  // The job folder Start runs (typed, opened, or the conversion's).
  [[nodiscard]] QString jobFolder() const;
  [[nodiscard]] bool isRunPaused() const;
  // The latest outcome or problem (a refusal, the robot's words of a fault, the run's end).
  [[nodiscard]] QString messageText() const;
  [[nodiscard]] bool messageIsError() const { return m_messageIsError; }
  // "Robot mode RUNNING, safety mode NORMAL, program PLAYING"; "unknown" parts before the first read.
  [[nodiscard]] QString stateText() const;
  // Where the run is ("step 2 of 3: movel 120 of 800, 41 %, about 3 min left").
  [[nodiscard]] QString runStepText() const;
  // The robot's stop, while latched ("Robot: E-STOP confirmed by the robot."); empty otherwise.
  [[nodiscard]] QString stopText() const;
  // The sentence the panel's banner shows while the robot's link is lost ("" otherwise).
  [[nodiscard]] QString linkLostText() const;

 public slots:
  // Converts the document's sliced job for the document's cell into a robot job folder (off the GUI thread);
  // false when it cannot start (the reason in the message).
  bool convertSlicedJob();
  void cancelConversion();
  void connectRobot();
  void disconnectRobot();
  void startRun();
  void pauseRun();
  void resumeRun();
  void stopRobot();
  // Before the studio quits: a run under way stopped and waited for (up to the run's 10 s for the robot to
  // confirm the stop), else the robot sent its stop.
  void stopForQuit();
  // The arm's emergency stop (stop, then power off), latched and resent until the robot confirms it.
  void emergencyStop();

 signals:
  // The banner's or the stop line's text may have changed, or a run started or ended.
  void statusChanged();

 private:
  void chooseJobFolder();
  void onConnected(const QString& problem);
  void refresh();
  void refuse(const QString& text);
  void setMessage(const QString& text, bool error);
  void updateControls();
  void onRunFinished(int kind, int step, const QString& why, int stepsPrinted);

  StudioDocument* m_document;
  JobTimeline* m_timeline;
  RobotCellRun* m_run = nullptr;
  hardware::UrLinkSettings m_linkTemplate;
  std::shared_ptr<hardware::UrLink> m_link;
  bool m_connected = false;  // connect() succeeded on m_link
  bool m_connecting = false;
  std::thread m_connectThread;
  QTimer m_timer;
  int m_steps = 0;  // of the run under way or last run
  CellJob* m_convert = nullptr;
  std::unique_ptr<QTemporaryDir> m_convertedDir;               // holds the last conversion's job folder
  QString m_convertedFolder;                                   // "" when none
  std::shared_ptr<const core::Decomposition> m_convertedPlan;  // the plan it was converted from
  QString m_lastLinkLost;                                      // linkLostText() when statusChanged was last emitted

  QLineEdit* m_address = nullptr;
  QLineEdit* m_jobFolder = nullptr;
  QPushButton* m_browse = nullptr;
  QPushButton* m_convertButton = nullptr;
  QPushButton* m_cancelConvert = nullptr;
  QProgressBar* m_convertProgress = nullptr;
  QPushButton* m_connect = nullptr;
  QPushButton* m_disconnect = nullptr;
  QLabel* m_state = nullptr;
  QLabel* m_joints = nullptr;
  QLabel* m_runStep = nullptr;
  QLabel* m_stop = nullptr;
  QLabel* m_message = nullptr;
  bool m_messageIsError = false;
  QPushButton* m_start = nullptr;
  QPushButton* m_pause = nullptr;
  QPushButton* m_resume = nullptr;
  QPushButton* m_stopButton = nullptr;
  QPushButton* m_estop = nullptr;
};

}  // namespace multidir::ui
