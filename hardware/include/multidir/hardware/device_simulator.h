#pragma once
// A Modbus TCP server that behaves like MultiDir's devices, for tests, demos and `multidir simulate`:
// the rotary platform controller at one unit id and the robot arm's registers 128-255 (with the URScript
// program's behaviour) at every other unit id. Motion runs at finite speed, homing takes time, both
// heartbeat watchdogs work, and faults can be injected. Both devices keep the control lock of docs/hardware.md
// ("One controller at a time"): one session controls each; stops and e-stops are taken from anyone.
//
// Listens on 127.0.0.1 unless told otherwise; port 0 picks a free port (see port()). Runs on its own thread
// (one poll() loop over non-blocking sockets, so a slow or hostile client never holds up the others); every
// method may be called from any thread.
//
// Under load and against bad input: at most maxClients connections (later ones are accepted and closed at
// once, and counted); a client that starts a request and does not finish it within requestTimeout is
// disconnected; every Modbus request gets its reply or the exception the specification names (quantity 0 or
// above 125: illegal data value; unknown function: illegal function), framed by the length field so the
// connection stays in sync; a frame whose protocol id is not 0 (not Modbus) or whose length no Modbus
// request can have closes that connection.
#include <Eigen/Core>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

struct SimulatorOptions {
  bool rotary = true;  // serve the rotary platform controller
  bool robot = true;   // serve the robot arm registers
  std::string listenAddress = "127.0.0.1";  // an IPv4 address; anything but loopback only when asked for
  int port = 0;                             // 0: a free port chosen by the system
  int rotaryUnitId = 1;                     // requests to this unit id go to the rotary controller
  int maxClients = 64;                      // 1..1000 connections at once
  std::chrono::milliseconds requestTimeout{1000};  // 1..60000 ms from a request's first byte to its last
  // The control lock (docs/hardware.md, "One controller at a time") lapses when the session holding it has
  // written nothing with its SESSION for this long (1..60000 ms), as the URScript program's owner_timeout_s.
  std::chrono::milliseconds controlTimeout{3000};

  double rotaryInitialAngleDegrees = 7.5;   // where the platform stands at power-on (not homed)
  double rotaryHomingSpeedDegreesPerSecond = 90.0;
  double rotaryMinAngleDegrees = -180.0;    // the controller's own limits (beyond them: rejected command)
  double rotaryMaxAngleDegrees = 180.0;
  double robotMaxSpeedDegreesPerSecond = 90.0;  // at speed 100 %
  double robotMaxTiltDegrees = 90.0;           // the program's own limit (beyond it: fault 1)
  // The rotary controller's shaft in the platform frame at rest (x = azimuth 0, z = the platform's normal):
  // the machine files' rotation axis, +X for a plan decomposed about the platform frame's x.
  Eigen::Vector3d rotaryShaftAxis = Eigen::Vector3d::UnitX();
  // The clock of commandLog()'s times (motion always runs on the system's steady clock); tests inject the
  // clock they share with the printer simulator, to compare both devices' records.
  std::function<std::chrono::steady_clock::time_point()> steadyNow;
};

enum class SimulatedDevice { Rotary, Robot };

// One command write (any write that touches more than the heartbeat, its timeout, SESSION and CLAIM) as the
// simulator received it, taken or refused.
struct SimulatedCommandRecord {
  std::chrono::steady_clock::time_point at;  // SimulatorOptions::steadyNow
  SimulatedDevice device = SimulatedDevice::Rotary;
  // The COMMAND register's value in the write (rotary: 1 enable ... 4 move, 5 stop, 6 e-stop; robot: 1 move,
  // 2 stop, 3 halt, 4 reset), -1 when the write did not touch it.
  int command = -1;
};

// A copy of the simulated rotary controller's state.
struct SimulatedRotaryState {
  double angleDegrees = 0.0;
  // Where the platform physically points: the rotation taking platform-frame vectors (x = azimuth 0, z = its
  // normal at rest) to the room's, from the shaft's angle (a positive angle tilts the top towards z x shaft).
  Eigen::Matrix3d platformOrientation = Eigen::Matrix3d::Identity();
  double targetAngleDegrees = 0.0;
  bool enabled = false;
  bool homed = false;
  bool homing = false;
  bool moving = false;
  int faultCode = 0;  // as in the FAULT_CODE register
  std::uint16_t controlOwner = 0;  // OWNER: the session in control, 0 when nobody is
};

struct SimulatedRobotState {
  double tiltDegrees = 0.0;     // as the program reports them: the platform-frame direction pointing up now
  double azimuthDegrees = 0.0;
  // The TCP's orientation relative to p_level, as the simulated program turned it (movel's shortest
  // rotation towards orientation_pose(tilt, azimuth) of multidir_platform.script).
  Eigen::Matrix3d platformOrientation = Eigen::Matrix3d::Identity();
  int programState = 1;  // as in the STATE register (the simulated program runs from the start)
  int faultCode = 0;
  std::uint16_t acknowledgedSequence = 0;
  std::uint16_t controlOwner = 0;  // OWNER: the session in control, 0 when nobody is
};

class DeviceSimulator {
 public:
  explicit DeviceSimulator(SimulatorOptions options = {});
  ~DeviceSimulator();  // stops
  DeviceSimulator(const DeviceSimulator&) = delete;
  DeviceSimulator& operator=(const DeviceSimulator&) = delete;

  // Binds, listens and starts the thread. InvalidParameter for bad options; Internal when the address
  // cannot be bound, saying why (port in use, not an address of this machine, port needs root).
  core::Status start();
  void stop();  // closes every connection and joins the thread; idempotent
  [[nodiscard]] bool running() const;
  [[nodiscard]] int port() const;  // the port listened on (the chosen one when options.port was 0)
  [[nodiscard]] std::string address() const;  // "127.0.0.1:40123"

  // Fault injection. Each stays in force until changed.
  // Closes every client connection now, and refuses new ones for `refuseFor`.
  void dropConnections(std::chrono::milliseconds refuseFor = std::chrono::milliseconds(0));
  // Holds every reply this long (0: answer at once). Requests keep their order.
  void setReplyDelay(std::chrono::milliseconds delay);
  // Answers every request to `device` with this Modbus exception code (1..11; 0: answer normally).
  void setExceptionReply(SimulatedDevice device, int exceptionCode);
  // Answers the next `count` writes of a stop or e-stop command to `device` (rotary COMMAND 5 or 6, robot
  // COMMAND 2 or 3) with this Modbus exception code (6 busy, 4 device failure...) and takes none of them, as a
  // controller busy in a state change or a gateway with a failing link would; later ones are taken. Each is
  // still in commandLog().
  void refuseStops(SimulatedDevice device, int exceptionCode, int count);
  // The rotary motor stops turning although the controller believes it moves.
  void setMotorStuck(bool stuck);
  // The device stops answering heartbeats: the rotary controller freezes its HEARTBEAT_ECHO, the robot
  // program freezes its heartbeat (as if the controller's loop or the URScript program hung).
  void setHeartbeatAnswering(SimulatedDevice device, bool answering);

  // Observation.
  [[nodiscard]] SimulatedRotaryState rotaryState() const;
  [[nodiscard]] SimulatedRobotState robotState() const;
  // Requests received by a device, and those among them that write more than the heartbeat registers and the
  // control lock's (target, speed, command, sequence...): a refused command must leave the second at 0.
  [[nodiscard]] std::uint64_t requestCount(SimulatedDevice device) const;
  [[nodiscard]] std::uint64_t commandWriteCount(SimulatedDevice device) const;
  // Every command write, in the order received.
  [[nodiscard]] std::vector<SimulatedCommandRecord> commandLog() const;
  [[nodiscard]] int connectionCount() const;  // clients connected now
  // Connections closed by the simulator: refused beyond maxClients (or during dropConnections' refusal),
  // and clients dropped for a request timeout, a non-Modbus frame or a broken length.
  [[nodiscard]] std::uint64_t refusedConnectionCount() const;
  [[nodiscard]] std::uint64_t droppedClientCount() const;

 private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::hardware
