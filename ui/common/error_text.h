#pragma once
// Core reports errors in English with technical detail; the GUI leads with a translated sentence per
// error code and keeps core's text as the detail.
#include <QString>

#include "multidir/core/common/result.h"

namespace multidir::ui {

// One translated sentence saying what kind of problem `code` is and what the user can do.
QString errorHeadline(core::ErrorCode code);

}  // namespace multidir::ui
