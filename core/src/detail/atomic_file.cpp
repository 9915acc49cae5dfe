#include "detail/atomic_file.h"

#include <filesystem>
#include <fstream>

namespace multidir::core::detail {

namespace fs = std::filesystem;

Status writeFileAtomically(const std::string& path, const std::string& name,
                           const std::function<Status(std::ostream&)>& write) {
  const fs::path temporary = path + ".partial";
  auto discard = [&] {
    std::error_code ignored;
    fs::remove(temporary, ignored);
  };
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out)
        return Error{ErrorCode::WriteFailed, "cannot create the file (does the folder exist and is it writable?)",
                     name};
      if (Status s = write(out); !s) {
        out.close();
        discard();
        return Error{s.error().code, s.error().message, name};
      }
      out.flush();
      if (!out) {
        out.close();
        discard();
        return Error{ErrorCode::WriteFailed, "writing failed (is the disk full?)", name};
      }
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
      discard();
      return Error{ErrorCode::WriteFailed, "cannot replace the file: " + ec.message(), name};
    }
  } catch (const std::exception& e) {
    discard();
    return Error{ErrorCode::WriteFailed, std::string("writing failed: ") + e.what(), name};
  }
  return Done{};
}

}  // namespace multidir::core::detail
