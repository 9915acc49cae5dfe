#pragma once
// A robot job run (hardware::runRobotJob, docs/hardware.md "The robot cell section") on a worker thread of its own,
// for the Hardware dock's robot cell section: the run blocks for the whole job, so it never runs on the GUI
// thread. Its events come back as queued signals on the GUI thread; the operator's pause, resume and stop go
// in through the run's request counters, which the run reads as it goes.
//
// Thread: the object lives on the GUI thread; start(), requestPauseOrResume() and requestStop() are called
// there. The destructor asks a run still under way to stop and waits for it to end.
#include <QObject>
#include <QString>
#include <memory>
#include <thread>

#include "multidir/core/common/result.h"
#include "multidir/hardware/robot_run.h"

namespace multidir::ui {

class RobotCellRun : public QObject {
  Q_OBJECT

 public:
  explicit RobotCellRun(QObject* parent = nullptr);
  ~RobotCellRun() override;
  RobotCellRun(const RobotCellRun&) = delete;
  RobotCellRun& operator=(const RobotCellRun&) = delete;

  // Runs `job` from its first step on the robot `link` is connected to. InvalidParameter while a run is under
  // way or when the link is missing.
  core::Status start(std::shared_ptr<hardware::UrLink> link, hardware::RobotJob job);
  // From start() until finished() was delivered.
  [[nodiscard]] bool isActive() const { return m_active; }
  // Paused at a safe point (between paused() and resuming()).
  [[nodiscard]] bool isPaused() const { return m_paused; }
  // A pause asked for while a step runs; the resume while paused.
  void requestPauseOrResume();
  // The run ends with the program stopped; a second request, while the stop is unconfirmed, powers the arm off.
  void requestStop();
  // Quitting: the stop asked for and the run waited for (the stop confirmed, or the run's 10 s for it), on
  // the calling thread; the run is no longer active once it returns (finished() still follows, queued).
  void stopAndWait();

 signals:
  void stepStarting(int step, int steps, const QString& program);
  // Once a second while a step's program plays: the step's share done (0..1), the job's time left (s), the
  // movel under way (0-based, -1 unknown) of the step's movels.
  void progressed(int step, int steps, double fraction, double secondsLeft, int movel, int movels);
  // A robot message in the robot's own words; `fault`: an error or runtime exception, not a textmsg.
  void robotSaid(const QString& words, bool fault);
  void cannotPause(const QString& why);
  void paused(int step, int movel, int movels, double liftMm);
  void resuming(int step, int movel);
  void poweringOff();
  void stopSettled(bool confirmed, const QString& problem);
  void stepDone(int step, int steps, double robotSeconds);
  // The run ended: kind as hardware::RobotRunEnd::Kind, the step it stopped in, why (the robot's words).
  void finished(int kind, int step, const QString& why, int stepsPrinted);

 private:
  class Forwarder;
  std::unique_ptr<hardware::RobotRunRequests> m_requests;
  std::shared_ptr<hardware::UrLink> m_link;
  std::thread m_thread;
  bool m_active = false;
  bool m_paused = false;
};

}  // namespace multidir::ui
