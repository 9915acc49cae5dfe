#pragma once
// The one read of a step's G-code before a printer link sends it: the links send these bytes and never open
// the file again, and when the run gave the SHA-256 taken at its check (content_digest.h), bytes that differ
// are refused before anything reaches the printer.
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

// The content of `localPath`. FileNotFound when it cannot be read; InvalidParameter naming the file when
// `checkedSha256` is not empty and the content's SHA-256 differs from it. `purpose`: "upload", "stream".
core::Result<std::string> readGcodeToSend(const std::string& localPath, const std::string& checkedSha256,
                                          const std::string& purpose);

}  // namespace multidir::hardware
