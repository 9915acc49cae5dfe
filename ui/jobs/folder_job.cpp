#include "ui/jobs/folder_job.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QThread>
#include <exception>
#include <new>

namespace multidir::ui {
namespace {

// What the worker hands back once the thread has finished.
struct Outcome {
  std::optional<core::Status> status;
  QString headline;  // an exception's, when `status` is empty
  QString detail;
};

}  // namespace

FolderJob::FolderJob(QObject* parent) : QObject(parent) {}

FolderJob::~FolderJob() {
  if (m_thread) {
    m_job.cancel();
    m_thread->wait();
    delete m_thread;
  }
}

bool FolderJob::start(const QString& folderPattern, Work work, StageText stageText, FailureTexts texts,
                      Finished finished, QString* folderError) {
  if (m_thread) return false;
  auto folder = std::make_shared<QTemporaryDir>(QDir(QDir::tempPath()).filePath(folderPattern));
  if (!folder->isValid()) {
    if (folderError) *folderError = folder->errorString();
    return false;
  }
  const int generation = ++m_generation;
  m_job = core::JobContext([this, generation, stageText](double fraction, const std::string& phase) {
    const QString stage = stageText(fraction, phase);
    // From the worker thread: queued to the GUI thread; `this` outlives the worker (the destructor waits).
    QMetaObject::invokeMethod(
        this,
        [this, generation, fraction, stage] {
          if (generation == m_generation && m_thread) emit progressed(fraction, stage);
        },
        Qt::QueuedConnection);
  });
  m_workFolder = folder->path();
  auto outcome = std::make_shared<Outcome>();
  core::JobContext job = m_job;  // copies share the cancellation flag
  const std::string directory = QFile::encodeName(folder->path()).toStdString();
  m_thread = QThread::create([outcome, work = std::move(work), directory, job, texts]() mutable {
    // Nothing may escape a worker thread: whatever goes wrong becomes a message.
    try {
      outcome->status = work(directory, job);
    } catch (const std::bad_alloc&) {
      outcome->status.reset();
      outcome->headline = texts.outOfMemory;
    } catch (const std::exception& e) {
      outcome->status.reset();
      outcome->headline = texts.unexpected;
      outcome->detail = QString::fromLocal8Bit(e.what());
    }
  });
  connect(m_thread, &QThread::finished, this,
          [this, outcome, folder, generation, finished = std::move(finished), headline = texts.headline]() mutable {
            if (generation != m_generation) return;
            m_thread->deleteLater();
            m_thread = nullptr;
            m_workFolder.clear();
            emit runningChanged(false);
            if (outcome->status && outcome->status->ok()) {
              finished(std::move(folder));
              return;
            }
            folder.reset();  // a failed or cancelled job leaves nothing behind
            if (!outcome->status) {
              emit failed(outcome->headline, outcome->detail);
            } else if (outcome->status->error().code == core::ErrorCode::Cancelled) {
              emit cancelled();
            } else {
              const core::Error& error = outcome->status->error();
              emit failed(headline(error), QString::fromStdString(error.describe()));
            }
          });
  m_thread->start();
  emit runningChanged(true);
  return true;
}

void FolderJob::cancel() {
  if (m_thread) m_job.cancel();
}

}  // namespace multidir::ui
