#pragma once
// Autosave: while a project has unsaved changes, it is written every autosave/intervalSeconds (QSettings,
// default 60 s) to a project file of its own in QStandardPaths::AppDataLocation/autosave/. The file is deleted
// after a clean save and when its window goes away normally, so a file left there means the studio crashed:
// the next start offers to recover it.
//
// Each window owns its file through a lock file beside it ("<file>.lock", QLockFile): files whose lock a
// running studio holds are never offered for recovery, so two studios running at once do not take each
// other's work. A note beside the file ("<file>.origin") names the project file it stands for.
//
// Thread: GUI thread only.
#include <QObject>
#include <QString>
#include <QStringList>
#include <memory>

#include "multidir/core/plan/project_file.h"

class QLockFile;
class QTimer;

namespace multidir::ui {

class Autosave : public QObject {
  Q_OBJECT

 public:
  static constexpr int kDefaultIntervalSeconds = 60;

  explicit Autosave(QObject* parent = nullptr);
  // Deletes this window's file: going away normally is a clean exit.
  ~Autosave() override;
  Autosave(const Autosave&) = delete;
  Autosave& operator=(const Autosave&) = delete;

  // The folder autosaves live in (created when first written).
  [[nodiscard]] static QString folder();
  // QSettings "autosave/intervalSeconds", at least 1; kDefaultIntervalSeconds when unset or unreadable.
  [[nodiscard]] static int intervalSeconds();

  // Runs the timer while there are unsaved changes: due() every intervalSeconds(), read when it starts.
  void setPending(bool unsavedChanges);
  // Writes `project` to this window's file (atomically, core::saveProject), creating and locking the file on
  // the first call, and notes `origin` (the project file it stands for; empty for an untitled project).
  // On failure returns false with the reason.
  bool write(const core::Project& project, const QString& origin, QString* error = nullptr);
  // Deletes this window's file (after a clean save); the next write starts a new one.
  void discard();
  // This window's file; empty until the first write.
  [[nodiscard]] QString path() const { return m_path; }

  // Autosave files no running studio owns, newest first.
  [[nodiscard]] static QStringList orphans();
  // The project file an autosave stands for (empty: it was untitled).
  [[nodiscard]] static QString originOf(const QString& autosavePath);
  // Makes an orphan this window's file (after recovering it): it is then rewritten and deleted like its own.
  // False when another studio took it first.
  bool adopt(const QString& orphanPath);
  // Deletes an orphan and its note (the user chose not to recover it).
  static void removeOrphan(const QString& orphanPath);

 signals:
  // Time to write: the owner calls write() with the project as it is now.
  void due();

 private:
  void release(bool deleteFile);

  QTimer* m_timer = nullptr;
  QString m_path;
  std::unique_ptr<QLockFile> m_lock;
};

}  // namespace multidir::ui
