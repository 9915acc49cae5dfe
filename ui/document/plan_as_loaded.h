#pragma once
// The plan shown as the plan folder `multidir slice` and `multidir cell reach` read (core::LoadedPlan): what
// the studio hands to the slicer and to the reach map, so both see the plan as the CLI would.
#include <QStringList>
#include <optional>

#include "multidir/core/plan/plan_file.h"
#include "ui/document/loaded_model.h"
#include "ui/document/search_run.h"

namespace multidir::ui {

// `run`'s plan (must not be null) with its machine, settings and supports; the model's file as its source.
core::LoadedPlan planAsLoaded(const SearchRun& run, const std::optional<LoadedModel>& model);

}  // namespace multidir::ui
