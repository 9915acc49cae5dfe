#pragma once
// Writing a file so that readers never see half of it: the content goes to a new `path.<random>.partial`
// (created exclusively, never through a symbolic link), which is renamed
// into place only when everything was written. A failed write leaves any old file as it was.
#include <functional>
#include <ostream>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::core::detail {

// `write` fills the stream (opened binary); an error it returns is passed on with `name` as where.
// Errors: WriteFailed (cannot create, disk full, cannot rename), or the writer's own.
Status writeFileAtomically(const std::string& path, const std::string& name,
                           const std::function<Status(std::ostream&)>& write);

}  // namespace multidir::core::detail
