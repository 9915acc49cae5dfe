// MainWindow's best pose: the Machine panel's "Best pose" group (PoseSearchBox) run by PoseSearchJob, the
// preview of a pose in the view and "Use this pose".
#include <QStatusBar>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/plan/pose_runners_up.h"
#include "ui/common/error_text.h"
#include "ui/main_window.h"
#include "ui/panels/machine_panel.h"
#include "ui/panels/overhang_panel.h"
#include "ui/panels/pose_search_box.h"
#include "ui/panels/search_panel.h"
#include "ui/project/project_session.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {

void MainWindow::buildPoseSearch() {
  PoseSearchBox* box = m_machinePanel->poseBox();
  connect(box, &PoseSearchBox::findClicked, this, [this] { findBestPose(); });
  connect(box, &PoseSearchBox::cancelClicked, this, &MainWindow::cancelPoseSearch);
  connect(box, &PoseSearchBox::poseClicked, this, &MainWindow::previewPose);
  connect(box, &PoseSearchBox::useClicked, this, &MainWindow::usePoseFromUser);
  connect(box, &PoseSearchBox::showCurrentClicked, this, &MainWindow::showCurrentUp);
  connect(m_poseSearch, &PoseSearchJob::progressed, this, [this](double fraction, PoseSearchJob::Phase phase) {
    if (!m_dropPoseResult) m_machinePanel->poseBox()->showProgress(fraction, phase);
  });
  connect(m_poseSearch, &PoseSearchJob::finished, this, &MainWindow::onPoseSearchFinished);
  connect(m_poseSearch, &PoseSearchJob::failed, this, &MainWindow::onPoseSearchFailed);
  // Either search blocks the other: both buttons follow whichever runs.
  connect(m_poseSearch, &PoseSearchJob::runningChanged, this, [this] { updateRunnable(); });
  connect(m_search, &SearchJob::runningChanged, this, [this] { updatePoseRunnable(); });
}

void MainWindow::updatePoseRunnable() {
  PoseSearchBox* box = m_machinePanel->poseBox();
  if (!model()) {
    box->setRunnable(false, tr("Open a model first."));
  } else if (!m_machinePanel->errorText().isEmpty()) {
    box->setRunnable(false, tr("Fix the machine first: %1").arg(m_machinePanel->errorText()));
  } else if (m_search->isRunning()) {
    box->setRunnable(false, tr("A search is running: wait for it or cancel it."));
  } else {
    box->setRunnable(true, QString());
  }
}

bool MainWindow::isPoseSearching() const { return m_poseSearch->isRunning(); }

bool MainWindow::findBestPose() {
  PoseSearchBox* box = m_machinePanel->poseBox();
  QString problem;
  if (m_poseSearch->isRunning()) problem = tr("A pose search is already running.");
  else if (m_search->isRunning()) problem = tr("A search is running: wait for it or cancel it.");
  else if (!model()) problem = tr("Open a model first.");
  else if (model()->mesh == m_regionsModel) problem = tr("This plan was opened without its model: open the model.");
  else if (!m_machinePanel->validateFor(upDirection())) problem = m_machinePanel->errorText();
  const core::SearchOptions options = m_searchPanel->searchOptions();
  const core::PoseOptions poseOptions = box->poseOptions();
  if (problem.isEmpty()) {
    core::Status valid = core::validate(options);
    if (valid) valid = core::validate(poseOptions);
    if (!valid) problem = tr("%1 (%2)").arg(errorHeadline(valid.error().code),
                                             QString::fromStdString(valid.error().describe()));
  }
  if (!problem.isEmpty()) {
    statusBar()->showMessage(tr("Cannot find the best pose: %1").arg(problem));
    box->showFailure(tr("Cannot find the best pose."), problem);
    emit poseSearchFailed(problem);
    return false;
  }
  endPreview();
  m_poseRun.reset();
  const core::MachineSpec machine = m_document->machine();
  if (!m_poseSearch->start(model()->mesh, machine, options, poseOptions)) return false;
  box->searchStarted();
  statusBar()->showMessage(tr("Finding the best pose for %1...").arg(model()->name));
  return true;
}

void MainWindow::cancelPoseSearch() {
  if (!m_poseSearch->isRunning()) return;
  m_poseSearch->cancel();
  m_machinePanel->poseBox()->cancelRequested();
  statusBar()->showMessage(tr("Cancelling the pose search..."));
}

void MainWindow::onPoseSearchFinished(const PoseRun& run) {
  if (m_dropPoseResult) {
    m_dropPoseResult = false;
    return;
  }
  PoseSearchBox* box = m_machinePanel->poseBox();
  // Never a plan of one model over another: a result for a model or an up no longer shown is dropped.
  const bool current = model() && model()->mesh == run.model && (upDirection() - run.machine.up).norm() < 1e-9;
  if (!current) {
    box->clear();
    statusBar()->showMessage(tr("The pose search result was dropped: the model or its up direction changed."));
    return;
  }
  m_poseRun = run;
  const bool cancelled = run.chosenRun.plan->cancelled;
  box->showResult(*run.result, cancelled);
  markPoseInUse();
  emit poseSearchFinished();
  if (cancelled) {
    // The plan shown stays: the best pose that finished is there to use.
    statusBar()->showMessage(tr("Pose search cancelled: the poses that finished are listed; the plan shown is "
                                "unchanged."));
    return;
  }
  statusBar()->showMessage(tr("Best pose found."));
  usePoseFromUser(run.result->chosenTrial);
}

void MainWindow::onPoseSearchFailed(const QString& headline, const QString& detail, bool cancelled) {
  if (m_dropPoseResult) {
    m_dropPoseResult = false;
    return;
  }
  m_machinePanel->poseBox()->showFailure(headline, detail);
  statusBar()->showMessage(cancelled ? tr("Pose search cancelled before any pose finished: the plan shown is "
                                          "unchanged.")
                                     : tr("Pose search failed: %1").arg(headline));
  emit poseSearchFailed(detail.isEmpty() ? headline : headline + QLatin1Char(' ') + detail);
}

void MainWindow::previewPose(int trial) {
  if (!m_poseRun || !model() || model()->mesh != m_poseRun->model) return;
  const std::vector<core::PoseTrial>& trials = m_poseRun->result->trials;
  if (trial < 0 || trial >= static_cast<int>(trials.size())) return;
  const core::Vec3 up = trials[static_cast<std::size_t>(trial)].pose.up;
  m_previewUp = up;
  // The viewer shows the up as the platform below the model and up on screen: the model stands on the pose.
  m_viewer->setMesh(*model()->mesh, up);
  core::OverhangOptions overhang;
  overhang.alphaMaxDegrees = m_overhangPanel->alphaMaxDegrees();
  if (const core::Result<core::OverhangAnalysis> risky = core::analyzeOverhang(*model()->mesh, up, overhang); risky)
    m_viewer->setRiskyFaces(risky->risky);
  statusBar()->showMessage(tr("Showing pose %1 (up %2, %3, %4): the project is unchanged. \"Use this pose\" makes it "
                              "the model's up; \"Show current up\" goes back.")
                               .arg(trial + 1)
                               .arg(up.x(), 0, 'f', 2)
                               .arg(up.y(), 0, 'f', 2)
                               .arg(up.z(), 0, 'f', 2));
}

void MainWindow::showCurrentUp() {
  if (!m_previewUp) return;
  endPreview();
  statusBar()->clearMessage();
}

void MainWindow::endPreview() {
  if (!m_previewUp || !model()) {
    m_previewUp.reset();
    return;
  }
  m_previewUp.reset();
  m_viewer->setMesh(*model()->mesh, upDirection());
  updateOverhangs();
  if (plan() && plan()->plan) {
    m_viewer->setPlan(plan()->plan);
    m_viewer->setSupports(plan()->supports);
  }
}

void MainWindow::usePoseFromUser(int trial) {
  if (!m_poseRun || trial < 0 || trial >= static_cast<int>(m_poseRun->result->trials.size())) return;
  // As the Up box: a running search or an unsaved plan is not dropped without asking.
  const bool dropsWork = isSearching() || (plan().has_value() && m_project->isModified());
  const std::shared_ptr<const core::PoseSearchResult> result = m_poseRun->result;
  auto apply = [this, trial, result] {
    // The question may have been answered after another pose search or model replaced this one.
    if (m_poseRun && m_poseRun->result == result) applyPose(trial);
  };
  if (!dropsWork) {
    apply();
    return;
  }
  m_project->whenWorkMayBeReplaced(apply);
}

void MainWindow::applyPose(int trial) {
  const PoseRun run = *m_poseRun;  // a copy: showing the plan below may replace m_poseRun's owner state
  if (!model() || model()->mesh != run.model) {
    statusBar()->showMessage(tr("This pose belongs to another model: find the best pose again."));
    return;
  }
  const core::PoseSearchResult& result = *run.result;
  const core::PoseTrial& chosen = result.trials[static_cast<std::size_t>(trial)];
  UpPose pose;
  pose.up = chosen.pose.up;  // unit already (core's candidates); setUpPose keeps it bit for bit
  pose.pose.source = core::poseSourceName(chosen.pose.source);
  pose.pose.contactAreaMm2 = chosen.pose.contactAreaMm2;
  pose.pose.platformUp = run.machine.up.normalized();
  pose.runnersUp = core::poseRunnersUp(result, trial);
  // The machine turns with the pose (a 4-DOF axis and forbidden cones stay where they were on the platform).
  m_document->setMachine(core::machineForPose(run.machine, pose.up));
  setUpPose(pose);
  if (trial == result.chosenTrial) {
    showPlan(run.chosenRun);
    statusBar()->showMessage(tr("The model now stands on the best pose; its plan is shown."));
  } else if (runSearch()) {
    // Only the chosen pose's plan comes back from the pose search: another pose is searched now.
    statusBar()->showMessage(tr("The model now stands on pose %1; searching its plan...").arg(trial + 1));
  }
  markPoseInUse();
}

void MainWindow::markPoseInUse() {
  int inUse = -1;
  if (m_poseRun) {
    const std::vector<core::PoseTrial>& trials = m_poseRun->result->trials;
    for (std::size_t i = 0; i < trials.size() && inUse < 0; ++i) {
      if ((trials[i].pose.up.normalized() - upDirection()).norm() < 1e-9) inUse = static_cast<int>(i);
    }
  }
  m_machinePanel->poseBox()->setTrialInUse(inUse);
}

}  // namespace multidir::ui
