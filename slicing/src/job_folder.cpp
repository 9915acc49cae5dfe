#include "multidir/slicing/job_folder.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

namespace multidir::slicing {
namespace {

namespace fs = std::filesystem;

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// print-job.json that MultiDir wrote (its schema), read whole only when it is small enough to be one.
bool isOurJobFile(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) > (std::uintmax_t{1} << 30)) return false;
  std::ifstream in(path, std::ios::binary);
  const nlohmann::json job = nlohmann::json::parse(in, nullptr, false);
  return job.is_object() && job.contains("schema") && job["schema"] == "multidir-print-job";
}

}  // namespace

bool isJobFolderEntry(const std::string& name) {
  if (startsWith(name, "print-job.json") || startsWith(name, "job.gcode") || startsWith(name, ".slicing-"))
    return true;
  return startsWith(name, "step-") && name.size() > 5 && std::isdigit(static_cast<unsigned char>(name[5]));
}

core::Result<JobFolder> inspectJobFolder(const std::string& directory) {
  JobFolder folder;
  std::error_code ec;
  const fs::file_status status = fs::status(directory, ec);
  if (!fs::exists(status)) return folder;  // Kind::Missing
  if (!fs::is_directory(status))
    return core::Error{core::ErrorCode::WriteFailed,
                       "a file of this name is in the way: name a folder for the job, not a file", directory};
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, ec))
    names.push_back(entry.path().filename().string());
  if (ec)
    return core::Error{core::ErrorCode::WriteFailed, "cannot list the folder: " + ec.message(), directory};
  std::sort(names.begin(), names.end());
  if (names.empty()) {
    folder.kind = JobFolder::Kind::Empty;
    return folder;
  }
  const bool ours = isOurJobFile(fs::path(directory) / "print-job.json");
  const auto other = std::find_if(names.begin(), names.end(), [](const std::string& n) { return !isJobFolderEntry(n); });
  if (ours && other == names.end()) {
    folder.kind = JobFolder::Kind::Job;
    return folder;
  }
  folder.kind = JobFolder::Kind::Other;
  folder.firstOtherEntry = other != names.end() ? *other : names.front();
  return folder;
}

}  // namespace multidir::slicing
