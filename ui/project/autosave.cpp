#include "ui/project/autosave.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QRegularExpression>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <QUuid>
#include <algorithm>

#include "ui/common/error_text.h"

namespace multidir::ui {
namespace {

const QString kPattern = QStringLiteral("*.multidir");

std::string localPath(const QString& path) { return QFile::encodeName(path).toStdString(); }

// A lock another running studio holds is never taken as stale, however old: a studio keeps its file for hours.
std::unique_ptr<QLockFile> lockFor(const QString& autosavePath) {
  auto lock = std::make_unique<QLockFile>(autosavePath + QStringLiteral(".lock"));
  lock->setStaleLockTime(0);
  if (!lock->tryLock(0)) return nullptr;
  return lock;
}

QString originNotePath(const QString& autosavePath) { return autosavePath + QStringLiteral(".origin"); }

// "kitten-1a2b3c4d.multidir": the project's (or model's) name, so a person looking into the folder knows which
// is which, and a random part, so windows never share a file.
QString newFileName(const core::Project& project, const QString& origin) {
  QString stem = !origin.isEmpty() ? QFileInfo(origin).completeBaseName()
                 : !project.model.sampleId.empty()
                     ? QString::fromStdString(project.model.sampleId)
                     : QFileInfo(QString::fromStdString(project.model.path)).completeBaseName();
  stem.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]+")), QStringLiteral("_"));
  stem = stem.left(40);
  if (stem.isEmpty()) stem = QStringLiteral("untitled");
  const QString unique = QUuid::createUuid().toString(QUuid::Id128).left(8);
  return QStringLiteral("%1-%2.multidir").arg(stem, unique);
}

}  // namespace

Autosave::Autosave(QObject* parent) : QObject(parent), m_timer(new QTimer(this)) {
  connect(m_timer, &QTimer::timeout, this, &Autosave::due);
}

Autosave::~Autosave() { release(true); }

QString Autosave::folder() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
}

int Autosave::intervalSeconds() {
  bool ok = false;
  const int seconds = QSettings().value(QStringLiteral("autosave/intervalSeconds"), kDefaultIntervalSeconds).toInt(&ok);
  if (!ok) return kDefaultIntervalSeconds;
  return std::max(1, seconds);
}

void Autosave::setPending(bool unsavedChanges) {
  if (!unsavedChanges) {
    m_timer->stop();
    return;
  }
  if (m_timer->isActive()) return;
  m_timer->setInterval(intervalSeconds() * 1000);
  m_timer->start();
}

bool Autosave::write(const core::Project& project, const QString& origin, QString* error) {
  auto fail = [error](const QString& message) {
    if (error) *error = message;
    return false;
  };
  if (m_path.isEmpty()) {
    if (!QDir().mkpath(folder())) return fail(tr("Cannot create the autosave folder %1.").arg(folder()));
    // A name clash is as good as impossible; a second try covers it.
    for (int attempt = 0; attempt < 2 && m_path.isEmpty(); ++attempt) {
      const QString candidate = folder() + QLatin1Char('/') + newFileName(project, origin);
      if (QFileInfo::exists(candidate)) continue;
      m_lock = lockFor(candidate);
      if (m_lock) m_path = candidate;
    }
    if (m_path.isEmpty()) return fail(tr("Cannot lock a new autosave file in %1.").arg(folder()));
  }
  const core::Status saved = core::saveProject(project, localPath(m_path));
  if (!saved) {
    return fail(tr("Autosave failed: %1 (%2)")
                    .arg(errorHeadline(saved.error().code), QString::fromStdString(saved.error().describe())));
  }
  QSaveFile note(originNotePath(m_path));
  if (note.open(QIODevice::WriteOnly)) {
    note.write(origin.toUtf8());
    note.commit();
  }
  return true;
}

void Autosave::discard() { release(true); }

void Autosave::release(bool deleteFile) {
  if (deleteFile && !m_path.isEmpty()) {
    QFile::remove(m_path);
    QFile::remove(originNotePath(m_path));
  }
  m_lock.reset();  // unlocks: removes the lock file
  m_path.clear();
}

QStringList Autosave::orphans() {
  QStringList found;
  const QFileInfoList files = QDir(folder()).entryInfoList({kPattern}, QDir::Files, QDir::Time);
  for (const QFileInfo& file : files) {
    // Taking the lock for a moment tells whether a running studio holds it; the probe gives it back at once.
    if (lockFor(file.absoluteFilePath())) found << file.absoluteFilePath();
  }
  return found;
}

QString Autosave::originOf(const QString& autosavePath) {
  QFile note(originNotePath(autosavePath));
  if (!note.open(QIODevice::ReadOnly)) return {};
  return QString::fromUtf8(note.readAll()).trimmed();
}

bool Autosave::adopt(const QString& orphanPath) {
  if (orphanPath == m_path) return true;
  std::unique_ptr<QLockFile> lock = lockFor(orphanPath);
  if (!lock) return false;
  release(true);  // the recovered project supersedes what this window autosaved before
  m_lock = std::move(lock);
  m_path = orphanPath;
  return true;
}

void Autosave::removeOrphan(const QString& orphanPath) {
  std::unique_ptr<QLockFile> lock = lockFor(orphanPath);
  if (!lock) return;  // a running studio owns it after all
  QFile::remove(orphanPath);
  QFile::remove(originNotePath(orphanPath));
}

}  // namespace multidir::ui
