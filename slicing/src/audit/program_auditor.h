#pragma once
// The replay of one program (the step programs one after another, or job.gcode) through the audit's
// kinematics, and its checks (a) to (e) written into a ProgramAudit (audit.h). Single-threaded.
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "gcode_replay.h"
#include "multidir/core/common/job_context.h"
#include "multidir/slicing/audit.h"

namespace multidir::slicing::audit {

class TriangleGrid;

class ProgramAuditor {
 public:
  // `solids`: one grid per step of the job (its region and supports, model frame). `out` gets one row per
  // step; pose and sequence findings go to `report`. All are referenced, not copied.
  ProgramAuditor(const AuditJob& job, const AuditOptions& options, double alphaDegrees,
                 const std::vector<std::unique_ptr<TriangleGrid>>& solids, ProgramAudit& out, AuditReport& report);
  ~ProgramAuditor();
  ProgramAuditor(const ProgramAuditor&) = delete;
  ProgramAuditor& operator=(const ProgramAuditor&) = delete;

  // Replays one G-code text. `fixedPose` (a step program): every move prints at this pose, and its moves
  // belong to step slot `fileStep`; none (job.gcode): the pose follows the A axis as replayed and the step
  // markers say which step a move belongs to. Errors: those of replayGcode, Cancelled (checked every 4096
  // moves).
  core::Status replay(const std::string& text, const std::string& name, std::size_t fileStep,
                      const Eigen::Isometry3d* fixedPose, MachineState& state, core::JobContext& context);
  // (e) on a Modbus platform: the turn from step slot `slot`'s pose to the next, the nozzle where `state`
  // left it.
  void modbusTurn(std::size_t slot, const MachineState& state);
  // The first-layer gaps, the totals and the worst places.
  void finish();

 private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace multidir::slicing::audit
