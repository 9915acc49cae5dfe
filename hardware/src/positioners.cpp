// Adapters that let the print-run sequencer drive the real drivers.
#include <future>
#include <mutex>
#include <optional>

#include "multidir/hardware/print_run.h"
#include "multidir/hardware/robot_arm.h"
#include "multidir/hardware/rotary_platform.h"

namespace multidir::hardware {
namespace {

// A command future the adapter keeps, to report a write that failed after startMove returned.
class PendingCommand {
 public:
  void set(std::future<core::Status> future) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_future = std::move(future);
    m_failure.reset();
  }
  // The failure of the last command, once known.
  std::optional<std::string> failure() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_failure && m_future.valid() &&
        m_future.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
      const core::Status status = m_future.get();
      if (!status.ok()) m_failure = status.error().describe();
    }
    return m_failure;
  }

 private:
  mutable std::mutex m_mutex;
  mutable std::future<core::Status> m_future;
  mutable std::optional<std::string> m_failure;
};

// The command future is ready at once when refused; otherwise the command is on its way.
core::Status immediateOutcome(std::future<core::Status>& future, PendingCommand& pending) {
  if (future.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    core::Status status = future.get();
    if (!status.ok()) return status;
    return core::Done{};
  }
  pending.set(std::move(future));
  return core::Done{};
}

class RotaryPositioner : public Positioner {
 public:
  explicit RotaryPositioner(RotaryPlatform& platform) : m_platform(platform) {}

  core::Status startMove(const PlatformOrientation& target) override {
    if (target.kind != PlatformOrientation::Kind::Rotary)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "the rotary platform cannot take a tilt/azimuth orientation: plan for a 4dof machine",
                         m_platform.name()};
    m_target = target.rotaryDegrees;
    auto future = m_platform.moveTo(target.rotaryDegrees);
    return immediateOutcome(future, m_pending);
  }
  core::Status stopMotion() override {
    m_target.reset();
    auto future = m_platform.stop();
    return immediateOutcome(future, m_pending);
  }
  core::Status emergencyStop() override {
    m_target.reset();
    auto future = m_platform.emergencyStop();
    return immediateOutcome(future, m_pending);
  }
  core::Status clearStop() override { return m_platform.clearStop(); }
  PositionerSnapshot snapshot() const override {
    const RotaryStatus s = m_platform.status();
    PositionerSnapshot snap;
    snap.linkUp = s.link == LinkState::Connected;
    snap.moving = s.moving || s.homing;
    snap.reached = m_target && m_platform.reached(*m_target);
    snap.faulted = s.fault != RotaryFault::None;
    snap.stopLatched = s.stop.latched();
    snap.stopConfirmed = s.stop.latched() && s.stop.confirmed;
    if (auto failed = m_pending.failure()) {
      snap.faulted = true;
      snap.problem = *failed;
    } else if (snap.faulted || !snap.linkUp) {
      snap.problem = s.lastError.empty() ? std::string("fault: ") + rotaryFaultName(s.fault) : s.lastError;
    }
    return snap;
  }
  std::string name() const override { return m_platform.name(); }

 private:
  RotaryPlatform& m_platform;
  std::optional<double> m_target;
  PendingCommand m_pending;
};

class RobotPositioner : public Positioner {
 public:
  explicit RobotPositioner(RobotArm& arm) : m_arm(arm) {}

  core::Status startMove(const PlatformOrientation& target) override {
    if (target.kind != PlatformOrientation::Kind::TiltAzimuth)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "the robot arm cannot take a rotary angle: plan for a 5dof machine", m_arm.name()};
    m_target = target;
    auto future = m_arm.moveTo(target.tiltDegrees, target.azimuthDegrees);
    return immediateOutcome(future, m_pending);
  }
  core::Status stopMotion() override {
    m_target.reset();
    auto future = m_arm.stop();
    return immediateOutcome(future, m_pending);
  }
  core::Status emergencyStop() override {
    m_target.reset();
    auto future = m_arm.emergencyStop();
    return immediateOutcome(future, m_pending);
  }
  core::Status clearStop() override { return m_arm.clearStop(); }
  PositionerSnapshot snapshot() const override {
    const RobotStatus s = m_arm.status();
    PositionerSnapshot snap;
    snap.linkUp = s.link == LinkState::Connected;
    snap.moving = s.state == RobotProgramState::Moving;
    snap.reached = m_target && m_arm.reached(m_target->tiltDegrees, m_target->azimuthDegrees);
    snap.faulted = s.state == RobotProgramState::Fault || s.state == RobotProgramState::Halted || !s.programAlive;
    snap.stopLatched = s.stop.latched();
    snap.stopConfirmed = s.stop.latched() && s.stop.confirmed;
    if (auto failed = m_pending.failure()) {
      snap.faulted = true;
      snap.problem = *failed;
    } else if (snap.faulted || !snap.linkUp) {
      snap.problem = s.lastError.empty() ? std::string("program ") + robotProgramStateName(s.state) : s.lastError;
    }
    return snap;
  }
  std::string name() const override { return m_arm.name(); }

 private:
  RobotArm& m_arm;
  std::optional<PlatformOrientation> m_target;
  PendingCommand m_pending;
};

}  // namespace

std::unique_ptr<Positioner> makePositioner(RotaryPlatform& platform) {
  return std::make_unique<RotaryPositioner>(platform);
}
std::unique_ptr<Positioner> makePositioner(RobotArm& arm) { return std::make_unique<RobotPositioner>(arm); }

}  // namespace multidir::hardware
