#include "ui/device/robot_cell_section.h"

#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QVBoxLayout>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <utility>

#include "multidir/robot/cell.h"
#include "multidir/robot/cell_file.h"
#include "multidir/robot/robot_program.h"
#include "ui/device/job_timeline.h"
#include "ui/device/robot_cell_run.h"
#include "ui/document/studio_document.h"
#include "ui/jobs/cell_job.h"

namespace multidir::ui {
namespace {

QLabel* valueLabel(QWidget* parent, const QString& name) {
  auto* label = new QLabel(parent);
  label->setObjectName(name);
  label->setWordWrap(true);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  return label;
}

QPushButton* button(const QString& text, const QString& name, QWidget* parent) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  return b;
}

// One timeline entry for the robot run: the step (1-based) in `state`, now.
hardware::PrintRunLogEntry timelineEntry(int step, hardware::PrintRunState state) {
  hardware::PrintRunLogEntry entry;
  entry.wallTime = std::chrono::system_clock::now();
  entry.step = static_cast<std::size_t>(std::max(0, step - 1));
  entry.state = state;
  return entry;
}

QString minutesText(double seconds) {
  const long long s = std::llround(std::max(0.0, seconds));
  return QStringLiteral("%1:%2:%3")
      .arg(s / 3600)
      .arg((s / 60) % 60, 2, 10, QLatin1Char('0'))
      .arg(s % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace

RobotCellSection::RobotCellSection(StudioDocument* document, JobTimeline* timeline, QWidget* parent)
    : QGroupBox(tr("Robot cell (Universal Robots)"), parent), m_document(document), m_timeline(timeline) {
  setObjectName(QStringLiteral("robotCellSection"));
  m_run = new RobotCellRun(this);
  m_convert = new CellJob(this);

  m_address = new QLineEdit(this);
  m_address->setObjectName(QStringLiteral("robotAddress"));
  m_address->setPlaceholderText(tr("host or host:port (the dashboard's port; UR's own 29999 when left out)"));
  m_jobFolder = new QLineEdit(this);
  m_jobFolder->setObjectName(QStringLiteral("robotJobFolder"));
  m_jobFolder->setPlaceholderText(tr("the folder 'multidir robot-program' wrote"));
  m_browse = button(tr("Open job folder…"), QStringLiteral("robotBrowse"), this);
  m_convertButton = button(tr("Convert the sliced job"), QStringLiteral("robotConvert"), this);
  m_convertButton->setToolTip(
      tr("The plan's sliced job turned into the cell's programs (as multidir robot-program "
         "does), for the cell on the Machine tab"));
  m_cancelConvert = button(tr("Cancel"), QStringLiteral("robotConvertCancel"), this);
  m_convertProgress = new QProgressBar(this);
  m_convertProgress->setObjectName(QStringLiteral("robotConvertProgress"));
  m_convertProgress->setRange(0, 1000);
  m_convertProgress->setTextVisible(false);
  m_connect = button(tr("Connect"), QStringLiteral("robotConnect"), this);
  m_disconnect = button(tr("Disconnect"), QStringLiteral("robotDisconnect"), this);
  m_state = valueLabel(this, QStringLiteral("robotState"));
  m_joints = valueLabel(this, QStringLiteral("robotJoints"));
  m_runStep = valueLabel(this, QStringLiteral("robotRunStep"));
  m_stop = valueLabel(this, QStringLiteral("robotStopText"));
  m_message = valueLabel(this, QStringLiteral("robotMessage"));
  m_start = button(tr("Start job"), QStringLiteral("robotStart"), this);
  m_pause = button(tr("Pause"), QStringLiteral("robotPause"), this);
  m_resume = button(tr("Resume"), QStringLiteral("robotResume"), this);
  m_stopButton = button(tr("Stop"), QStringLiteral("robotStopButton"), this);
  m_estop = button(tr("E-STOP"), QStringLiteral("robotEstop"), this);
  m_estop->setStyleSheet(QStringLiteral("QPushButton { background-color: #c62828; color: white; font-weight: bold; }"));

  auto* folderRow = new QHBoxLayout;
  folderRow->addWidget(m_jobFolder, 1);
  folderRow->addWidget(m_browse);
  auto* convertRow = new QHBoxLayout;
  convertRow->addWidget(m_convertButton);
  convertRow->addWidget(m_convertProgress, 1);
  convertRow->addWidget(m_cancelConvert);
  auto* linkRow = new QHBoxLayout;
  linkRow->addWidget(m_connect);
  linkRow->addWidget(m_disconnect);
  auto* runRow = new QHBoxLayout;
  runRow->addWidget(m_start);
  runRow->addWidget(m_pause);
  runRow->addWidget(m_resume);
  runRow->addWidget(m_stopButton);
  runRow->addWidget(m_estop);
  auto* form = new QFormLayout;
  form->addRow(tr("Robot:"), m_address);
  form->addRow(QString(), linkRow);
  form->addRow(tr("State:"), m_state);
  form->addRow(tr("Joints:"), m_joints);
  form->addRow(tr("Robot job:"), folderRow);
  form->addRow(QString(), convertRow);
  form->addRow(tr("Step:"), m_runStep);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(runRow);
  layout->addWidget(m_stop);
  layout->addWidget(m_message);

  connect(m_browse, &QPushButton::clicked, this, &RobotCellSection::chooseJobFolder);
  connect(m_convertButton, &QPushButton::clicked, this, &RobotCellSection::convertSlicedJob);
  connect(m_cancelConvert, &QPushButton::clicked, this, &RobotCellSection::cancelConversion);
  connect(m_convert, &CellJob::progressed, this,
          [this](double fraction) { m_convertProgress->setValue(static_cast<int>(std::lround(1000.0 * fraction))); });
  connect(m_convert, &CellJob::cancelled, this, [this] {
    setMessage(tr("Conversion cancelled."), false);
    updateControls();
  });
  connect(m_jobFolder, &QLineEdit::textChanged, this, [this] { updateControls(); });
  connect(m_connect, &QPushButton::clicked, this, &RobotCellSection::connectRobot);
  connect(m_disconnect, &QPushButton::clicked, this, &RobotCellSection::disconnectRobot);
  connect(m_start, &QPushButton::clicked, this, &RobotCellSection::startRun);
  connect(m_pause, &QPushButton::clicked, this, &RobotCellSection::pauseRun);
  connect(m_resume, &QPushButton::clicked, this, &RobotCellSection::resumeRun);
  connect(m_stopButton, &QPushButton::clicked, this, &RobotCellSection::stopRobot);
  connect(m_estop, &QPushButton::clicked, this, &RobotCellSection::emergencyStop);

  connect(m_run, &RobotCellRun::stepStarting, this, [this](int step, int steps, const QString& program) {
    m_timeline->apply(timelineEntry(step, hardware::PrintRunState::Printing), QString());
    m_runStep->setText(tr("%1 of %2: %3 sent").arg(step).arg(steps).arg(program));
  });
  connect(m_run, &RobotCellRun::progressed, this,
          [this](int step, int steps, double fraction, double secondsLeft, int movel, int movels) {
            const QString move =
                movel >= 0 ? tr("movel %1 of %2").arg(movel + 1).arg(movels) : tr("between movels (a joint move)");
            m_runStep->setText(tr("%1 of %2: %3, %4 %, about %5 left")
                                   .arg(step)
                                   .arg(steps)
                                   .arg(move)
                                   .arg(std::lround(100.0 * fraction))
                                   .arg(minutesText(secondsLeft)));
          });
  connect(m_run, &RobotCellRun::robotSaid, this, [this](const QString& words, bool fault) {
    if (fault) setMessage(tr("The robot reports: %1").arg(words), true);
  });
  connect(m_run, &RobotCellRun::cannotPause, this,
          [this](const QString& why) { setMessage(tr("Cannot pause: %1. Stop ends the run.").arg(why), true); });
  connect(m_run, &RobotCellRun::paused, this, [this](int step, int movel, int movels, double liftMm) {
    const QString reason = tr("paused after movel %1 of %2; the extruder stopped, the platform %3 mm off the nozzle")
                               .arg(movel + 1)
                               .arg(movels)
                               .arg(liftMm, 0, 'f', 0);
    m_timeline->apply(timelineEntry(step, hardware::PrintRunState::Paused), reason);
    m_runStep->setText(tr("%1 of %2: %3").arg(step).arg(m_steps).arg(reason));
    setMessage(tr("Paused at a safe point. Resume goes on from there; Stop ends the run."), false);
    updateControls();
  });
  connect(m_run, &RobotCellRun::resuming, this, [this](int step, int movel) {
    m_timeline->apply(timelineEntry(step, hardware::PrintRunState::Printing), QString());
    setMessage(tr("Resuming step %1 after movel %2: back down to the nozzle, then the rest of the step.")
                   .arg(step)
                   .arg(movel + 1),
               false);
    updateControls();
  });
  connect(m_run, &RobotCellRun::stepDone, this, [this](int step, int steps, double robotSeconds) {
    m_runStep->setText(
        tr("%1 of %2 done in %3 of the robot's time").arg(step).arg(steps).arg(minutesText(robotSeconds)));
  });
  connect(m_run, &RobotCellRun::finished, this, &RobotCellSection::onRunFinished);

  m_timer.setInterval(100);
  connect(&m_timer, &QTimer::timeout, this, &RobotCellSection::refresh);
  refresh();
  updateControls();
}

RobotCellSection::~RobotCellSection() {
  if (m_connectThread.joinable()) m_connectThread.join();
  delete m_run;  // stops and joins a run still under way, before the link goes
  m_run = nullptr;
}

void RobotCellSection::setAddress(const QString& hostPort) { m_address->setText(hostPort); }
void RobotCellSection::setJobFolder(const QString& folder) { m_jobFolder->setText(folder); }
bool RobotCellSection::isRunUnderWay() const { return m_run != nullptr && m_run->isActive(); }
bool RobotCellSection::isConverting() const { return m_convert->isRunning(); }
QString RobotCellSection::jobFolder() const { return m_jobFolder->text(); }
bool RobotCellSection::isRunPaused() const { return m_run != nullptr && m_run->isPaused(); }
QString RobotCellSection::messageText() const { return m_message->text(); }
QString RobotCellSection::stateText() const { return m_state->text(); }
QString RobotCellSection::runStepText() const { return m_runStep->text(); }
QString RobotCellSection::stopText() const { return m_stop->text(); }

QString RobotCellSection::linkLostText() const {
  if (!m_link || !m_connected) return {};
  const hardware::UrLinkStatus s = m_link->status();
  if (!s.linkLost) return {};
  QString text = tr("The link to the robot at %1 is lost (%2). The robot's values are unknown; MultiDir keeps "
                    "trying to reconnect and sends a latched stop first thing once it is back.")
                     .arg(m_address->text(), QString::fromStdString(s.linkProblem));
  if (isRunUnderWay()) text += QLatin1Char(' ') + tr("The robot job run is ending: it stops the program.");
  return text;
}

void RobotCellSection::chooseJobFolder() {
  const QString folder = QFileDialog::getExistingDirectory(
      this, tr("Open a robot job folder (multidir robot-program OUT)"), m_jobFolder->text());
  if (!folder.isEmpty()) m_jobFolder->setText(folder);
}

bool RobotCellSection::convertSlicedJob() {
  if (isConverting() || isRunUnderWay()) return false;
  if (!m_document->cell()) {
    setMessage(tr("There is no robot cell: choose the machine \"robot arm under a fixed extruder\"."), true);
    return false;
  }
  const PrintJob session = m_document->sessionJob();
  if (!session.plan || session.steps.empty()) {
    setMessage(tr("The plan shown is not sliced: slice it with the cell's profile (ur5-cell-0.8) first."), true);
    return false;
  }
  auto dir = std::make_unique<QTemporaryDir>();
  if (!dir->isValid()) {
    setMessage(tr("No folder for the converted job: %1").arg(dir->errorString()), true);
    return false;
  }
  const std::filesystem::path sliced = std::filesystem::path(session.steps.front().path).parent_path();
  const std::filesystem::path base(dir->path().toStdString());
  const std::filesystem::path out = base / "robot-job";
  const robot::Cell cell = *m_document->cell();
  std::shared_ptr<const void> files = session.files;  // the sliced job's folder stays while the work reads it
  auto steps = std::make_shared<int>(0);
  const bool started = m_convert->start([cell, sliced, base, out, files, steps](core::JobContext context) {
    // The job's cell.json is a copy of the cell file: the document's cell written as the file it reads back as.
    const std::filesystem::path cellFile = base / "cell.json";
    if (core::Status written = robot::writeCell(cell, cellFile); !written)
      return QString::fromStdString(written.error().describe());
    auto job = robot::planRobotJob(sliced, cell, robot::RobotProgramOptions{}, context);
    if (!job) return QString::fromStdString(job.error().describe());
    if (core::Status written = robot::writeRobotJob(*job, cellFile, out); !written)
      return QString::fromStdString(written.error().describe());
    *steps = static_cast<int>(job->steps.size());
    return QString();
  });
  if (!started) return false;
  m_convertedDir = std::move(dir);
  m_convertedFolder.clear();
  m_convertedPlan.reset();
  const std::shared_ptr<const core::Decomposition> plan = session.plan;
  const QString folder = QString::fromStdString(out.string());
  auto connection = std::make_shared<QMetaObject::Connection>();
  *connection =
      connect(m_convert, &CellJob::finished, this, [this, connection, plan, folder, steps](const QString& error) {
        disconnect(*connection);
        if (!error.isEmpty()) {
          setMessage(tr("The sliced job cannot be converted for the cell: %1").arg(error), true);
        } else {
          m_convertedFolder = folder;
          m_convertedPlan = plan;
          m_jobFolder->setText(folder);
          setMessage(tr("Converted for the cell: %1 steps in %2.").arg(*steps).arg(folder), false);
        }
        updateControls();
      });
  // A cancelled job emits cancelled, not finished: the handler goes with the next start.
  connect(
      m_convert, &CellJob::cancelled, this, [this, connection] { disconnect(*connection); }, Qt::SingleShotConnection);
  m_convertProgress->setValue(0);
  setMessage(tr("Converting the sliced job for the cell…"), false);
  updateControls();
  return true;
}

void RobotCellSection::cancelConversion() { m_convert->cancel(); }

void RobotCellSection::connectRobot() {
  if (m_connecting || isRunUnderWay()) return;
  core::Result<hardware::UrLinkSettings> settings = hardware::parseUrAddress(m_address->text().trimmed().toStdString());
  if (!settings) {
    setMessage(tr("The robot's address: %1").arg(QString::fromStdString(settings.error().describe())), true);
    return;
  }
  settings->replyTimeout = m_linkTemplate.replyTimeout;
  settings->silenceLimit = m_linkTemplate.silenceLimit;
  settings->reconnectInterval = m_linkTemplate.reconnectInterval;
  settings->stopResendInterval = m_linkTemplate.stopResendInterval;
  disconnectRobot();
  m_link = std::make_shared<hardware::UrLink>(*settings);
  m_connecting = true;
  setMessage(tr("Connecting to the robot at %1…").arg(m_address->text()), false);
  updateControls();
  if (m_connectThread.joinable()) m_connectThread.join();
  // connect() waits for the controller's answers: not on the GUI thread.
  std::shared_ptr<hardware::UrLink> link = m_link;
  m_connectThread = std::thread([this, link] {
    const core::Status connected = link->connect();
    const QString problem = connected ? QString() : QString::fromStdString(connected.error().describe());
    QMetaObject::invokeMethod(
        this, [this, problem] { onConnected(problem); }, Qt::QueuedConnection);
  });
}

void RobotCellSection::onConnected(const QString& problem) {
  if (m_connectThread.joinable()) m_connectThread.join();
  m_connecting = false;
  if (!problem.isEmpty()) {
    m_link.reset();
    setMessage(tr("The robot at %1 cannot be reached: %2").arg(m_address->text(), problem), true);
  } else {
    m_connected = true;
    m_timer.start();
    setMessage(tr("Connected to the robot at %1.").arg(m_address->text()), false);
  }
  refresh();
  updateControls();
  emit statusChanged();
}

void RobotCellSection::disconnectRobot() {
  if (isRunUnderWay()) {
    setMessage(tr("A robot job run is under way: Stop it before disconnecting."), true);
    return;
  }
  if (m_link && !m_connecting) {
    m_link->disconnect();
    m_link.reset();
  }
  m_connected = false;
  m_timer.stop();
  refresh();
  updateControls();
  emit statusChanged();
}

void RobotCellSection::refuse(const QString& text) { setMessage(tr("Start refused: %1").arg(text), true); }

void RobotCellSection::startRun() {
  if (isRunUnderWay()) return;
  if (!isConnected()) return refuse(tr("no robot is connected: Connect first."));
  core::Result<hardware::RobotJob> job = hardware::readRobotJob(m_jobFolder->text().trimmed().toStdString());
  if (!job) return refuse(QString::fromStdString(job.error().describe()));
  // The job's cell must be the document's: the programs put the nozzle where that cell says it is.
  const std::filesystem::path folder(m_jobFolder->text().trimmed().toStdString());
  const std::filesystem::path cellFile =
      (std::filesystem::is_directory(folder) ? folder : folder.parent_path()) / "cell.json";
  if (!m_document->cell())
    return refuse(tr("the document has no robot cell: set the cell on the Machine tab (the job was made for %1).")
                      .arg(QString::fromStdString(job->robot)));
  core::Result<robot::Cell> jobCell = robot::parseCell(cellFile);
  if (!jobCell)
    return refuse(
        tr("the job's cell (%1) cannot be read: %2")
            .arg(QString::fromStdString(cellFile.string()), QString::fromStdString(jobCell.error().describe())));
  if (robot::cellJson(*jobCell) != robot::cellJson(*m_document->cell()))
    return refuse(tr("the job's cell (%1) is not the cell on the Machine tab: convert the job again with this "
                     "cell, or load the job's cell on the Machine tab.")
                      .arg(QString::fromStdString(cellFile.string())));
  const PrintJob session = m_document->sessionJob();
  const int steps = static_cast<int>(job->steps.size());
  if (!session.plan) return refuse(tr("no plan is shown: open the plan the job was made from."));
  if (!m_convertedFolder.isEmpty() && m_jobFolder->text().trimmed() == m_convertedFolder &&
      m_convertedPlan != session.plan)
    return refuse(tr("the job was converted from another plan than the one shown: convert the sliced job again."));
  if (static_cast<int>(session.plan->regions.size()) != steps)
    return refuse(tr("the job has %1 steps but the plan shown has %2 regions: it was made from another plan.")
                      .arg(steps)
                      .arg(session.plan->regions.size()));
  const hardware::UrLinkStatus status = m_link->status();
  if (status.stop.latched()) {
    if (!status.stop.confirmed)
      return refuse(
          tr("the robot has not confirmed its stop yet (%1).").arg(QString::fromStdString(status.stop.problem)));
    if (core::Status cleared = m_link->clearStop(); !cleared)
      return refuse(QString::fromStdString(cleared.error().describe()));
  }
  if (core::Result<PrintJob> pinned = m_document->pinSessionJob(); !pinned)
    return refuse(QString::fromStdString(pinned.error().describe()));
  std::vector<hardware::PrintStep> rows;
  for (const hardware::RobotJobStep& step : job->steps) {
    hardware::PrintStep row;
    row.regionFile = step.program;
    rows.push_back(row);
  }
  m_timeline->reset(rows);
  m_steps = steps;
  if (core::Status started = m_run->start(m_link, std::move(job.value())); !started) {
    m_document->unpinSessionJob();
    return refuse(QString::fromStdString(started.error().describe()));
  }
  m_runStep->setText(tr("starting: %1 steps").arg(steps));
  setMessage(tr("Robot job started: %1 steps.").arg(steps), false);
  updateControls();
  emit statusChanged();
}

void RobotCellSection::pauseRun() {
  if (!isRunUnderWay() || isRunPaused()) return;
  m_run->requestPauseOrResume();
  setMessage(tr("Pause asked for: the arm finishes the move under way, the extruder stops and the platform "
                "backs off the nozzle."),
             false);
}

void RobotCellSection::resumeRun() {
  if (!isRunPaused()) return;
  m_run->requestPauseOrResume();
}

void RobotCellSection::stopRobot() {
  if (isRunUnderWay())
    m_run->requestStop();
  else if (m_link && m_connected)
    m_link->stop();
  refresh();
}

void RobotCellSection::stopForQuit() {
  if (isRunUnderWay())
    m_run->stopAndWait();
  else if (m_link && m_connected)
    m_link->stop();
}

void RobotCellSection::emergencyStop() {
  // The link's emergency stop first (latched, resent until confirmed), then the run ends through its stop.
  if (m_link && m_connected) m_link->emergencyStop();
  if (isRunUnderWay()) m_run->requestStop();
  if (m_link && m_connected)
    setMessage(tr("E-STOP sent to the robot (stop, then power off). To go on: release it on the teach pendant "
                  "if pressed there; Start powers the arm on again once the robot confirmed the stop."),
               false);
  refresh();
  emit statusChanged();
}

void RobotCellSection::onRunFinished(int kind, int step, const QString& why, int stepsPrinted) {
  m_document->unpinSessionJob();
  switch (static_cast<hardware::RobotRunEnd::Kind>(kind)) {
    case hardware::RobotRunEnd::Kind::Done:
      m_timeline->apply(timelineEntry(m_steps, hardware::PrintRunState::Completed), QString());
      m_runStep->setText(tr("done: %1 steps printed").arg(stepsPrinted));
      setMessage(tr("The robot job is done: %1 steps printed.").arg(stepsPrinted), false);
      break;
    case hardware::RobotRunEnd::Kind::Refused:
      m_runStep->clear();
      setMessage(tr("The robot did not start the job: %1").arg(why), true);
      break;
    case hardware::RobotRunEnd::Kind::Stopped:
      m_timeline->apply(timelineEntry(step, hardware::PrintRunState::Faulted), why);
      m_runStep->setText(tr("stopped in step %1 of %2").arg(step).arg(m_steps));
      setMessage(tr("The run stopped in step %1: %2").arg(step).arg(why), true);
      break;
  }
  refresh();
  updateControls();
  emit statusChanged();
}

void RobotCellSection::setMessage(const QString& text, bool error) {
  m_message->setText(text);
  m_messageIsError = error;
  m_message->setStyleSheet(error ? QStringLiteral("color: #c62828;") : QString());
}

void RobotCellSection::refresh() {
  QString stopLine;
  if (!m_link || !m_connected) {
    m_state->setText(tr("not connected"));
    m_joints->setText(tr("unknown"));
  } else {
    const hardware::UrLinkStatus s = m_link->status();
    if (s.linkLost) {
      m_state->setText(tr("unknown: the link is lost (%1)").arg(QString::fromStdString(s.linkProblem)));
      m_joints->setText(tr("unknown"));
    } else {
      m_state->setText(tr("robot mode %1, safety mode %2, program %3")
                           .arg(QString::fromStdString(s.robotMode), QString::fromStdString(s.safetyMode),
                                QString::fromStdString(s.programState)));
      QStringList joints;
      for (double q : s.joints) joints << QString::number(q * 180.0 / M_PI, 'f', 2);
      m_joints->setText(tr("%1 deg").arg(joints.join(QStringLiteral(", "))));
    }
    if (s.stop.latched()) {
      const QString kind = s.stop.kind == hardware::StopKind::EmergencyStop ? tr("E-STOP") : tr("stop");
      stopLine = s.stop.confirmed ? tr("Robot: %1 confirmed by the robot.").arg(kind)
                                  : tr("Robot: %1 not confirmed yet (%2); MultiDir keeps resending it.")
                                        .arg(kind, QString::fromStdString(s.stop.problem));
    }
  }
  const bool changed = stopLine != m_stop->text();
  m_stop->setText(stopLine);
  m_stop->setVisible(!stopLine.isEmpty());
  const QString lost = linkLostText();
  if (changed || lost != m_lastLinkLost) {
    m_lastLinkLost = lost;
    emit statusChanged();
  }
}

void RobotCellSection::updateControls() {
  const bool running = isRunUnderWay();
  const bool connected = isConnected();
  m_connect->setEnabled(!running && !m_connecting);
  m_disconnect->setEnabled(connected && !running);
  m_address->setEnabled(!running && !m_connecting);
  const bool converting = isConverting();
  m_jobFolder->setEnabled(!running && !converting);
  m_browse->setEnabled(!running && !converting);
  m_convertButton->setEnabled(!running && !converting);
  m_cancelConvert->setEnabled(converting);
  m_convertProgress->setVisible(converting);
  m_start->setEnabled(connected && !running && !converting && !m_jobFolder->text().trimmed().isEmpty());
  m_pause->setEnabled(running && !isRunPaused());
  m_resume->setEnabled(running && isRunPaused());
  m_stopButton->setEnabled(connected);
  m_estop->setEnabled(connected);
}

}  // namespace multidir::ui
