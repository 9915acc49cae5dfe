#include "ui/slicing/slice_session.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QStatusBar>

#include "multidir/core/plan/plan_file.h"
#include "ui/document/plan_as_loaded.h"
#include "ui/main_window.h"
#include "ui/panels/slice_panel.h"
#include "ui/slicing/gcode_export.h"
#include "ui/viewer/gcode_toolpaths.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {

SliceSession::SliceSession(MainWindow& window, SlicePanel* panel)
    : QObject(&window), m_window(window), m_panel(panel), m_runner(new SliceJobRunner(this)) {
  connect(&window, &MainWindow::planShown, this, &SliceSession::onPlanChanged);
  connect(&window, &MainWindow::planCleared, this, &SliceSession::onPlanChanged);
  connect(&window, &MainWindow::supportsRegrown, this, &SliceSession::onPlanChanged);

  connect(panel, &SlicePanel::sliceClicked, this, &SliceSession::chooseAndSlice);
  connect(panel, &SlicePanel::cancelClicked, this, &SliceSession::cancel);
  connect(panel, &SlicePanel::exportClicked, this, &SliceSession::chooseExportGcode);
  connect(panel, &SlicePanel::previewToggled, this, &SliceSession::setPreviewShown);
  connect(panel, &SlicePanel::layerLimitChanged, this, &SliceSession::showLayer);
  connect(panel, &SlicePanel::travelVisibleChanged, this,
          [this](bool visible) { m_window.viewer()->setGcodeTravelVisible(visible); });

  connect(m_runner, &SliceJobRunner::runningChanged, this, [this](bool running) {
    m_panel->showRunning(running);
    updateSliceable();
  });
  connect(m_runner, &SliceJobRunner::progressed, m_panel, &SlicePanel::showProgress);
  connect(m_runner, &SliceJobRunner::finished, this, &SliceSession::onFinished);
  connect(m_runner, &SliceJobRunner::failed, this, [this](const QString& headline, const QString& detail) {
    m_plan.reset();
    m_supports.reset();
    m_panel->showMessage(tr("Slicing failed: %1").arg(headline), detail);
    m_window.statusBar()->showMessage(tr("Slicing failed: %1").arg(headline));
    emit sliceFailed(headline + QLatin1Char('\n') + detail);
  });
  connect(m_runner, &SliceJobRunner::cancelled, this, [this] {
    m_plan.reset();
    m_supports.reset();
    m_panel->showMessage(tr("Slicing cancelled: nothing was written."), QString(), false);
    m_window.statusBar()->showMessage(tr("Slicing cancelled."));
    emit sliceCancelled();
  });
  updateSliceable();
}

void SliceSession::updateSliceable() {
  const auto& run = m_window.plan();
  if (!run || !run->plan) {
    m_panel->setSliceable(false, tr("Show a plan first: run a search or open a plan."));
  } else if (run->plan->jgAfterMm2 > 0.0 && !run->supports && m_window.isGrowingSupports()) {
    m_panel->setSliceable(false, tr("The plan's supports are still being grown: slice it when they are ready."));
  } else {
    m_panel->setSliceable(true);
  }
  emit sliceableChanged(m_panel->sliceButton()->isEnabled());
}

void SliceSession::onPlanChanged() {
  const auto& run = m_window.plan();
  const bool same = run && run->plan == m_plan && run->supports == m_supports && (m_outcome || isSlicing());
  if (!same) {
    if (isSlicing()) {
      m_runner->cancel();
      m_panel->showMessage(tr("The plan changed: slicing was cancelled."), QString(), false);
    } else if (m_outcome && run) {
      m_panel->showMessage(tr("The plan changed: slice it again for its G-code."), QString(), false);
    } else if (!run) {
      m_panel->showMessage(QString(), QString(), false);  // no plan (another model): nothing to slice again
    }
    dropResult();
  }
  updateSliceable();
}

void SliceSession::dropResult() {
  const bool had = m_outcome.has_value();
  m_outcome.reset();
  m_plan.reset();
  m_supports.reset();
  m_window.viewer()->setGcodePreview(nullptr);
  m_panel->clearResult();
  if (had) emit resultAvailable(false);
}

void SliceSession::chooseAndSlice() {
  const auto& run = m_window.plan();
  if (!run || !run->plan) return;
  auto* dialog = new SliceDialog(run->machine.kind, &m_window);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    if (const std::optional<SliceChoice> choice = dialog->choice()) slice(*choice);
  });
  dialog->open();
}

bool SliceSession::slice(const SliceChoice& choice) {
  const auto& run = m_window.plan();
  updateSliceable();
  if (!run || !run->plan) {
    m_panel->showMessage(tr("There is no plan to slice: run a search or open a plan."));
    return false;
  }
  if (isSlicing()) {
    m_panel->showMessage(tr("A slicing job is already running."));
    return false;
  }
  if (run->plan->jgAfterMm2 > 0.0 && !run->supports && m_window.isGrowingSupports()) {
    m_panel->showMessage(tr("The plan's supports are still being grown: slice it when they are ready."));
    return false;
  }
  // The plan as shown, with its supports: what `multidir slice` reads from a plan folder.
  const core::LoadedPlan plan = planAsLoaded(*run, m_window.model());
  dropResult();
  QString error;
  if (!m_runner->start(plan, choice.profile, choice.options, &error)) {
    m_panel->showMessage(error);
    return false;
  }
  m_plan = run->plan;
  m_supports = run->supports;
  // A plan that needs supports but could not get them is sliced all the same, never silently.
  if (run->plan->jgAfterMm2 > 0.0 && !run->supports) {
    m_panel->showMessage(tr("Slicing without supports although the plan leaves risky area: %1")
                             .arg(run->supportsNote.isEmpty() ? tr("no supports were grown for it.") : run->supportsNote),
                         QString(), false);
  } else {
    m_panel->showMessage(QString());
  }
  m_window.statusBar()->showMessage(tr("Slicing the plan for %1...").arg(QString::fromStdString(choice.profile.name)));
  return true;
}

void SliceSession::cancel() {
  if (!isSlicing()) return;
  m_runner->cancel();
  m_panel->showProgress(0.0, tr("Cancelling: stopping the slicer..."));
}

void SliceSession::onFinished(const SliceOutcome& outcome) {
  const auto& run = m_window.plan();
  if (!run || run->plan != m_plan || run->supports != m_supports) return;  // the plan changed meanwhile
  m_outcome = outcome;
  m_panel->showResult(*outcome.job, outcome.preview ? outcome.preview->layerCount() : 0);
  if (const GcodePreview* preview = outcome.preview.get(); preview && preview->audited) {
    const double percent =
        preview->auditedExtrusionMm > 0.0 ? 100.0 * preview->unsupportedMm / preview->auditedExtrusionMm : 0.0;
    m_panel->showUnsupported(true, preview->unsupportedMm, percent);
  }
  const double total = outcome.job->total.printSeconds;
  // An audit that failed costs the preview its marks only: the job is sliced, the message says why.
  m_panel->showMessage(tr("Sliced for %1: %n step(s), %2 of printing.", nullptr, static_cast<int>(outcome.job->steps.size()))
                           .arg(QString::fromStdString(outcome.job->profile.name),
                                QString::fromStdString(slicing::durationText(total))),
                       outcome.auditError, !outcome.auditError.isEmpty());
  m_window.statusBar()->showMessage(outcome.auditError.isEmpty() ? tr("Slicing finished.")
                                                                 : tr("Slicing finished; the audit failed."));
  emit resultAvailable(true);
  emit sliced();
}

bool SliceSession::setPreviewShown(bool shown) {
  MeshViewerWidget* viewer = m_window.viewer();
  if (!shown || !m_outcome || !m_outcome->preview) {
    viewer->setGcodePreview(nullptr);
    m_panel->setPreviewShown(false);
    return !shown;
  }
  if (!viewer->setGcodePreview(m_outcome->preview)) {
    m_panel->setPreviewShown(false);
    return false;
  }
  viewer->setGcodeTravelVisible(m_panel->travelBox()->isChecked());
  const int layers = m_panel->layerSlider()->value();
  viewer->setGcodeLayerLimit(layers);
  showLayer(layers);
  m_panel->setPreviewShown(true);
  return true;
}

void SliceSession::showLayer(int layers) {
  if (!m_outcome || !m_outcome->preview) return;
  m_window.viewer()->setGcodeLayerLimit(layers);
  const GcodePreview& preview = *m_outcome->preview;
  if (layers < 1 || layers > preview.layerCount()) {
    m_panel->setLayerText(QString());
    m_panel->setLayerZ(std::nullopt);
    return;
  }
  const ToolpathLayer& layer = preview.layers[static_cast<std::size_t>(layers - 1)];
  m_panel->setLayerZ(layer.printerZMm);
  m_panel->setLayerText(tr("Layer %1 of %2: step %3, its layer %4").arg(layers).arg(preview.layerCount())
                            .arg(layer.step).arg(layer.layerInStep));
}

bool SliceSession::exportGcode(const QString& directory, QString* error, bool intoOtherFolder) {
  if (!m_outcome) {
    if (error) *error = tr("There is no G-code to export: slice the plan first.");
    return false;
  }
  QStringList written;
  QString problem;
  if (!exportSlicedFiles(m_outcome->folderPath(), directory, &written, &problem, intoOtherFolder)) {
    m_window.statusBar()->showMessage(problem);
    if (error) *error = problem;
    return false;
  }
  m_window.statusBar()->showMessage(tr("G-code exported to %1 (%n file(s)).", nullptr, static_cast<int>(written.size()))
                                        .arg(QDir::toNativeSeparators(directory)));
  return true;
}

void SliceSession::chooseExportGcode() {
  if (!m_outcome) return;
  const QString stem = m_window.model() ? QFileInfo(m_window.model()->name).completeBaseName() : QStringLiteral("multidir");
  // A folder name: an existing folder, or a new one that exportGcode creates.
  const QString directory = QFileDialog::getSaveFileName(
      &m_window, tr("Export G-code to Folder"), QDir(m_window.dialogFolder(FileKind::Plan)).filePath(stem + tr("-gcode")),
      tr("G-code folders (*)"), nullptr, QFileDialog::ShowDirsOnly | QFileDialog::DontConfirmOverwrite);
  if (directory.isEmpty()) return;
  rememberDialogFolder(FileKind::Plan, directory);
  // The user's own files are never replaced without asking (`multidir slice` wants --force for it).
  const QString other = otherFileIn(directory);
  if (!other.isEmpty() &&
      QMessageBox::question(&m_window, tr("Export G-code"),
                            tr("%1 holds files that are not a MultiDir job (%2 is one).\n\nWrite the job into this "
                               "folder anyway? Files with the job's names are replaced; the others stay.")
                                .arg(QDir::toNativeSeparators(directory), other),
                            QMessageBox::Yes | QMessageBox::No, QMessageBox::No) != QMessageBox::Yes)
    return;
  QString error;
  if (!exportGcode(directory, &error, !other.isEmpty())) QMessageBox::warning(&m_window, tr("Export G-code"), error);
}

}  // namespace multidir::ui
