#include "ui/project/recent_files.h"

#include <QFileInfo>
#include <QSettings>

namespace multidir::ui {
namespace {

const QString kKey = QStringLiteral("recentFiles");

QString absolute(const QString& path) { return QFileInfo(path).absoluteFilePath(); }

void store(const QStringList& paths) { QSettings().setValue(kKey, paths); }

}  // namespace

QStringList recentFiles() {
  QStringList paths = QSettings().value(kKey).toStringList();
  paths.removeAll(QString());
  return paths.mid(0, kMaxRecentFiles);
}

void addRecentFile(const QString& path) {
  if (path.isEmpty()) return;
  const QString entry = absolute(path);
  QStringList paths = recentFiles();
  paths.removeAll(entry);
  paths.prepend(entry);
  store(paths.mid(0, kMaxRecentFiles));
}

void removeRecentFile(const QString& path) {
  QStringList paths = recentFiles();
  paths.removeAll(path);
  paths.removeAll(absolute(path));
  store(paths);
}

void clearRecentFiles() { QSettings().remove(kKey); }

RecentFilesMenu::RecentFilesMenu(QWidget* parent) : QMenu(tr("Open &Recent"), parent) {
  setObjectName(QStringLiteral("openRecentMenu"));
  connect(this, &QMenu::aboutToShow, this, &RecentFilesMenu::refresh);
  refresh();
}

void RecentFilesMenu::refresh() {
  // Not clear(): refresh() also runs from an entry's own triggered() (Clear Recent, or a file opened and
  // moved to the front), and an action must not be deleted while it is still emitting.
  for (QAction* action : actions()) {
    removeAction(action);
    action->setParent(nullptr);  // out of findChild()'s reach at once
    action->deleteLater();
  }
  const QStringList paths = recentFiles();
  for (int i = 0; i < paths.size(); ++i) {
    const QString path = paths[i];
    // "&1 kitten.off" .. "1&0 ...": the first nine get a digit shortcut.
    const QString number = i < 9 ? QStringLiteral("&%1").arg(i + 1) : QString::number(i + 1);
    QAction* action = addAction(QStringLiteral("%1 %2").arg(number, QFileInfo(path).fileName()));
    action->setObjectName(QStringLiteral("recentFile%1").arg(i + 1));
    action->setToolTip(path);
    action->setStatusTip(path);
    action->setData(path);
    connect(action, &QAction::triggered, this, [this, path] { emit fileChosen(path); });
  }
  if (!paths.isEmpty()) addSeparator();
  QAction* clearAction = addAction(tr("&Clear Recent"));
  clearAction->setObjectName(QStringLiteral("clearRecentFiles"));
  clearAction->setEnabled(!paths.isEmpty());
  connect(clearAction, &QAction::triggered, this, [this] {
    clearRecentFiles();
    refresh();
  });
}

}  // namespace multidir::ui
