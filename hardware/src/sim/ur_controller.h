#pragma once
// The simulated UR controller without its sockets (ur_simulator.cpp serves it): the dashboard's commands, the
// secondary interface's programs (the URScript subset of urscript_program.h) and the real-time state, with the
// arm moving by the kinematic model one 8 ms control tick at a time. Time is what tick() advanced: nothing here
// reads a clock, so tests step it exactly. Not thread-safe: the simulator holds its mutex around every call.
//
// Motion (docs/hardware.md, "UR controller"): movej moves every joint on one trapezoidal profile (the joint with
// the longest way at the commanded a and v, the others in proportion); movel moves the TCP on a straight line
// (orientation by the shortest rotation) on a trapezoidal profile at a and v, and solves the inverse kinematics
// every tick on the branch nearest the current joints. Moves end at rest (blend radii are read, not blended), so
// a statement after a movel (write_output_integer_register before the next movel) runs when the arm is at the
// movel's end; on a real controller, with a blend, it runs when the blend into the next move begins.
// Every tick is checked against the arm's joint position and speed limits: a violation is a protective stop;
// with a cell (watchCollisions), so is a link or the platform touching one of its bodies or the table.
// Stops (stop, pause, protective stop, power off, emergency stop) brake every joint to rest together, at
// kStopDecelerationRadPerS2 for the joint that takes longest, from the speeds of the last tick.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "multidir/robot/cell.h"
#include "multidir/robot/ur_kinematics.h"
#include "sim/arm_collision_watch.h"
#include "ur/ur_wire.h"
#include "ur/urscript_program.h"

namespace multidir::hardware::sim {

constexpr double kUrTickSeconds = 0.008;  // the e-Series control loop: 125 Hz
// The nozzle heater (analog in 0 = temperature / 300 C follows analog out 1 = set point / 300 C): a hot end of
// MultiDir's cells heats at about 3 C/s and cools at about 1 C/s in still air.
constexpr double kNozzleHeatingCPerS = 3.0;
constexpr double kNozzleCoolingCPerS = 1.0;
constexpr double kNozzleFullScaleC = 300.0;
constexpr double kAmbientC = 25.0;
// UR lets a protective stop be unlocked 5 s after it happened (dashboard "unlock protective stop").
constexpr double kProtectiveStopUnlockSeconds = 5.0;
// Every stop (stop, pause, protective stop, power off, emergency stop) brakes each joint at this deceleration, a
// category 1/2 stop as UR's arms make it in a few tenths of a second from full speed; the arm's own acceleration
// limit (movej's 1.4 rad/s^2) is for planned motion, far gentler than a stop.
constexpr double kStopDecelerationRadPerS2 = 10.0;
// Powering on takes the arm through POWER_ON to IDLE.
constexpr double kPowerOnSeconds = 0.5;

struct UrTraceSample {
  double time = 0.0;
  robot::Joints q{};
  std::array<double, 6> tcp{};  // x, y, z (mm), rotation vector (rad), base frame
  double analogOut0 = 0.0;      // extruder speed, fraction of the cell's maxFilamentMmPerS
  double analogOut1 = 0.0;      // nozzle set point, fraction of 300 C
  double nozzleC = 0.0;
  std::string program;  // the program running ("" when none)
  int line = 0;         // its statement's line (0 when none)
};

enum class UrControllerFault { ProtectiveStop, EmergencyStop, ProgramError };

class UrController {
 public:
  UrController(robot::ArmModel arm, const robot::Joints& initial);

  // The cell's bodies and table (simulate --cell): from now on every tick's motion is checked against them
  // (arm_collision_watch.h) and a contact is a protective stop. Without it the arm moves in free space.
  void watchCollisions(const robot::Cell& cell);

  // Advances one control tick (kUrTickSeconds).
  void tick();
  [[nodiscard]] double time() const { return m_time; }

  // One dashboard command line (without its line end) and UR's reply; `quit` is set for "quit".
  std::string dashboard(const std::string& command, bool& quit);
  // A program received on the secondary interface: run it (it replaces a running one after the arm is at rest),
  // or refuse it with a runtime exception naming the line, or, above the bound, saying its size and the bound.
  void receiveProgram(const std::string& text);
  // The largest program the controller compiles (docs/robot-cell.md, "Programs the controller accepts").
  void setMaxProgramBytes(std::size_t bytes) { m_maxProgramBytes = bytes; }

  // Faults, now.
  void protectiveStop(const std::string& reason);
  void pressEmergencyStop();                   // the teach pendant's e-stop button
  void releaseEmergencyStop();                 // released: the arm stays powered off until "power on"
  void programError(const std::string& text);  // a runtime exception in the running program's current line

  // Observation.
  [[nodiscard]] ur::UrRealtimeState realtime() const;
  [[nodiscard]] const robot::Joints& joints() const { return m_q; }
  [[nodiscard]] bool atRest() const;
  [[nodiscard]] ur::UrRobotMode robotMode() const { return m_robotMode; }
  [[nodiscard]] ur::UrSafetyMode safetyMode() const { return m_safetyMode; }
  [[nodiscard]] ur::UrProgramState programState() const { return m_programState; }
  [[nodiscard]] const std::string& programName() const { return m_programName; }
  [[nodiscard]] int currentLine() const;
  [[nodiscard]] double analogOut(int index) const { return m_analogOut[static_cast<std::size_t>(index)]; }
  [[nodiscard]] bool digitalOut(int index) const { return (m_digitalOut >> index) & 1u; }
  // General purpose output integer register 0..47 (write_output_integer_register; RTDE's output_int_register_N).
  [[nodiscard]] std::int32_t outputIntRegister(int index) const {
    return m_outputIntRegisters[static_cast<std::size_t>(index)];
  }
  [[nodiscard]] double nozzleC() const { return m_nozzleC; }
  [[nodiscard]] const std::string& lastFault() const { return m_lastFault; }  // UR's words, "" when none
  [[nodiscard]] std::size_t programsFinished() const { return m_programsFinished; }
  // The messages the secondary interface sends since the last call (text, runtime exceptions, error codes).
  std::vector<ur::UrRobotMessage> takeMessages();
  // The samples of the ticks since the last call in which a program ran or the arm moved.
  std::vector<UrTraceSample> takeTrace();
  // The TCP pose (mm, rotation vector) of joints `q` with the program's TCP.
  [[nodiscard]] std::array<double, 6> tcpPose(const robot::Joints& q) const;

 private:
  struct Profile {  // a trapezoidal (or triangular) speed profile over `distance`
    double distance = 0.0, acceleration = 1.0, peak = 0.0, accelTime = 0.0, cruiseTime = 0.0;
    [[nodiscard]] double duration() const { return 2.0 * accelTime + cruiseTime; }
    [[nodiscard]] double at(double t) const;  // distance covered at time t
  };
  enum class Activity { None, MoveJ, MoveL, Sleep, Wait, Braking };

  static Profile profile(double distance, double speed, double acceleration);
  void runProgram();
  bool startStatement(const ur::UrStatement& statement);  // true when it takes time
  double advanceActivity(double budget);                  // returns the part of `budget` left when the activity ended
  void beginBraking();
  void haltProgram(ur::UrProgramState state);
  void fault(ur::UrSafetyMode mode, const std::string& words, int code, int argument = 0);
  bool checkLimits(const robot::Joints& next);    // position limits; a fault when violated
  bool checkSpeeds(const robot::Joints& before);  // this tick's change against the speed limits
  void message(ur::UrRobotMessage::Kind kind, const std::string& text, int line = 0, int column = 0, int code = 0,
               int argument = 0);
  void record();

  robot::ArmModel m_arm;
  std::optional<ArmCollisionWatch> m_collisionWatch;
  double m_time = 0.0;
  robot::Joints m_q{};
  robot::Joints m_qd{};                                     // speeds of the last tick
  robot::Joints m_qTarget{};                                // where the planner wants the arm this tick
  Eigen::Isometry3d m_tcp = Eigen::Isometry3d::Identity();  // TCP in the flange frame (mm)
  ur::UrRobotMode m_robotMode = ur::UrRobotMode::PowerOff;
  ur::UrSafetyMode m_safetyMode = ur::UrSafetyMode::Normal;
  ur::UrProgramState m_programState = ur::UrProgramState::Stopped;
  double m_poweredOnAt = -1.0;       // when "power on" came (IDLE kPowerOnSeconds later)
  double m_protectiveStopAt = -1.0;  // when the protective stop happened
  bool m_emergencyPressed = false;
  bool m_powerOffAfterBraking = false;

  std::size_t m_maxProgramBytes = robot::kDefaultMaxProgramBytes;
  std::optional<ur::UrProgram> m_program;
  std::optional<ur::UrProgram> m_nextProgram;  // received while the arm still braked
  std::string m_programName;
  std::string m_tickProgram;  // the program playing when the current tick began
  std::size_t m_pc = 0;       // the statement running, or the next one
  std::size_t m_programsFinished = 0;

  Activity m_activity = Activity::None;
  double m_elapsed = 0.0;
  Profile m_profile;
  robot::Joints m_fromQ{}, m_toQ{};
  Eigen::Isometry3d m_fromPose = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d m_toPose = Eigen::Isometry3d::Identity();
  double m_waitBelow = 0.0;
  robot::Joints m_brakeFromQ{}, m_brakeFromQd{};
  double m_brakeDuration = 0.0;

  std::array<double, 2> m_analogOut{};
  unsigned m_digitalOut = 0;
  // Kept from one program to the next; MultiDir's programs write theirs first, so nothing depends on that.
  std::array<std::int32_t, 48> m_outputIntRegisters{};
  double m_nozzleC = kAmbientC;
  std::string m_lastFault;
  std::vector<ur::UrRobotMessage> m_messages;
  std::vector<UrTraceSample> m_trace;
};

// p[x, y, z, rx, ry, rz] (m, rotation vector) as a pose in mm, and back.
Eigen::Isometry3d urPoseToIsometry(const std::array<double, 6>& pose);
std::array<double, 6> isometryToUrPose(const Eigen::Isometry3d& pose);

}  // namespace multidir::hardware::sim
