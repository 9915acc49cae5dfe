#pragma once
// The folder a sliced job is written into (`multidir slice -o`, sliceJob's `directory`), looked at before
// anything is written: a new job replaces an earlier MultiDir job as a whole, but a folder holding anything
// else (the user's own files) is refused unless the caller allows writing into it (`--force`).
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::slicing {

struct JobFolder {
  enum class Kind {
    Missing,  // nothing there yet: it is created
    Empty,    // an empty folder
    Job,      // an earlier job: print-job.json of ours ("schema": "multidir-print-job") and only the job's files
    Other,    // anything else: files a job does not write, or no print-job.json of ours
  };
  Kind kind = Kind::Missing;
  std::string firstOtherEntry;  // Kind::Other: the first entry (by name) that is not the job's
};

// True for the names a job folder holds: print-job.json, job.gcode, step-NN... (the step meshes and G-code),
// the atomic writer's `.partial` files of those and `.slicing-PID` work folders an interrupted run left behind.
bool isJobFolderEntry(const std::string& name);

// What `directory` holds. Errors: WriteFailed when a file (not a folder) of that name is in the way, or the
// folder cannot be listed; `where` is the path.
core::Result<JobFolder> inspectJobFolder(const std::string& directory);

}  // namespace multidir::slicing
