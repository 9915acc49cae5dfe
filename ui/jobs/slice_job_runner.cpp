#include "ui/jobs/slice_job_runner.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QThread>
#include <exception>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>

#include "multidir/slicing/gcode_program.h"
#include "ui/common/error_text.h"
#include "ui/jobs/preview_audit.h"
#include "ui/viewer/gcode_toolpaths.h"

namespace multidir::ui {
namespace {

// What the worker hands back once the thread has finished.
struct Outcome {
  std::optional<core::Result<slicing::SlicedJob>> sliced;
  std::shared_ptr<const GcodePreview> preview;
  QString headline;  // an exception's, when `sliced` is empty
  QString detail;
  std::string auditError;  // the audit failed: the preview is shown without its marks
};

core::Result<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return core::Error{core::ErrorCode::FileNotFound, "cannot read the G-code just written", path};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every step's program read back from `folder`, for the preview.
core::Result<GcodePreview> previewOf(const slicing::SlicedJob& job, const std::string& folder,
                                     const core::JobContext& context) {
  std::vector<StepProgram> steps;
  for (const slicing::SlicedStep& step : job.steps) {
    if (context.isCancelled()) return core::Error{core::ErrorCode::Cancelled, "slicing was cancelled", "slicing"};
    const core::Result<std::string> text = readText(folder + "/" + step.gcodeFile);
    if (!text) return text.error();
    core::Result<slicing::GcodeProgram> program = slicing::parseGcode(*text, slicing::rotaryAxisNames(job.profile), step.gcodeFile);
    if (!program) return program.error();
    steps.push_back({step.index, std::move(program).value(), step.modelToPrinter});
  }
  return buildGcodePreview(steps);
}

QString stageText(double fraction, int steps, bool fixedDirection) {
  const slicing::SliceStage stage = slicing::sliceStageAt(fraction, steps, fixedDirection);
  switch (stage.kind) {
    case slicing::SliceStage::Kind::Step:
      return SliceJobRunner::tr("Slicing step %1 of %2").arg(stage.step).arg(steps);
    case slicing::SliceStage::Kind::FixedDirection:
      return SliceJobRunner::tr("Slicing the whole model along up with the slicer's supports, for comparison");
    case slicing::SliceStage::Kind::Stitching:
      return SliceJobRunner::tr("Stitching the steps into one program");
    case slicing::SliceStage::Kind::Done:
      break;
  }
  return SliceJobRunner::tr("Reading the G-code for the preview");
}

// A translated sentence for what went wrong; the slicer's own messages stay in the detail.
QString headlineFor(const core::Error& error, const std::string& slicer) {
  if (error.code == core::ErrorCode::FileNotFound && error.where == slicer)
    return SliceJobRunner::tr("The slicer '%1' was not found: install PrusaSlicer (scripts/install-deps.sh) or "
                              "give the slicer program's full path in the Slice dialog.")
        .arg(QString::fromStdString(slicer));
  if (error.code == core::ErrorCode::ExternalToolFailed)
    return SliceJobRunner::tr("The slicer failed: its command and last output lines are below.");
  if (error.code == core::ErrorCode::TooLarge)
    return SliceJobRunner::tr("The part does not fit this printer, so nothing was sliced: by how much, and what "
                              "would help, is below.");
  if (error.code == core::ErrorCode::CheckFailed)
    return SliceJobRunner::tr("The G-code failed MultiDir's checks and was not kept: the step, line and reason are "
                              "below.");
  return errorHeadline(error.code);
}

}  // namespace

QString SliceOutcome::folderPath() const { return folder ? folder->path() : QString(); }

SliceJobRunner::SliceJobRunner(QObject* parent) : QObject(parent) {
  static const int registered = qRegisterMetaType<multidir::ui::SliceOutcome>();
  (void)registered;
}

SliceJobRunner::~SliceJobRunner() {
  if (m_thread) {
    m_job.cancel();
    m_thread->wait();
    delete m_thread;
  }
}

bool SliceJobRunner::start(const core::LoadedPlan& plan, const slicing::PrinterProfile& profile,
                           const slicing::SliceJobOptions& options, QString* error) {
  if (m_thread) {
    if (error) *error = tr("A slicing job is already running.");
    return false;
  }
  auto folder = std::make_shared<QTemporaryDir>(QDir(QDir::tempPath()).filePath(QStringLiteral("multidir-slice-XXXXXX")));
  if (!folder->isValid()) {
    if (error) *error = tr("Could not create a temporary folder for the G-code: %1").arg(folder->errorString());
    return false;
  }
  const int generation = ++m_generation;
  const int steps = static_cast<int>(plan.decomposition.regions.size());
  const bool fixedDirection = options.fixedDirection;
  m_job = core::JobContext([this, generation, steps, fixedDirection](double fraction, const std::string&) {
    // From the worker thread: queued to the GUI thread; `this` outlives the worker (the destructor waits).
    QMetaObject::invokeMethod(
        this,
        [this, generation, fraction, steps, fixedDirection] {
          if (generation == m_generation && m_thread) emit progressed(fraction, stageText(fraction, steps, fixedDirection));
        },
        Qt::QueuedConnection);
  });
  m_workFolder = folder->path();
  auto outcome = std::make_shared<Outcome>();
  core::JobContext job = m_job;  // copies share the cancellation flag
  const std::string directory = QFile::encodeName(folder->path()).toStdString();
  m_thread = QThread::create([outcome, plan, profile, options, directory, job]() mutable {
    // Nothing may escape a worker thread: whatever goes wrong becomes a message.
    try {
      outcome->sliced = slicing::slicePlan(plan, profile, options, directory, job);
      if (outcome->sliced->ok()) {
        core::Result<GcodePreview> preview = previewOf(outcome->sliced->value(), directory, job);
        if (!preview) {
          outcome->sliced = preview.error();
        } else {
          GcodePreview shown = std::move(preview).value();
          const core::Status audit =
              markUnsupportedExtrusions(shown, directory, plan.metadata.options.alphaMaxDegrees, job);
          if (!audit && audit.error().code == core::ErrorCode::Cancelled) {
            outcome->sliced = audit.error();
          } else {
            if (!audit) outcome->auditError = audit.error().describe();
            outcome->preview = std::make_shared<const GcodePreview>(std::move(shown));
          }
        }
      }
    } catch (const std::bad_alloc&) {
      outcome->sliced.reset();
      outcome->headline = tr("Not enough memory to slice this plan.");
    } catch (const std::exception& e) {
      outcome->sliced.reset();
      outcome->headline = tr("Unexpected error while slicing.");
      outcome->detail = QString::fromLocal8Bit(e.what());
    }
  });
  connect(m_thread, &QThread::finished, this, [this, outcome, folder, generation, options]() mutable {
    if (generation != m_generation) return;
    m_thread->deleteLater();
    m_thread = nullptr;
    m_workFolder.clear();
    emit runningChanged(false);
    if (outcome->sliced && outcome->sliced->ok()) {
      SliceOutcome result;
      result.job = std::make_shared<const slicing::SlicedJob>(std::move(outcome->sliced->value()));
      result.preview = outcome->preview;
      result.folder = folder;
      if (!outcome->auditError.empty())
        result.auditError = tr("The audit of the G-code failed, so unsupported extrusions are not marked: %1")
                                .arg(QString::fromStdString(outcome->auditError));
      emit finished(result);
      return;
    }
    folder.reset();  // a failed or cancelled job leaves nothing behind
    if (outcome->sliced && outcome->sliced->error().code == core::ErrorCode::Cancelled) {
      emit cancelled();
      return;
    }
    if (outcome->sliced) {
      const core::Error& error = outcome->sliced->error();
      emit failed(headlineFor(error, options.slicerExecutable), QString::fromStdString(error.describe()));
      return;
    }
    emit failed(outcome->headline, outcome->detail);
  });
  m_thread->start();
  emit runningChanged(true);
  return true;
}

void SliceJobRunner::cancel() {
  if (m_thread) m_job.cancel();
}

}  // namespace multidir::ui
