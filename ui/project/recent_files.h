#pragma once
// File > Open Recent: the models and projects opened or saved lately, most recent first, at most
// kMaxRecentFiles, kept in QSettings ("recentFiles") so every window and the next start share them.
#include <QMenu>
#include <QString>
#include <QStringList>

namespace multidir::ui {

constexpr int kMaxRecentFiles = 10;

// The list, most recent first (absolute paths).
[[nodiscard]] QStringList recentFiles();
// Puts `path` (made absolute) first; an earlier entry of it is dropped and the list is cut to kMaxRecentFiles.
void addRecentFile(const QString& path);
void removeRecentFile(const QString& path);
void clearRecentFiles();

// The Open Recent menu: one entry per file (objectName "recentFile1", ...; the file name as text, the path as
// tip), then "Clear Recent" (objectName "clearRecentFiles"). It reads the list whenever it is about to show and
// when refresh() is called.
class RecentFilesMenu : public QMenu {
  Q_OBJECT

 public:
  explicit RecentFilesMenu(QWidget* parent = nullptr);
  void refresh();

 signals:
  // An entry was chosen; the file may have gone since it was listed.
  void fileChosen(const QString& path);
};

}  // namespace multidir::ui
