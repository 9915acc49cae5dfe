#pragma once
// Writing a file so that readers never see half of it, and never through a planted link: the content goes to a
// new `path.<random>.partial` (created exclusively, O_EXCL | O_NOFOLLOW, so a symbolic link or any file already
// there is never opened), which is renamed into place only when everything was written and synced. The rename
// replaces `path` itself, never what a link at `path` points to. A failed write leaves any old file as it was.
// Every file MultiDir writes goes through here (core's plan and mesh files, the slicer's G-code and
// print-job.json, the command line's JSON reports); std::ofstream would follow a link and truncate in place.
#include <functional>
#include <ostream>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::core {

// `write` fills the stream (opened binary); an error it returns is passed on with `name` as where.
// Errors: WriteFailed (cannot create, disk full, cannot rename: the message says which), or the writer's own.
Status writeFileAtomically(const std::string& path, const std::string& name,
                           const std::function<Status(std::ostream&)>& write);

// `text` written as above; `name` is where in errors (the path when empty).
Status writeTextFileAtomically(const std::string& path, const std::string& text, const std::string& name = {});

}  // namespace multidir::core
