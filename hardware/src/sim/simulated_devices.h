#pragma once
// The behaviour behind the simulator's registers: a rotary platform controller and the URScript program
// on the robot arm, each working on its block of holding registers (as libmodbus's mapping holds them).
// Time comes in as arguments, so the models are deterministic; the server thread calls them under its lock.
//
// Both keep the control lock of docs/hardware.md ("One controller at a time"): a session claims control
// through CLAIM, every command but a stop must carry the holder's SESSION, and the lock lapses when its holder
// has written nothing with its session for SimulatorOptions::controlTimeout. The controller refuses another
// session's writes at the Modbus level (exception 1, nothing written), as its firmware can; the robot's
// Modbus server takes every write, so the program ignores another session's commands, as the URScript does.
#include <chrono>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "multidir/hardware/device_simulator.h"

namespace multidir::hardware::sim {

using Clock = std::chrono::steady_clock;

class RotaryController {
 public:
  // `regs` points at registers 0..regs::rotary::kMapSize-1.
  RotaryController(const SimulatorOptions& options, std::uint16_t* regs, Clock::time_point now);

  // Before a client's write of `values` from `address` is applied: 0 takes it, else the Modbus exception that
  // refuses it. While a session controls the platform, only writes carrying its SESSION are taken, and
  // CLAIM alone, and a stop or e-stop alone in COMMAND (stopping is never refused).
  int writeRefusal(int address, const std::vector<std::uint16_t>& values, Clock::time_point now);
  // After a client wrote registers: takes a claim from CLAIM and a command from COMMAND (and clears both).
  void afterWrite(Clock::time_point now);
  // Advances motion and the watchdog by the time since the last step, then refreshes the status registers.
  void step(Clock::time_point now);

  void setStuck(bool stuck) { m_stuck = stuck; }
  void setEchoing(bool echoing) { m_echoing = echoing; }
  [[nodiscard]] SimulatedRotaryState state() const;

 private:
  void command(std::uint16_t code, Clock::time_point now);
  void reject() { m_fault = 4; m_moving = false; m_homing = false; }
  void lapseControl(Clock::time_point now);
  void publish();

  SimulatorOptions m_options;
  std::uint16_t* m_regs;
  double m_angle;
  double m_target = 0.0;
  bool m_enabled = false;
  bool m_homed = false;
  bool m_homing = false;
  bool m_moving = false;
  std::uint16_t m_fault = 0;
  bool m_stuck = false;
  bool m_echoing = true;
  std::uint16_t m_lastHeartbeat = 0;
  Clock::time_point m_lastLife;
  Clock::time_point m_lastStep;
  std::uint16_t m_owner = 0;       // the session in control (OWNER), 0 when nobody is
  Clock::time_point m_ownerLife;  // the holder's last write with its session
};

class RobotProgram {
 public:
  // `regs` points at register 128 (regs[0] is register 128).
  RobotProgram(const SimulatorOptions& options, std::uint16_t* regs, Clock::time_point now);

  // One cycle of the program: take a new command, move, watch the host's heartbeat, write the status.
  void step(Clock::time_point now);

  void setAnswering(bool answering) { m_answering = answering; }
  [[nodiscard]] SimulatedRobotState state() const;

 private:
  std::uint16_t& reg(int address) { return m_regs[address - 128]; }
  void command(std::uint16_t code, std::uint16_t session);
  void followControl(Clock::time_point now);
  void publish();

  SimulatorOptions m_options;
  std::uint16_t* m_regs;
  Eigen::Matrix3d m_orientation = Eigen::Matrix3d::Identity();  // the TCP relative to p_level
  Eigen::Matrix3d m_target = Eigen::Matrix3d::Identity();       // orientation_pose of the last move
  std::uint16_t m_state = 1;
  std::uint16_t m_fault = 0;
  std::uint16_t m_ack = 0;
  std::uint16_t m_heartbeat = 0;
  bool m_answering = true;
  std::uint16_t m_lastHostHeartbeat = 0;
  std::uint16_t m_lastSequence = 0;  // the SEQUENCE last seen, taken or ignored (ACK_SEQUENCE: last taken)
  Clock::time_point m_lastLife;
  Clock::time_point m_lastStep;
  std::uint16_t m_owner = 0;
  Clock::time_point m_ownerLife;
};

}  // namespace multidir::hardware::sim
