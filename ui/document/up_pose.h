#pragma once
// The up direction in force when a pose search chose it (the Machine panel's "Find best pose", then "Use this
// pose"): kept with the Up box entry so that a saved project and an exported plan record the pose.
#include <QMetaType>
#include <vector>

#include "multidir/core/plan/plan_file.h"
#include "multidir/core/plan/project_file.h"

namespace multidir::ui {

struct UpPose {
  core::Vec3 up = core::Vec3::UnitZ();  // unit, in the model's coordinates
  core::ProjectPose pose;               // source, contact area, the up the search started from
  // The other poses the search tried (plan.json's pose.runnersUp); empty for a pose read back from a project.
  std::vector<core::PlanPoseTrial> runnersUp;
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::ui::UpPose)
