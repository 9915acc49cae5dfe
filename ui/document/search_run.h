#pragma once
// A plan with what it was computed with: the machine, the search's settings and the supports grown for it.
// The studio document holds the one shown (StudioDocument::plan); searches, opened plans and edits make them.
#include <QMetaType>
#include <QString>
#include <memory>
#include <vector>

#include "multidir/core/search/decomposition.h"
#include "multidir/core/search/machine.h"
#include "multidir/core/search/search_options.h"
#include "multidir/core/supports/support_set.h"

namespace multidir::ui {

// What one search was asked to do, and what it found.
struct SearchRun {
  core::MachineSpec machine;
  core::SearchOptions options;
  int axisSearchCount = 0;  // 4-DOF axes tried; 0: the machine's own axis only
  std::shared_ptr<const core::Decomposition> plan;  // set in finished(); never null there
  // One set per region in printing order; null when none were grown (J_G = 0, a cancelled search, or
  // supportsNote).
  std::shared_ptr<const std::vector<core::SupportSet>> supports;
  // Why a plan with J_G > 0 has no supports (translated; empty otherwise).
  QString supportsNote;
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::ui::SearchRun)
