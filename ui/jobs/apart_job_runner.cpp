#include "ui/jobs/apart_job_runner.h"

#include <QDir>
#include <QFile>
#include <QThread>
#include <exception>
#include <new>
#include <optional>

#include "ui/common/error_text.h"

namespace multidir::ui {
namespace {

// What the worker hands back once the thread has finished.
struct Outcome {
  std::optional<core::Result<apart::ApartResult>> result;
  QString headline;  // an exception's, when `result` is empty
  QString detail;
};

// The pipeline's stage in the user's words: the library's phase names the stage first ("slicing plate 2 of 3").
QString stageText(const std::string& phase) {
  const QString text = QString::fromStdString(phase);
  if (text.startsWith(QLatin1String("slicing plate"))) {
    const QStringList words = text.split(QLatin1Char(' '));
    if (words.size() >= 5) return ApartJobRunner::tr("Slicing plate %1 of %2").arg(words.at(2), words.at(4));
  }
  if (text.startsWith(QLatin1String("slicing the model")))
    return ApartJobRunner::tr("Slicing the model in one piece with supports, for comparison");
  if (text.startsWith(QLatin1String("plan"))) return ApartJobRunner::tr("Cutting the parts to fit the printer");
  if (text.startsWith(QLatin1String("dowels"))) return ApartJobRunner::tr("Placing the dowels");
  if (text.startsWith(QLatin1String("drilling"))) return ApartJobRunner::tr("Drilling the dowel holes");
  if (text.startsWith(QLatin1String("numbers"))) return ApartJobRunner::tr("Sinking the part numbers");
  if (text.startsWith(QLatin1String("plates"))) return ApartJobRunner::tr("Laying the parts on plates");
  if (text.startsWith(QLatin1String("3MF"))) return ApartJobRunner::tr("Writing the parts and the 3MF");
  if (text.startsWith(QLatin1String("assembly sheet"))) return ApartJobRunner::tr("Drawing the assembly sheet");
  return text;
}

// What went wrong in plain words, with what to do; the library's message stays in the detail.
QString headlineFor(const core::Error& error) {
  if (error.code == core::ErrorCode::TooLarge)
    return ApartJobRunner::tr("A part does not fit this printer even cut further: choose a printer with a larger "
                              "bed, or scale the model down and search again.");
  if (error.code == core::ErrorCode::FileNotFound && error.where == "prusa-slicer")
    return ApartJobRunner::tr("The slicer 'prusa-slicer' was not found: install PrusaSlicer "
                              "(scripts/install-deps.sh), or untick \"Slice the plates\".");
  if (error.code == core::ErrorCode::ExternalToolFailed)
    return ApartJobRunner::tr("The slicer failed on a plate: its command and last output lines are below. Try "
                              "another printer, or untick \"Slice the plates\" to get the parts without G-code.");
  if (error.code == core::ErrorCode::InvalidParameter)
    return ApartJobRunner::tr("The parts could not be laid out or the dowels not placed: the reason is below. "
                              "Choose a printer with a larger bed or other dowel options.");
  if (error.code == core::ErrorCode::Internal)
    return ApartJobRunner::tr("Drilling the dowel holes or sinking the numbers failed on a part (named below): "
                              "try a smaller dowel diameter or another plan.");
  return errorHeadline(error.code);
}

}  // namespace

ApartJobRunner::ApartJobRunner(QObject* parent) : QObject(parent) {
  static const int registered = qRegisterMetaType<multidir::ui::ApartPrint>();
  (void)registered;
}

ApartJobRunner::~ApartJobRunner() {
  if (m_thread) {
    m_job.cancel();
    m_thread->wait();
    delete m_thread;
  }
}

bool ApartJobRunner::start(std::shared_ptr<const core::Decomposition> plan, const apart::PrintApartOptions& options,
                           QString* error) {
  if (m_thread) {
    if (error) *error = tr("The plan is being printed apart already.");
    return false;
  }
  if (!plan) {
    if (error) *error = tr("There is no plan to print apart: search the model first.");
    return false;
  }
  auto folder = std::make_shared<QTemporaryDir>(QDir(QDir::tempPath()).filePath(QStringLiteral("multidir-apart-XXXXXX")));
  if (!folder->isValid()) {
    if (error) *error = tr("Could not create a temporary folder for the parts: %1").arg(folder->errorString());
    return false;
  }
  const int generation = ++m_generation;
  m_job = core::JobContext([this, generation](double fraction, const std::string& phase) {
    const QString stage = stageText(phase);
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
  const std::string directory = QFile::encodeName(QDir(folder->path()).filePath(QStringLiteral("apart"))).toStdString();
  m_thread = QThread::create([outcome, plan, options, directory, job]() mutable {
    // Nothing may escape a worker thread: whatever goes wrong becomes a message.
    try {
      outcome->result = apart::printApart(*plan, options, directory, job);
    } catch (const std::bad_alloc&) {
      outcome->result.reset();
      outcome->headline = tr("Not enough memory to print this plan apart.");
    } catch (const std::exception& e) {
      outcome->result.reset();
      outcome->headline = tr("Unexpected error while printing the plan apart.");
      outcome->detail = QString::fromLocal8Bit(e.what());
    }
  });
  connect(m_thread, &QThread::finished, this, [this, outcome, folder, generation, plan]() mutable {
    if (generation != m_generation) return;
    m_thread->deleteLater();
    m_thread = nullptr;
    m_workFolder.clear();
    emit runningChanged(false);
    if (outcome->result && outcome->result->ok()) {
      ApartPrint print;
      print.plan = plan;
      print.result = std::make_shared<const apart::ApartResult>(std::move(outcome->result->value()));
      print.files = folder;
      emit finished(print);
      return;
    }
    folder.reset();  // a failed or cancelled job leaves nothing behind
    if (outcome->result && outcome->result->error().code == core::ErrorCode::Cancelled) {
      emit cancelled();
      return;
    }
    if (outcome->result) {
      const core::Error& error = outcome->result->error();
      emit failed(headlineFor(error), QString::fromStdString(error.describe()));
      return;
    }
    emit failed(outcome->headline, outcome->detail);
  });
  m_thread->start();
  emit runningChanged(true);
  return true;
}

void ApartJobRunner::cancel() {
  if (m_thread) m_job.cancel();
}

}  // namespace multidir::ui
