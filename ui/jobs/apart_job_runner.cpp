#include "ui/jobs/apart_job_runner.h"

#include <optional>

#include "ui/common/error_text.h"
#include "ui/jobs/folder_job.h"

namespace multidir::ui {
namespace {

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
    return ApartJobRunner::tr(
        "A part does not fit this printer even cut further: choose a printer with a larger "
        "bed, or scale the model down and search again.");
  if (error.code == core::ErrorCode::FileNotFound && error.where == "prusa-slicer")
    return ApartJobRunner::tr(
        "The slicer 'prusa-slicer' was not found: install PrusaSlicer "
        "(scripts/install-deps.sh), or untick \"Slice the plates\".");
  if (error.code == core::ErrorCode::ExternalToolFailed)
    return ApartJobRunner::tr(
        "The slicer failed on a plate: its command and last output lines are below. Try "
        "another printer, or untick \"Slice the plates\" to get the parts without G-code.");
  if (error.code == core::ErrorCode::InvalidParameter)
    return ApartJobRunner::tr(
        "The parts could not be laid out or the dowels not placed: the reason is below. "
        "Choose a printer with a larger bed or other dowel options.");
  if (error.code == core::ErrorCode::Internal)
    return ApartJobRunner::tr(
        "Drilling the dowel holes or sinking the numbers failed on a part (named below): "
        "try a smaller dowel diameter or another plan.");
  return errorHeadline(error.code);
}

}  // namespace

ApartJobRunner::ApartJobRunner(QObject* parent) : QObject(parent), m_job(new FolderJob(this)) {
  static const int registered = qRegisterMetaType<multidir::ui::ApartPrint>();
  (void)registered;
  connect(m_job, &FolderJob::progressed, this, &ApartJobRunner::progressed);
  connect(m_job, &FolderJob::runningChanged, this, &ApartJobRunner::runningChanged);
  connect(m_job, &FolderJob::failed, this, &ApartJobRunner::failed);
  connect(m_job, &FolderJob::cancelled, this, &ApartJobRunner::cancelled);
}

ApartJobRunner::~ApartJobRunner() = default;

bool ApartJobRunner::isRunning() const { return m_job->isRunning(); }

QString ApartJobRunner::workFolder() const { return m_job->workFolder(); }

bool ApartJobRunner::start(std::shared_ptr<const core::Decomposition> plan, const apart::PrintApartOptions& options,
                           QString* error) {
  if (m_job->isRunning()) {
    if (error) *error = tr("The plan is being printed apart already.");
    return false;
  }
  if (!plan) {
    if (error) *error = tr("There is no plan to print apart: search the model first.");
    return false;
  }
  auto result = std::make_shared<std::optional<apart::ApartResult>>();
  auto work = [result, plan, options](const std::string& folder, core::JobContext& job) -> core::Status {
    core::Result<apart::ApartResult> printed = apart::printApart(*plan, options, folder + "/apart", job);
    if (!printed) return printed.error();
    *result = std::move(printed).value();
    return core::Done{};
  };
  auto stage = [](double, const std::string& phase) { return stageText(phase); };
  auto finish = [this, result, plan](std::shared_ptr<QTemporaryDir> folder) {
    ApartPrint print;
    print.plan = plan;
    print.result = std::make_shared<const apart::ApartResult>(std::move(**result));
    print.files = std::move(folder);
    emit finished(print);
  };
  FolderJob::FailureTexts texts{headlineFor, tr("Not enough memory to print this plan apart."),
                                tr("Unexpected error while printing the plan apart.")};
  QString folderError;
  if (!m_job->start(QStringLiteral("multidir-apart-XXXXXX"), work, stage, texts, finish, &folderError)) {
    if (error) *error = tr("Could not create a temporary folder for the parts: %1").arg(folderError);
    return false;
  }
  return true;
}

void ApartJobRunner::cancel() { m_job->cancel(); }

}  // namespace multidir::ui
