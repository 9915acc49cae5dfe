#include "ui/project/dialog_folders.h"

#include <QFileInfo>
#include <QSettings>

namespace multidir::ui {
namespace {

QString settingsKey(FileKind kind) {
  switch (kind) {
    case FileKind::Model: return QStringLiteral("dialogFolders/model");
    case FileKind::Project: return QStringLiteral("dialogFolders/project");
    case FileKind::Plan: return QStringLiteral("dialogFolders/plan");
    case FileKind::MachineProfile: return QStringLiteral("dialogFolders/machineProfile");
    case FileKind::Picture: return QStringLiteral("dialogFolders/picture");
  }
  return QStringLiteral("dialogFolders/other");
}

}  // namespace

QString rememberedDialogFolder(FileKind kind) {
  const QString folder = QSettings().value(settingsKey(kind)).toString();
  return !folder.isEmpty() && QFileInfo(folder).isDir() ? folder : QString();
}

void rememberDialogFolder(FileKind kind, const QString& path) {
  if (path.isEmpty()) return;
  const QFileInfo info(path);
  const QString folder = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
  QSettings().setValue(settingsKey(kind), folder);
}

}  // namespace multidir::ui
