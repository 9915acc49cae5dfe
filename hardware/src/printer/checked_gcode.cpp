#include "printer/checked_gcode.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "multidir/hardware/content_digest.h"
#include "printable_text.h"

namespace multidir::hardware {

core::Result<std::string> readGcodeToSend(const std::string& localPath, const std::string& checkedSha256,
                                          const std::string& purpose) {
  std::ifstream in(localPath, std::ios::binary);
  if (!in)
    return core::Error{core::ErrorCode::FileNotFound,
                       "cannot read the G-code file to " + purpose + ": check that it exists (slice the job first)",
                       localPath};
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad())
    return core::Error{core::ErrorCode::FileNotFound,
                       "cannot read the G-code file to " + purpose + ": reading it failed; nothing of it was sent",
                       localPath};
  std::string bytes = std::move(content).str();
  if (!checkedSha256.empty() && sha256Hex(bytes) != checkedSha256)
    return core::Error{core::ErrorCode::InvalidParameter,
                       escapeControls(std::filesystem::path(localPath).filename().string()) +
                           " changed after it was checked; nothing of it was sent. Something replaced or rewrote "
                           "it during the run: find out what writes to the job folder, slice the job again and "
                           "run it from this step",
                       localPath};
  return bytes;
}

}  // namespace multidir::hardware
