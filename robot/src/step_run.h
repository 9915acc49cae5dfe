#pragma once
// One run of a step: a stretch of its moves checked and converted on one rotation about the nozzle axis and one
// arm configuration (branch), so the platform only translates while it prints (docs/robot-cell.md, "Checks" and
// "Re-orientation within a step"). A step is one run unless no single rotation reaches its whole path.
#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gcode_events.h"
#include "multidir/robot/arm_links.h"
#include "multidir/robot/move_time.h"
#include "multidir/slicing/gcode_program.h"
#include "step_converter.h"

namespace multidir::robot::detail {

// A program line to be: a straight movel of the TCP to `tcp`, or (turn) a movej from turnFrom to turnTo, the
// re-orientation's turn in joint space with the part off the nozzle.
struct Converted {
  int line = 0;
  Eigen::Vector3d fileMm = Eigen::Vector3d::Zero();  // the nozzle's point, files' frame
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();  // platform pose, base frame
  double lengthMm = 0.0;
  double speedMmPerS = 0.0;  // after any slowdown
  double filamentMm = 0.0;   // the G-code's E of this move
  bool extrudes = false;
  bool turn = false;
  Joints turnFrom{}, turnTo{};
  std::vector<std::string> before;  // statements to write before the move (outputs, messages)
};

// The step read once: its moves and what every run of it shares.
struct StepPath {
  const StepInput* input = nullptr;
  const Cell* cell = nullptr;
  const RobotProgramOptions* options = nullptr;
  const GcodeSideInfo* side = nullptr;
  std::vector<const slicing::GcodeMove*> moves;  // those that go somewhere (XY or Z)
  std::vector<Eigen::Vector3d> points;           // each move's end, files' frame
  Eigen::Vector3d approach = Eigen::Vector3d::Zero(), retreat = Eigen::Vector3d::Zero();
  Eigen::AlignedBox3d bounds;        // the moves, the approach and the retreat: what the rotation is chosen over
  Eigen::AlignedBox3d sweptBounds;   // bounds raised by the lift: every nozzle point a run can ask for
  Eigen::Isometry3d platformToFlange = Eigen::Isometry3d::Identity();
};

struct Orientation {
  double rotationRad = 0.0;  // about the nozzle axis
  int branch = 0;            // the arm configuration (ur_kinematics.h)
  bool operator==(const Orientation& o) const { return rotationRad == o.rotationRad && branch == o.branch; }
};

// An orientation scored at the 8 corners of a box of nozzle points: how many it reaches within the joint
// limits with the arm's housings above the table, at how many the arm's links are clear, and the least margin
// (reach over margins.minReachMm, wrist over margins.minWristDegrees) when it reaches all 8.
struct OrientationScore {
  Orientation orientation;
  int reached = 0;
  bool clear = false;
  double score = 0.0;
};

// Every rotation (options.rotationStepDegrees apart) and branch, in that order, scored over `box`.
std::vector<OrientationScore> scoreOrientations(const StepPath& path, const Eigen::AlignedBox3d& box);
// The choice's order: all corners reached first, then the links clear at all of them, then the larger margin;
// with fewer corners reached, the more. Strict: of equals the first listed is taken.
bool betterOrientation(const OrientationScore& a, const OrientationScore& b);
// The best of `scores` by betterOrientation (the first of equals).
const OrientationScore& bestOrientation(const std::vector<OrientationScore>& scores);

// Where and why a run cannot go on. `fatal`: not the orientation's fault (the G-code's, or cancelled): no other
// rotation can help.
struct RunFailure {
  std::size_t move = 0;  // index into StepPath::moves
  int line = 0;
  std::string reason;
  bool fatal = false;
};

// What the summary takes from a run.
struct RunStats {
  double reachMarginMm = 0.0;
  double wristMarginDegrees = 0.0;
  double worstLoad = 0.0;
  int worstLoadJoint = 0;
  int slowdowns = 0;
  double slowdownSeconds = 0.0;
  double gcodeFilamentMm = 0.0;
};

// One orientation's run through the step's moves: start it, advance it move by move, end it (retreat or lift).
// With `keep`, every converted move (and, with the input's recordMotion, its pose) is kept for the program.
class StepRun {
 public:
  StepRun(const StepPath& path, Orientation orientation, bool keep);
  ~StepRun();
  StepRun(const StepRun&) = delete;
  StepRun& operator=(const StepRun&) = delete;

  // From home to the approach point (the step's first point, kStepApproachLiftMm off the nozzle).
  std::optional<RunFailure> startAtApproach();
  // A re-orientation in place of travel move `first`: the arm stands at `liftedJoints`, the part lifted
  // kStepApproachLiftMm off the nozzle above the end of move first - 1 on the run before; one joint move (checked:
  // joint_move_check.h) takes it onto this orientation lifted above the travel's end, and it comes down there.
  // The run goes on with move first + 1.
  std::optional<RunFailure> startAfterTurn(std::size_t first, const Joints& liftedJoints);
  // Move i (the next one) checked and converted.
  std::optional<RunFailure> advance(std::size_t i, const core::JobContext& context);
  // After move `last`: the part lifted off the nozzle for a re-orientation before move last + 1.
  std::optional<RunFailure> liftOff(std::size_t last);
  // After the step's last move: the platform backs off the nozzle (the step's retreat).
  std::optional<RunFailure> retreat();

  // Where the run stands, to come back to (a lift tried at an earlier travel move).
  struct State {
    Eigen::Vector3d current = Eigen::Vector3d::Zero();
    Joints joints{};
    ArmClearance lastClearance;
    double reachMarginMm = 0.0, wristMarginDegrees = 0.0;
  };
  [[nodiscard]] State state() const;
  void restore(const State& state);

  [[nodiscard]] const Orientation& orientation() const { return m_orientation; }
  [[nodiscard]] const Joints& joints() const { return m_joints; }
  [[nodiscard]] const Joints& startJoints() const { return m_startJoints; }  // at the approach or lifted point
  [[nodiscard]] const Eigen::Matrix3d& nozzleTurn() const { return m_turn; }
  [[nodiscard]] const RunStats& stats() const { return m_stats; }
  [[nodiscard]] std::vector<Converted>& converted() { return m_converted; }
  [[nodiscard]] std::vector<MotionSample>& motion() { return m_motion; }

 private:
  struct Collisions;
  std::string followTo(const Eigen::Vector3d& target, double requested, double& load, int& loadJoint,
                       Eigen::Isometry3d& endTcp);
  std::string collisionAt(const Eigen::Vector3d& f) const;
  void convertLine(const Eigen::Vector3d& target, int line, bool extrudes, double filamentMm, double requested,
                   double load, int loadJoint, const Eigen::Isometry3d& endTcp);
  std::optional<RunFailure> straightTo(const Eigen::Vector3d& target, std::size_t move, int line);
  RunFailure failure(std::size_t move, const std::string& reason, bool fatal = false) const;

  const StepPath& m_path;
  Orientation m_orientation;
  bool m_keep;
  Eigen::Matrix3d m_turn;
  std::unique_ptr<Collisions> m_collisions;
  Eigen::Vector3d m_current = Eigen::Vector3d::Zero();
  Joints m_joints{};
  Joints m_startJoints{};
  ArmClearance m_lastClearance;
  RunStats m_stats;
  std::vector<Converted> m_converted;
  std::vector<MotionSample> m_motion;
};

// The solution of `branch` for the flange pose, turned to lie nearest `near` within the limits.
enum class Solve { Ok, OutOfReach, OtherBranchOnly, BeyondLimits };
Solve solveOnBranch(const ArmModel& arm, const Eigen::Isometry3d& flange, int branch, const Joints& near, Joints& out);

// Shared with the program writer.
std::string fixedText(double v, int decimals);

}  // namespace multidir::robot::detail
