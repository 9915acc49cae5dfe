#pragma once
// Via points for a joint move whose straight joint path is not clear (docs/robot-cell.md, "Joint moves"): a short
// sequence of movej's, each segment clear by the one joint-move check (joint_move_check.h), found deterministically
// (the same input gives the same vias on any machine and for any thread count).
#include <string>
#include <vector>

#include "joint_move_check.h"

namespace multidir::robot::detail {

struct JointPathPlan {
  bool found = false;
  std::vector<Joints> vias;   // between `from` and `to`, in order; empty when the straight move is clear
  std::string straightHit;    // why the straight move is not clear ("" when it is)
  std::string method;         // "straight", "backed off ...", "wrists first", "search" ...
  int candidatesTried = 0;    // the natural candidates checked
  int searchSamples = 0;      // the joint sets the search drew (0 when it did not run)
};

// The joint path from `from` to `to`: the straight move when clear; else the first clear natural candidate
// (the part backed off the nozzle along its axis at either end, the wrists or the big joints first, a pose straight
// below the nozzle); else a seeded RRT-connect search in the joint limits, shortcut. With `allowVias` false only
// the straight move is tried.
JointPathPlan planJointPath(const JointMoveScene& scene, const Joints& from, const Joints& to, bool allowVias);

}  // namespace multidir::robot::detail
