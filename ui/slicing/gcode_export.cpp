#include "ui/slicing/gcode_export.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace multidir::ui {
namespace {

struct ExportText {
  Q_DECLARE_TR_FUNCTIONS(GcodeExport)
};

const QString kJobFile = QStringLiteral("print-job.json");

bool copyInto(const QString& source, const QString& target, QString* error) {
  const QString part = target + QStringLiteral(".part");
  QFile::remove(part);
  QFile in(source);
  if (!in.copy(part)) {
    if (error)
      *error = ExportText::tr("Could not write %1: %2. Check that the folder can be written and the disk is not full.")
                   .arg(QDir::toNativeSeparators(target), in.errorString());
    QFile::remove(part);
    return false;
  }
  if (QFileInfo::exists(target) && !QFile::remove(target)) {
    if (error) *error = ExportText::tr("Could not replace %1: it is in use or read-only.").arg(QDir::toNativeSeparators(target));
    QFile::remove(part);
    return false;
  }
  if (!QFile::rename(part, target)) {
    if (error) *error = ExportText::tr("Could not move %1 into place.").arg(QDir::toNativeSeparators(target));
    QFile::remove(part);
    return false;
  }
  return true;
}

}  // namespace

bool exportSlicedFiles(const QString& from, const QString& to, QStringList* written, QString* error) {
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
  if (!QDir().mkpath(to)) {
    if (error)
      *error = ExportText::tr("Could not create the folder %1: check that its parent exists and can be written.")
                   .arg(QDir::toNativeSeparators(to));
    return false;
  }
  const QDir destination(to);
  if (destination.exists(kJobFile) && !QFile::remove(destination.filePath(kJobFile))) {
    if (error) *error = ExportText::tr("Could not replace %1: it is in use or read-only.").arg(QDir::toNativeSeparators(destination.filePath(kJobFile)));
    return false;
  }
  QStringList order = files;
  order.removeAll(kJobFile);
  order.append(kJobFile);
  QStringList done;
  for (const QString& name : order) {
    if (!copyInto(source.filePath(name), destination.filePath(name), error)) return false;
    done.append(name);
  }
  if (written) *written = done;
  return true;
}

}  // namespace multidir::ui
