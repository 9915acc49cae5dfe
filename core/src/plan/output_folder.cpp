#include "plan/output_folder.h"

namespace multidir::core::detail {

namespace fs = std::filesystem;

Status makeOutputFolder(const fs::path& folder, const std::string& what) {
  const std::string name = folder.string();
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    return Error{ErrorCode::WriteFailed, "a file of this name exists, so the " + what + " cannot be created there",
                 name};
  fs::create_directories(folder, ec);
  if (ec) return Error{ErrorCode::WriteFailed, "cannot create the " + what + ": " + ec.message(), name};
  return Done{};
}

}  // namespace multidir::core::detail
