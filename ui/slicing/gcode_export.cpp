#include "ui/slicing/gcode_export.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "multidir/core/common/staged_folder.h"
#include "multidir/slicing/job_folder.h"

namespace multidir::ui {
namespace {

struct ExportText {
  Q_DECLARE_TR_FUNCTIONS(GcodeExport)
};

const QString kJobFile = QStringLiteral("print-job.json");

std::string localPath(const QString& path) { return QFile::encodeName(path).toStdString(); }
QString fromLocal(const std::string& path) { return QFile::decodeName(QByteArray::fromStdString(path)); }

}  // namespace

QString otherFileIn(const QString& folder) {
  const core::Result<slicing::JobFolder> found = slicing::inspectJobFolder(localPath(folder));
  if (!found || found->kind != slicing::JobFolder::Kind::Other) return {};
  return fromLocal(found->firstOtherEntry);
}

bool exportSlicedFiles(const QString& from, const QString& to, QStringList* written, QString* error,
                       bool intoOtherFolder) {
  const QDir source(from);
  const QStringList files = source.entryList(QDir::Files | QDir::NoDotAndDotDot, QDir::Name);
  if (from.isEmpty() || !source.exists() || !files.contains(kJobFile)) {
    if (error) *error = ExportText::tr("There is no sliced job to export: slice the plan first.");
    return false;
  }
  const QFileInfo target(to);
  if (target.exists() && !target.isDir()) {
    if (error) *error = ExportText::tr("%1 is a file, not a folder: choose a folder for the G-code.").arg(QDir::toNativeSeparators(to));
    return false;
  }
  if (!QDir().mkpath(target.absolutePath())) {
    if (error)
      *error = ExportText::tr("Could not create the folder %1: check that its parent exists and can be written.")
                   .arg(QDir::toNativeSeparators(target.absolutePath()));
    return false;
  }
  const core::Result<slicing::JobFolder> folder = slicing::inspectJobFolder(localPath(to));
  if (!folder) {
    if (error) *error = ExportText::tr("Could not export the G-code: %1").arg(fromLocal(folder.error().describe()));
    return false;
  }
  const bool other = folder->kind == slicing::JobFolder::Kind::Other;
  if (other && !intoOtherFolder) {
    if (error)
      *error = ExportText::tr("%1 holds files that are not a MultiDir job (%2 is one), so nothing was exported: "
                              "choose an empty folder or one holding an earlier job.")
                   .arg(QDir::toNativeSeparators(to), fromLocal(folder->firstOtherEntry));
    return false;
  }
  // Every file copied into a fresh folder beside the target first (nothing can be planted in it), which takes
  // the target's place only once complete.
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(localPath(to));
  if (!staged) {
    if (error) *error = ExportText::tr("Could not export the G-code: %1").arg(fromLocal(staged.error().describe()));
    return false;
  }
  const QDir stagedDir(fromLocal(staged->path()));
  QStringList done;
  for (const QString& name : files) {
    QFile in(source.filePath(name));
    if (!in.copy(stagedDir.filePath(name))) {
      if (error)
        *error = ExportText::tr("Could not write %1: %2. Check that the folder can be written and the disk is not full.")
                     .arg(QDir::toNativeSeparators(QDir(to).filePath(name)), in.errorString());
      return false;  // the staged folder is removed; `to` is as it was
    }
    done.append(name);
  }
  const core::Status committed = other ? staged->moveEntriesInto(localPath(kJobFile)) : staged->replaceTarget();
  if (!committed) {
    if (error) *error = ExportText::tr("Could not export the G-code: %1").arg(fromLocal(committed.error().describe()));
    return false;
  }
  if (written) *written = done;
  return true;
}

}  // namespace multidir::ui
