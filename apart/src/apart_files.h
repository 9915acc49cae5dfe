#pragma once
// The files printApart writes last (the assembly sheet and apart.json) and how a staged folder of them takes
// its target's place.
#include <string>

#include "multidir/apart/print_apart.h"
#include "multidir/core/common/staged_folder.h"

namespace multidir::apart {

// assembly.html with its pictures in sheet/, then apart.json (every number the command prints), into `folder`;
// their names are added to result.files.
core::Status writeSheetAndSummary(ApartResult& result, const PrintApartOptions& options, const std::string& folder);

// A target that is missing, empty or holds an earlier apart.json is replaced as a whole; one holding other
// files gets the new entries moved in, apart.json last, and keeps the rest.
core::Status commitFolder(core::StagedFolder& staged);

}  // namespace multidir::apart
