#pragma once
// The folder a plan or a print job is written into.
#include <filesystem>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::core::detail {

// Creates `folder` with its parents, or finds it there already. Errors: WriteFailed when a file of that name
// is in the way or the folder cannot be created; `what` ("plan folder") names it in the message, and the
// folder's path is where.
Status makeOutputFolder(const std::filesystem::path& folder, const std::string& what);

}  // namespace multidir::core::detail
