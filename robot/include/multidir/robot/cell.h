#pragma once
// The robot cell (docs/robot-cell.md, "The cell file"): a UR arm carrying the printing platform on its flange,
// the extruder fixed on a frame with its nozzle tip at a known point of the robot base frame, the extruder's
// collision bodies, the table, and a safe home. Millimetres and radians inside; the file says degrees where
// its key does.
#include <Eigen/Geometry>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/robot/ur_kinematics.h"

namespace multidir::robot {

// A box in the base frame: `pose` takes the box's own frame (centred, axes along its edges) to the base.
struct CollisionBox {
  std::string name;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d sizeMm = Eigen::Vector3d::Zero();  // full edge lengths
};

// A solid cylinder in the base frame: from `baseMm` along the unit `axis` for `lengthMm`.
struct CollisionCylinder {
  std::string name;
  Eigen::Vector3d baseMm = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double radiusMm = 0.0;
  double lengthMm = 0.0;
};

// The largest robot program `multidir robot-program` writes, in bytes: a step above it is split into parts the
// controller accepts (docs/robot-cell.md, "Programs the controller accepts"). UR documents no bound; users report
// programs of about 1,000 to 2,500 movel targets (of the order of 100 to 250 kB) failing to start when sent to the
// controller and an 18 MB one crashing it, so the default stays below the smallest of those.
constexpr std::size_t kDefaultMaxProgramBytes = 100000;
// The smallest bound a cell may set: a part holds its own preamble, the step's closing lines and a few moves.
constexpr std::size_t kMinProgramBytes = 4096;

// What a program must keep (the checks of `multidir robot-program`).
struct CellMargins {
  double minReachMm = 20.0;           // the wrist centre's distance from the workspace's edges (reachMarginMm)
  double minWristDegrees = 10.0;      // |q5| (mod pi) away from 0 and 180 deg: the wrist singularity
  double maxJointStepDegrees = 20.0;  // joint change between samples 5 mm apart along a move (no flip)
  double tableClearanceMm = 5.0;      // platform, part and wrist above the table plane by this much
};

// How the programs move (URScript's movel/movej parameters, docs/robot-cell.md "Programs").
struct CellMotion {
  double travelSpeedMmPerS = 250.0;     // movel speed of travel moves
  double toolAccelMmPerS2 = 1200.0;     // movel acceleration
  double blendRadiusMm = 0.0;           // movel blend radius of extrusion moves (0: stop at each point; docs/robot-cell.md)
  double jointSpeedDegreesPerS = 60.0;  // movej between steps
  double jointAccelDegreesPerS2 = 80.0;
};

struct Cell {
  std::string name;
  ArmModel arm;                   // the model's table with the cell's joint limits
  Eigen::Vector3d nozzleTipMm = Eigen::Vector3d::Zero();  // base frame
  Eigen::Vector3d nozzleAxis = Eigen::Vector3d::UnitZ();  // unit, base frame, from the tip up into the extruder
  double nozzleZoneRadiusMm = 5.0;  // the tip's own zone (a cylinder about the axis from the tip up): where the
  double nozzleZoneHeightMm = 5.0;  // part meets the nozzle by design, exempt from the collision check
  Eigen::Isometry3d flangeToPlatform = Eigen::Isometry3d::Identity();  // TCP: the platform centre, z its normal
  double platformRadiusMm = 60.0;     // the platform disc about the TCP, in the TCP's xy plane
  double platformThicknessMm = 8.0;   // below the platform plane (towards the flange)
  double maxFilamentMmPerS = 20.0;    // analog out 0 = 1.0 drives the extruder at this filament speed
  std::size_t maxProgramBytes = kDefaultMaxProgramBytes;  // no program (part of a step) is larger
  std::vector<CollisionBox> boxes;    // the extruder and its mount
  std::vector<CollisionCylinder> cylinders;
  double tableZMm = 0.0;              // the table plane z = tableZMm (base frame); nothing goes below it
  Joints home{};                      // a safe pose, radians
  CellMargins margins;
  CellMotion motion;
};

// One thing wrong with a cell: the key concerned and what to do.
struct CellProblem {
  std::string key;      // "nozzleAxis", "bodies[2].sizeMm", ...
  std::string message;  // what is wrong and what to do
};

// Reads the file's values (JSON, format "multidir-robot-cell", version 1) without judging them: errors are a
// file that cannot be read (FileNotFound), malformed JSON or a key of the wrong type or shape (MalformedFile,
// naming the key), an unknown robot model (InvalidParameter, naming the known ones).
core::Result<Cell> parseCell(const std::filesystem::path& path);

// Everything wrong with a parsed cell, empty when it is sound: nozzle axis unit, joint limits ordered and within
// +-360 deg, home within the limits, reachable (IK of its own pose) and clear of the table, the flange-to-platform
// transform sane (under 500 mm), bodies with positive sizes and unit axes, the table below the nozzle tip,
// margins and motion parameters positive.
std::vector<CellProblem> checkCell(const Cell& cell);

// parseCell, then checkCell: a cell with problems is refused (InvalidParameter), the message listing them all.
core::Result<Cell> loadCell(const std::filesystem::path& path);

// The TCP (platform centre) of the joints, base frame.
Eigen::Isometry3d platformPose(const Cell& cell, const Joints& joints);

}  // namespace multidir::robot
