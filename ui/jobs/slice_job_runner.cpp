#include "ui/jobs/slice_job_runner.h"

#include <QTemporaryDir>
#include <fstream>
#include <optional>
#include <sstream>

#include "multidir/slicing/gcode_program.h"
#include "ui/common/error_text.h"
#include "ui/jobs/folder_job.h"
#include "ui/jobs/preview_audit.h"
#include "ui/viewer/gcode_toolpaths.h"

namespace multidir::ui {
namespace {

// What the work hands back to the GUI thread besides its status.
struct Outcome {
  std::optional<slicing::SlicedJob> sliced;
  std::shared_ptr<const GcodePreview> preview;
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
    core::Result<slicing::GcodeProgram> program =
        slicing::parseGcode(*text, slicing::rotaryAxisNames(job.profile), step.gcodeFile);
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
    return SliceJobRunner::tr(
               "The slicer '%1' was not found: install PrusaSlicer (scripts/install-deps.sh) or "
               "give the slicer program's full path in the Slice dialog.")
        .arg(QString::fromStdString(slicer));
  if (error.code == core::ErrorCode::ExternalToolFailed)
    return SliceJobRunner::tr("The slicer failed: its command and last output lines are below.");
  if (error.code == core::ErrorCode::TooLarge)
    return SliceJobRunner::tr(
        "The part does not fit this printer, so nothing was sliced: by how much, and what "
        "would help, is below.");
  if (error.code == core::ErrorCode::CheckFailed)
    return SliceJobRunner::tr(
        "The G-code failed MultiDir's checks and was not kept: the step, line and reason are "
        "below.");
  return errorHeadline(error.code);
}

}  // namespace

QString SliceOutcome::folderPath() const { return folder ? folder->path() : QString(); }

SliceJobRunner::SliceJobRunner(QObject* parent) : QObject(parent), m_job(new FolderJob(this)) {
  static const int registered = qRegisterMetaType<multidir::ui::SliceOutcome>();
  (void)registered;
  connect(m_job, &FolderJob::progressed, this, &SliceJobRunner::progressed);
  connect(m_job, &FolderJob::runningChanged, this, &SliceJobRunner::runningChanged);
  connect(m_job, &FolderJob::failed, this, &SliceJobRunner::failed);
  connect(m_job, &FolderJob::cancelled, this, &SliceJobRunner::cancelled);
}

SliceJobRunner::~SliceJobRunner() = default;

bool SliceJobRunner::isRunning() const { return m_job->isRunning(); }

QString SliceJobRunner::workFolder() const { return m_job->workFolder(); }

bool SliceJobRunner::start(const core::LoadedPlan& plan, const slicing::PrinterProfile& profile,
                           const slicing::SliceJobOptions& options, QString* error) {
  if (m_job->isRunning()) {
    if (error) *error = tr("A slicing job is already running.");
    return false;
  }
  const int steps = static_cast<int>(plan.decomposition.regions.size());
  const bool fixedDirection = options.fixedDirection;
  auto outcome = std::make_shared<Outcome>();
  auto work = [outcome, plan, profile, options](const std::string& directory, core::JobContext& job) -> core::Status {
    core::Result<slicing::SlicedJob> sliced = slicing::slicePlan(plan, profile, options, directory, job);
    if (!sliced) return sliced.error();
    core::Result<GcodePreview> preview = previewOf(*sliced, directory, job);
    if (!preview) return preview.error();
    GcodePreview shown = std::move(preview).value();
    const core::Status audit = markUnsupportedExtrusions(shown, directory, plan.metadata.options.alphaMaxDegrees, job);
    if (!audit && audit.error().code == core::ErrorCode::Cancelled) return audit.error();
    if (!audit) outcome->auditError = audit.error().describe();
    outcome->sliced = std::move(sliced).value();
    outcome->preview = std::make_shared<const GcodePreview>(std::move(shown));
    return core::Done{};
  };
  auto stage = [steps, fixedDirection](double fraction, const std::string&) {
    return stageText(fraction, steps, fixedDirection);
  };
  auto finish = [this, outcome](std::shared_ptr<QTemporaryDir> folder) {
    SliceOutcome result;
    result.job = std::make_shared<const slicing::SlicedJob>(std::move(*outcome->sliced));
    result.preview = outcome->preview;
    result.folder = std::move(folder);
    if (!outcome->auditError.empty())
      result.auditError = tr("The audit of the G-code failed, so unsupported extrusions are not marked: %1")
                              .arg(QString::fromStdString(outcome->auditError));
    emit finished(result);
  };
  const std::string slicer = options.slicerExecutable;
  FolderJob::FailureTexts texts{[slicer](const core::Error& e) { return headlineFor(e, slicer); },
                                tr("Not enough memory to slice this plan."), tr("Unexpected error while slicing.")};
  QString folderError;
  if (!m_job->start(QStringLiteral("multidir-slice-XXXXXX"), work, stage, texts, finish, &folderError)) {
    if (error) *error = tr("Could not create a temporary folder for the G-code: %1").arg(folderError);
    return false;
  }
  return true;
}

void SliceJobRunner::cancel() { m_job->cancel(); }

}  // namespace multidir::ui
