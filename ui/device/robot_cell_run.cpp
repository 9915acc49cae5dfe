#include "ui/device/robot_cell_run.h"

#include <utility>

namespace multidir::ui {

// The run's listener on the worker thread: every event a signal of the run object, which lives on the GUI
// thread, so each is queued there.
class RobotCellRun::Forwarder : public hardware::RobotRunListener {
 public:
  explicit Forwarder(RobotCellRun* run) : m_run(run) {}

  void stepStarting(int step, int steps, const std::string& program) override {
    emit m_run->stepStarting(step, steps, QString::fromStdString(program));
  }
  void robotMessage(const hardware::UrLinkMessage& message) override {
    emit m_run->robotSaid(QString::fromStdString(message.describe()),
                          message.kind != hardware::UrLinkMessage::Kind::Text);
  }
  void progress(const hardware::RobotRunProgress& p) override {
    emit m_run->progressed(p.step, p.steps, p.fraction, p.secondsLeft, p.movel, p.movels);
  }
  void cannotPause(const std::string& why) override { emit m_run->cannotPause(QString::fromStdString(why)); }
  void paused(const hardware::RobotRunPause& p) override { emit m_run->paused(p.step, p.movel, p.movels, p.liftMm); }
  void resuming(int step, int movel, const std::string& /*program*/) override { emit m_run->resuming(step, movel); }
  void poweringOff() override { emit m_run->poweringOff(); }
  void stopSettled(const hardware::StopLatch& latch) override {
    emit m_run->stopSettled(latch.confirmed, QString::fromStdString(latch.problem));
  }
  void stepDone(int step, int steps, double robotSeconds, double /*estimateSeconds*/) override {
    emit m_run->stepDone(step, steps, robotSeconds);
  }

 private:
  RobotCellRun* m_run;
};

RobotCellRun::RobotCellRun(QObject* parent) : QObject(parent) {
  connect(this, &RobotCellRun::paused, this, [this] { m_paused = true; });
  connect(this, &RobotCellRun::resuming, this, [this] { m_paused = false; });
  connect(this, &RobotCellRun::finished, this, [this] {
    if (m_thread.joinable()) m_thread.join();
    m_active = false;
    m_paused = false;
  });
}

RobotCellRun::~RobotCellRun() {
  if (m_thread.joinable()) {
    m_requests->stops.fetch_add(1);
    m_thread.join();
  }
}

core::Status RobotCellRun::start(std::shared_ptr<hardware::UrLink> link, hardware::RobotJob job) {
  if (m_active)
    return core::Error{core::ErrorCode::InvalidParameter, "a robot job run is under way: stop it first", "robot run"};
  if (!link) return core::Error{core::ErrorCode::InvalidParameter, "no robot is connected: Connect first", "robot run"};
  if (m_thread.joinable()) m_thread.join();
  m_requests = std::make_unique<hardware::RobotRunRequests>();
  m_requests->stopName = "the operator";
  m_link = std::move(link);
  m_active = true;
  m_paused = false;
  hardware::RobotRunRequests* requests = m_requests.get();
  std::shared_ptr<hardware::UrLink> runLink = m_link;
  m_thread = std::thread([this, requests, runLink, job = std::move(job)] {
    Forwarder forwarder(this);
    const hardware::RobotRunEnd end = hardware::runRobotJob(*runLink, job, 1, *requests, forwarder);
    emit finished(static_cast<int>(end.kind), end.step, QString::fromStdString(end.why), end.stepsPrinted);
  });
  return core::Done{};
}

void RobotCellRun::requestPauseOrResume() {
  if (m_active) m_requests->pauseToggles.fetch_add(1);
}

void RobotCellRun::stopAndWait() {
  if (!m_active) return;
  m_requests->stops.fetch_add(1);
  if (m_thread.joinable()) m_thread.join();
  m_active = false;
  m_paused = false;
}

void RobotCellRun::requestStop() {
  if (m_active) m_requests->stops.fetch_add(1);
}

}  // namespace multidir::ui
