#include "multidir/core/common/staged_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

namespace multidir::core {
namespace {

namespace fs = std::filesystem;

std::string lastError() { return std::strerror(errno); }

// The target as one absolute, normalised path without a trailing separator ("out/" and "out/." are "out"), a
// link to a folder replaced by the folder it names: the swap must move the folder, not the user's link.
fs::path normalisedTarget(const std::string& target) {
  std::error_code ec;
  fs::path path = fs::absolute(fs::path(target), ec).lexically_normal();
  if (!path.has_filename() && path.has_parent_path() && path != path.root_path()) path = path.parent_path();
  if (fs::is_symlink(path, ec) && fs::is_directory(path, ec)) {
    const fs::path resolved = fs::canonical(path, ec);
    if (!ec) path = resolved;
  }
  return path;
}

// A new empty folder `<parent>/.<name>.<tag>-XXXXXX`, or an empty string (errno set).
std::string makeUniqueFolder(const fs::path& parent, const std::string& name, const char* tag) {
  std::string pattern = (parent / ("." + name + "." + tag + "-XXXXXX")).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (::mkdtemp(buffer.data()) == nullptr) return {};
  return std::string(buffer.data());
}

void removeTree(const std::string& path) {
  std::error_code ec;
  fs::remove_all(path, ec);  // never follows a link inside: it removes the link
}

// Exchanges two existing paths atomically. False with errno set when the kernel or file system cannot.
bool exchangePaths(const std::string& a, const std::string& b) {
#ifdef RENAME_EXCHANGE
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
#else
  errno = ENOSYS;
  return false;
#endif
}

}  // namespace

Result<StagedFolder> StagedFolder::beside(const std::string& target) {
  const fs::path normalised = normalisedTarget(target);
  const fs::path parent = normalised.parent_path();
  const std::string name = normalised.filename().string();
  if (name.empty() || name == "." || name == "..")
    return Error{ErrorCode::WriteFailed, "cannot replace this folder as a whole: name a folder by its own name",
                 target};
  const std::string staged = makeUniqueFolder(parent, name, "new");
  if (staged.empty())
    return Error{ErrorCode::WriteFailed,
                 "cannot create a folder beside it to write the new content into (" + lastError() +
                     "); its parent folder must exist and be writable",
                 parent.string()};
  return StagedFolder(staged, normalised.string());
}

StagedFolder::StagedFolder(StagedFolder&& other) noexcept
    : m_path(std::move(other.m_path)), m_target(std::move(other.m_target)), m_committed(other.m_committed) {
  other.m_committed = true;  // the moved-from object owns nothing
  other.m_path.clear();
}

StagedFolder::~StagedFolder() {
  if (!m_committed && !m_path.empty()) removeTree(m_path);
}

Status StagedFolder::replaceTarget() {
  if (m_committed) return Error{ErrorCode::Internal, "the staged folder was committed already", m_target};
  // The target must exist to be exchanged; a new one is made by mkdir, so it gets the usual permissions (the
  // umask's), which the new content then takes over from it (mkdtemp made the staged folder 0700).
  if (::mkdir(m_target.c_str(), 0777) != 0 && errno != EEXIST)
    return Error{ErrorCode::WriteFailed, "cannot create the folder: " + lastError(), m_target};
  struct stat targetStat {};
  if (::stat(m_target.c_str(), &targetStat) != 0)
    return Error{ErrorCode::WriteFailed, "cannot read the folder's permissions: " + lastError(), m_target};
  if (!S_ISDIR(targetStat.st_mode))
    return Error{ErrorCode::WriteFailed, "a file of this name is in the way: remove it or choose another folder",
                 m_target};
  if (::chmod(m_path.c_str(), targetStat.st_mode & 07777) != 0)
    return Error{ErrorCode::WriteFailed, "cannot set the new folder's permissions: " + lastError(), m_path};

  if (exchangePaths(m_path, m_target)) {
    m_committed = true;
    removeTree(m_path);  // now the old content
    return Done{};
  }
  if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP)
    return Error{ErrorCode::WriteFailed, "cannot put the new content in place: " + lastError(), m_target};

  // No exchange here: the old folder goes aside (rename onto an empty folder replaces it in one step), the new
  // one takes its place, and the old one comes back should that fail.
  const fs::path target(m_target);
  const std::string aside = makeUniqueFolder(target.parent_path(), target.filename().string(), "old");
  if (aside.empty())
    return Error{ErrorCode::WriteFailed, "cannot make room beside the folder to swap it: " + lastError(), m_target};
  if (::rename(m_target.c_str(), aside.c_str()) != 0) {
    const std::string why = lastError();
    ::rmdir(aside.c_str());
    return Error{ErrorCode::WriteFailed, "cannot move the old content aside: " + why, m_target};
  }
  if (::rename(m_path.c_str(), m_target.c_str()) != 0) {
    const std::string why = lastError();
    if (::rename(aside.c_str(), m_target.c_str()) != 0)
      return Error{ErrorCode::WriteFailed,
                   "cannot put the new content in place (" + why + ") nor the old one back: it is in " + aside,
                   m_target};
    return Error{ErrorCode::WriteFailed, "cannot put the new content in place: " + why, m_target};
  }
  m_committed = true;
  removeTree(aside);
  return Done{};
}

Status StagedFolder::moveEntriesInto(const std::string& last) {
  if (m_committed) return Error{ErrorCode::Internal, "the staged folder was committed already", m_target};
  if (::mkdir(m_target.c_str(), 0777) != 0 && errno != EEXIST)
    return Error{ErrorCode::WriteFailed, "cannot create the folder: " + lastError(), m_target};
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(m_path, ec))
    names.push_back(entry.path().filename().string());
  if (ec) return Error{ErrorCode::WriteFailed, "cannot list the new content: " + ec.message(), m_path};
  std::sort(names.begin(), names.end());
  // `last` after the others (stable: the rest keep their order).
  std::stable_partition(names.begin(), names.end(), [&](const std::string& n) { return n != last; });
  for (const std::string& name : names) {
    const std::string from = (fs::path(m_path) / name).string();
    const std::string to = (fs::path(m_target) / name).string();
    if (::rename(from.c_str(), to.c_str()) != 0)
      return Error{ErrorCode::WriteFailed, "cannot move the new file into place: " + lastError(), to};
  }
  m_committed = true;
  removeTree(m_path);
  return Done{};
}

}  // namespace multidir::core
