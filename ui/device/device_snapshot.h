#pragma once
// What the Hardware panel knows of the device it drives: which kind it is, how to reach it, and the last
// status the driver reported, in the panel's terms (plain values, copied to the GUI thread).
#include <QDateTime>
#include <QMetaType>
#include <QString>
#include <chrono>
#include <cstdint>
#include <optional>

#include "multidir/core/search/machine.h"
#include "multidir/hardware/connection.h"

namespace multidir::ui {

// RobotCell: a Universal Robots arm carrying the part under a fixed extruder (docs/robot-cell.md), driven by the
// Hardware panel's RobotCellSection over UR's own interfaces, never by a DeviceLink (Modbus).
enum class DeviceKind { RotaryPlatform, RobotArm, RobotCell };

// The panel's view of a link: Fault is Connected with the device in fault (rotary fault, robot program
// halted or faulted). Connecting covers the first attempt and the driver's reconnecting.
enum class DeviceState { Disconnected, Connecting, Connected, Fault };

struct DeviceLinkSettings {
  DeviceKind kind = DeviceKind::RotaryPlatform;
  hardware::ConnectionSettings connection;
  // Soft limits the driver checks every command against: RotaryPlatform for the rotary platform,
  // TiltRotate for the robot arm (see machineForDevice).
  core::MachineSpec machine;
  double rotarySpeedDegreesPerSecond = 20.0;  // (0, 655]
  int robotSpeedPercent = 50;                 // 1..100
};

struct DeviceSnapshot {
  DeviceKind kind = DeviceKind::RotaryPlatform;
  DeviceState state = DeviceState::Disconnected;
  hardware::LinkState link = hardware::LinkState::Disconnected;
  bool enabled = false;  // rotary: the drive is on; robot: the program runs (not halted)
  bool homed = false;    // rotary only
  bool homing = false;   // rotary only
  bool moving = false;
  bool atTarget = false;
  double angleDegrees = 0.0;        // rotary
  double targetAngleDegrees = 0.0;  // rotary: the last target the controller holds
  double tiltDegrees = 0.0;         // robot
  double azimuthDegrees = 0.0;      // robot
  double targetTiltDegrees = 0.0;
  double targetAzimuthDegrees = 0.0;
  // Whether the device values above were ever read in this session (a status with the link up). Before the
  // first good read they are the driver's defaults, not the device's: the panel shows none of them.
  bool hasRead = false;
  // The values were read, but the link is down since this wall-clock time: they are stale (the device may
  // have moved, faulted or stopped since). Unset while the link is up or before the first read.
  std::optional<QDateTime> staleSince;
  QString faultText;  // the fault in plain words, empty when none (and before the first read)
  // The driver's latest link or device problem that still applies (English, from the driver), empty when
  // none: a link problem clears once the link is back, a device problem after Clear fault.
  QString lastError;
  bool deviceAlive = false;  // the controller echoes the heartbeat / the robot program's heartbeat runs
  // When the GUI last received a status with the device alive (nullopt: not since connecting).
  std::optional<std::chrono::steady_clock::time_point> lastAlive;
  std::uint64_t polls = 0;

  // The values are the device's as read just now (link up and read at least once).
  [[nodiscard]] bool isFresh() const { return hasRead && !staleSince; }
};

// The machine profile's limits when `profile` fits `kind`; else a default profile of the device's kind with
// `profile`'s up direction. `usedProfile` (optional) tells which.
core::MachineSpec machineForDevice(DeviceKind kind, const std::optional<core::MachineSpec>& profile,
                                   bool* usedProfile = nullptr);

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::ui::DeviceSnapshot)
