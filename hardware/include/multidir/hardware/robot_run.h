#pragma once
// A robot job (the folder `multidir robot-program` writes: robot-job.json and one URScript program per step)
// printed on a Universal Robots cell (docs/hardware.md, "`multidir run OUT --robot`"): the arm powered on, each step's
// program sent in order and waited for, with progress and the time left from the job's per-step seconds; a
// fault ends the run with the robot's own words; a stop request stops the arm (latched until the robot confirms
// it, resent after a reconnect), a second one powers it off; a pause request brings the arm to a safe point and
// the next one resumes the step where it stopped (robot_pause.h).
//
// The run is one blocking call on the caller's thread (the CLI's main thread, a studio worker): what happens
// comes out through RobotRunListener, what the operator asks goes in through RobotRunRequests, from any thread.
// No console text and no words for a person other than the robot's own and the reasons a run ends.
#include <atomic>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/robot_pause.h"
#include "multidir/hardware/stop_latch.h"
#include "multidir/hardware/ur_link.h"

namespace multidir::hardware {

// One program of a step: a step runs as one program, or, split to what the controller accepts (docs/robot-cell.md,
// "Programs the controller accepts"), as parts sent one after another.
struct RobotJobPart {
  std::string program;  // file name in the job folder
  std::string script;   // its text
};

struct RobotJobStep {
  int step = 0;
  std::string program;   // its first program's file name (the step's only one unless split)
  std::vector<RobotJobPart> parts;  // in the order they run; at least one
  double seconds = 0.0;  // the job's estimate
};

struct RobotJob {
  std::string robot;
  std::vector<RobotJobStep> steps;
  // From the job's copy of its cell (cell.json): what a pause needs; absent, the run cannot pause.
  bool canPause = false;
  std::string whyNoPause;
  PauseGeometry pause;
};

// robot-job.json (format multidir-robot-job, version 2 with each step's "parts", or version 1 with one "program"
// per step; `folder` is the job folder or that file) and every step's programs, read before anything moves. FileNotFound / MalformedFile whose message names the file and
// says what to do (write it again with `multidir robot-program`).
core::Result<RobotJob> readRobotJob(const std::string& folder);

// What the operator asks of a run, counted from any thread (a signal handler: the counters are lock-free).
struct RobotRunRequests {
  std::atomic<int> stops{0};              // the first ends the run with a stop; a second, while unconfirmed, powers off
  std::atomic<int> pauseToggles{0};       // each: a pause while a step runs, the resume while paused
  std::string stopName = "the operator";  // who stops, for the run's end ("stopped by Ctrl-C"); set before the run
};

// Where a step is, once a second while its program plays.
struct RobotRunProgress {
  int step = 0;              // the job's step number
  int steps = 0;             // the job's step count
  std::string programState;  // the controller's: "PLAYING", ...
  double fraction = 0.0;     // of the step, from the robot's time against the job's estimate (0..1)
  double secondsLeft = 0.0;  // of the job: this step's estimate less its time so far, and the steps after it
  int movel = -1;            // the movel under way (0-based) on the step's programs, -1 when none is found
  int movels = 0;            // the step's movel count (0 when its program cannot be read as movels)
  int part = 1;              // the step's program running (1-based), of `parts`
  int parts = 1;
};

// A step paused at a safe point: the arm stands liftMm off the nozzle after `movel` (0-based) of `movels`, the
// step's (over all its parts), in its program `part` (1-based) of `parts`.
struct RobotRunPause {
  int step = 0;
  int movel = 0;
  int movels = 0;
  double liftMm = 0.0;
  int part = 1;
  int parts = 1;
};

// The run's events, called on the run's thread; every one optional.
class RobotRunListener {
 public:
  virtual ~RobotRunListener() = default;
  virtual void poweringOn() {}  // the arm was not RUNNING
  virtual void stepStarting(int /*step*/, int /*steps*/, const std::string& /*program*/) {}
  virtual void robotMessage(const UrLinkMessage& /*message*/) {}  // every text and fault, as it comes
  virtual void progress(const RobotRunProgress& /*progress*/) {}
  virtual void cannotPause(const std::string& /*why*/) {}  // a pause asked of a job without cell.json
  virtual void paused(const RobotRunPause& /*pause*/) {}
  virtual void resuming(int /*step*/, int /*movel*/, const std::string& /*program*/) {}
  virtual void poweringOff() {}                            // a second stop request
  virtual void stopSettled(const StopLatch& /*latch*/) {}  // confirmed, or given up after 10 s
  virtual void stepDone(int /*step*/, int /*steps*/, double /*robotSeconds*/, double /*estimateSeconds*/) {}
};

struct RobotRunEnd {
  enum class Kind {
    Done,     // every step from `from` on printed
    Refused,  // nothing moved: the robot runs another program, or its arm did not power on
    Stopped   // the run stopped in `step`: a stop request, a fault, a lost link
  };
  Kind kind = Kind::Done;
  int step = 0;
  std::string why;  // Refused and Stopped: the reason, in the robot's words where it gave them
  int stepsPrinted = 0;
};

// Runs steps `from`..last (1-based) of `job` on the robot `link` is connected to (UrLink::connect() done).
RobotRunEnd runRobotJob(UrLink& link, const RobotJob& job, int from, RobotRunRequests& requests,
                        RobotRunListener& listener);

}  // namespace multidir::hardware
