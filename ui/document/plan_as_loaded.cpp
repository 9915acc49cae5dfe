#include "ui/document/plan_as_loaded.h"

#include <QFile>

#include "ui/common/studio_version.h"

namespace multidir::ui {

core::LoadedPlan planAsLoaded(const SearchRun& run, const std::optional<LoadedModel>& model) {
  core::LoadedPlan plan;
  plan.metadata.up = run.machine.up;
  plan.metadata.machine = run.machine;
  plan.metadata.options = run.options;
  plan.metadata.axisSearchCount = run.axisSearchCount;
  plan.metadata.multidirVersion = studioVersion().toStdString();
  if (model && !model->sourcePath.isEmpty()) plan.metadata.modelPath = QFile::encodeName(model->sourcePath).toStdString();
  plan.decomposition = *run.plan;
  if (run.supports) plan.supports = *run.supports;
  return plan;
}

}  // namespace multidir::ui
