#pragma once
// A folder's new content, written beside it and put in its place only when complete: a job that fails,
// is cancelled or crashes half-way leaves the folder exactly as it was (an earlier good job included), and a
// reader never sees half of the old content mixed with half of the new.
//
//   Result<StagedFolder> staged = StagedFolder::beside("out/job");   // out/.job.new-XXXXXX, empty
//   ... write every file into staged->path() ...
//   if (Status s = staged->replaceTarget(); !s) return s.error();    // out/job is now the new content
//
// The staged folder is created with mkdtemp (a fresh name, mode 0700), so nothing can be planted in it while it
// is written; a StagedFolder dropped before it is committed removes it. Not thread-safe (one owner).
#include <string>
#include <utility>

#include "multidir/core/common/result.h"

namespace multidir::core {

class StagedFolder {
 public:
  // Creates `.<name>.new-XXXXXX` beside `target` (in the same parent, so that one rename can swap them). A
  // `target` that is a symbolic link to a folder stands for the folder it names (the link stays). The parent
  // must exist. Errors: WriteFailed naming the parent (missing, not writable).
  static Result<StagedFolder> beside(const std::string& target);

  StagedFolder(StagedFolder&& other) noexcept;
  StagedFolder& operator=(StagedFolder&&) = delete;
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;
  ~StagedFolder();  // removes the staged folder and all it holds, unless committed

  const std::string& path() const { return m_path; }      // where the new content is written
  const std::string& target() const { return m_target; }  // absolute, normalised

  // Puts the staged folder in the target's place as a whole: the target (created empty first when missing) and
  // the staged folder are exchanged in one step (Linux renameat2 RENAME_EXCHANGE), the new content gets the
  // target's permissions, and the old content is then removed (best effort: what cannot be removed stays in
  // the hidden `.<name>.new-XXXXXX`). Where the file system cannot exchange, the old folder is renamed aside
  // first and renamed back should the new one fail to take its place. Errors: WriteFailed naming the target,
  // which is then as it was.
  Status replaceTarget();

  // Moves every entry of the staged folder into the target (created when missing), each by one rename that
  // replaces an entry of the same name; entries of the target the staged folder lacks are left alone. `last`
  // (a name in the staged folder, or empty) moves after all others, so that a reader who finds it finds the
  // rest. Errors: WriteFailed naming the entry that could not be moved (those moved before it stay).
  Status moveEntriesInto(const std::string& last);

 private:
  StagedFolder(std::string path, std::string target) : m_path(std::move(path)), m_target(std::move(target)) {}
  std::string m_path;
  std::string m_target;
  bool m_committed = false;
};

}  // namespace multidir::core
