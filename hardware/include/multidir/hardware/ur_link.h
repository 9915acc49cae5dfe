#pragma once
// The link to a Universal Robots controller (docs/hardware.md, "UR controller"): its dashboard server (power,
// brakes, program state, stops), its secondary interface (programs sent as URScript text; the controller's
// robot messages read back: textmsg texts, runtime exceptions with their line, error codes with UR's words), its
// real-time interface (the joints, speeds, TCP, robot, safety and program state of every control tick) and RTDE
// (the output integer register the programs write the running movel's number to, robot::kMovelRegister: the
// real-time interface does not carry the registers).
//
// A worker thread reads both streams and keeps status(); when a socket closes or the real-time stream stays
// silent for `silenceLimit`, the link is lost: status() says so and why, and the worker reconnects every
// `reconnectInterval` until the controller answers again.
//
// The stop rule (stop_latch.h): stop() and emergencyStop() latch. The worker sends the stop's dashboard
// commands at once when the link is up, again every `stopResendInterval` until the real-time state shows the
// program stopped and every joint at rest (an emergency stop: also the arm powered off), and again first thing
// after every reconnect; nothing is sent while a stop is latched, until clearStop(), which is refused until the
// stop was confirmed. stop: dashboard "stop" (the program stops, the arm brakes on its path); emergency stop:
// dashboard "stop" then "power off" (the arm brakes and its power is cut), the strongest stop UR's client
// interfaces offer: a real emergency stop is the cell's e-stop circuit, which no network link replaces.
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/hardware/stop_latch.h"

namespace multidir::hardware {

struct UrLinkSettings {
  std::string host = "127.0.0.1";
  int dashboardPort = 29999;
  int secondaryPort = 30002;
  int realtimePort = 30003;
  int rtdePort = 30004;
  std::chrono::milliseconds replyTimeout{2000};  // a dashboard reply
  std::chrono::milliseconds silenceLimit{1000};  // no real-time package this long: the link is lost
  std::chrono::milliseconds reconnectInterval{250};
  std::chrono::milliseconds stopResendInterval{200};
};

// "HOST" or "HOST:PORT" (PORT the dashboard's; the secondary, real-time and RTDE ports follow it as on the
// simulator: PORT+1, PORT+2, PORT+3; without PORT UR's own 29999, 30002, 30003, 30004). InvalidParameter for a bad text.
core::Result<UrLinkSettings> parseUrAddress(const std::string& text);

struct UrLinkStatus {
  bool connected = false;               // all three interfaces up and the real-time stream flowing
  bool linkLost = false;                // was connected, is not now
  std::string linkProblem;              // why not ("" when connected)
  std::uint64_t reconnects = 0;         // times the link came back after a loss
  double controllerTime = 0.0;          // the real-time package's time (s)
  std::string robotMode;                // "POWER_OFF", "IDLE", "RUNNING", ...
  std::string safetyMode;               // "NORMAL", "PROTECTIVE_STOP", ...
  std::string programState;             // "STOPPED", "PLAYING", "PAUSED"
  std::array<double, 6> joints{};       // rad
  std::array<double, 6> jointSpeeds{};  // rad/s
  std::array<double, 6> tcp{};          // x, y, z (m), rotation vector (rad)
  bool atRest = true;                   // every joint speed below 1e-6 rad/s
  // The movel the program runs (RTDE's output_int_register_24, written by the program before each movel:
  // 1-based within the program, 0 outside any movel) and the controller time of the RTDE package it came in.
  int movelRegister = 0;
  double movelRegisterTime = -1.0;
  // Program starts (into PLAYING) and ends (back to STOPPED) seen in the real-time stream since connect().
  std::uint64_t programStarts = 0;
  std::uint64_t programEnds = 0;
  StopLatch stop;
};

// One robot message in UR's words: "textmsg: ...", "runtime exception at line L, column C: ...",
// "error C<code>A<argument>: ...".
struct UrLinkMessage {
  enum class Kind { Text, RuntimeException, ErrorCode };
  Kind kind = Kind::Text;
  std::string text;  // the controller's own text
  int line = 0;      // runtime exception
  int column = 0;
  int code = 0;  // error code
  [[nodiscard]] std::string describe() const;
};

class UrLink {
 public:
  explicit UrLink(UrLinkSettings settings);
  ~UrLink();  // disconnects
  UrLink(const UrLink&) = delete;
  UrLink& operator=(const UrLink&) = delete;

  // Connects the four interfaces (RTDE: protocol version 2, its output recipe started) and waits for the first real-time package. DeviceUnreachable naming the
  // interface and port that did not answer. The worker keeps the link up from then on until disconnect().
  core::Status connect();
  void disconnect();

  // Dashboard command, its reply line. DeviceUnreachable when the link is down or no reply came in time.
  core::Result<std::string> dashboard(const std::string& command);
  // Powers the arm on and releases its brakes when it is not RUNNING yet, waiting up to `limit` for each.
  // DeviceFault with the robot's modes when it does not come up (an emergency stop pressed, a protective stop).
  core::Status powerOn(std::chrono::milliseconds limit = std::chrono::milliseconds(30000));
  // Sends a program's text on the secondary interface. Refused (DeviceFault) while a stop is latched;
  // DeviceUnreachable while the link is down.
  core::Status sendProgram(const std::string& script);

  void stop();
  void emergencyStop();
  // Releases a confirmed stop latch; InvalidParameter (naming why) while it is unconfirmed.
  core::Status clearStop();

  [[nodiscard]] UrLinkStatus status() const;
  // The robot messages received since the last call.
  std::vector<UrLinkMessage> takeMessages();

 private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::hardware
