#include "ui/studio_test_support.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QTimer>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMessageBox>
#include <QMimeData>
#include <QUrl>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "multidir/core/mesh/mesh_io.h"
#include "support/primitives.h"
#include "ui/main_window.h"
#include "ui/project/autosave.h"
#include "ui/project/project_session.h"
#include "ui/panels/search_panel.h"
#include "ui/studio_startup.h"

namespace multidir::test {

void resetStudioSettings() {
  QSettings settings;
  for (const char* group : {"recentFiles", "window", "autosave", "dialogFolders", "slicing"}) settings.remove(QLatin1String(group));
  for (const QString& orphan : ui::Autosave::orphans()) ui::Autosave::removeOrphan(orphan);
}

void showDefaultSample(ui::MainWindow& window, const QSize& size) {
  window.resize(size);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  QSignalSpy shown(&window, &ui::MainWindow::modelShown);
  ui::startStudio(window, ui::StudioOptions{});
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs)) << "the default sample did not load";
}

void openSample(ui::MainWindow& window, const QString& id) {
  QSignalSpy shown(&window, &ui::MainWindow::modelShown);
  window.openSample(id);
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs)) << "did not build " << id.toStdString();
}

core::SearchOptions quickSearchOptions() {
  core::SearchOptions options;
  options.beamWidth = 2;
  options.candidates.normalSamples = 60;
  options.candidates.offsetStepMm = 2.0;
  options.minVolumeDivisor = 10.0;  // a few large regions keep the scenes the tests look at readable
  options.volumeScales = 1;         // ... and so does one scale (w = 20 would add small ones)
  return options;
}

core::SearchOptions longSearchOptions() {
  core::SearchOptions options;
  options.beamWidth = 20;
  options.candidates.normalSamples = 3000;
  options.candidates.offsetStepMm = 0.5;
  return options;
}

ui::SearchRun runQuickSearch(ui::MainWindow& window) {
  window.searchPanel()->setSearchOptions(quickSearchOptions());
  return runSearchAsSet(window);
}

ui::SearchRun runSearchAsSet(ui::MainWindow& window) {
  QSignalSpy finished(&window, &ui::MainWindow::searchFinished);
  const bool started = window.runSearch();
  EXPECT_TRUE(started) << "the search did not start";
  if (!started) return {};
  EXPECT_TRUE(window.isSearching());
  EXPECT_TRUE(finished.wait(kSearchTimeoutMs)) << "the search did not finish";
  if (finished.isEmpty()) return {};
  return finished.front().front().value<ui::SearchRun>();
}

bool lockedWhilePanelSearches(ui::SearchPanel& panel, const QWidget& field) {
  panel.searchStarted(100.0, 10);
  const bool locked = !field.isEnabled();
  core::Decomposition plan;
  plan.jgBeforeMm2 = plan.jgAfterMm2 = 100.0;
  panel.searchFinished(plan);
  return locked && field.isEnabled();
}

void openPlanFolder(ui::MainWindow& window, const QString& folder) {
  QSignalSpy planShown(&window, &ui::MainWindow::planShown);
  QString error;
  ASSERT_TRUE(window.openPlan(folder, &error)) << error.toStdString();
  // A plan without its model is shown at once; one with a model when the model has loaded.
  if (planShown.isEmpty()) {
    ASSERT_TRUE(planShown.wait(kLoadTimeoutMs)) << "the plan in " << folder.toStdString() << " was not shown";
  }
}

void openModelFile(ui::MainWindow& window, const QString& path) {
  QSignalSpy shown(&window, &ui::MainWindow::modelShown);
  window.openFile(path);
  ASSERT_TRUE(shown.wait(kLoadTimeoutMs)) << "did not load " << path.toStdString();
}

QString writeTBar(const QTemporaryDir& dir, const QString& name) {
  const QString path = dir.filePath(name);
  const core::Status saved = core::saveMesh(makeTBar(10, 30, 80, 10, 10), path.toStdString());
  EXPECT_TRUE(saved.ok()) << saved.error().describe();
  return path;
}

void waitProjectOpened(ui::ProjectSession* session, const std::function<bool()>& start) {
  QSignalSpy opened(session, &ui::ProjectSession::projectOpened);
  QSignalSpy failed(session, &ui::ProjectSession::projectOpenFailed);
  ASSERT_TRUE(start());
  ASSERT_TRUE(opened.wait(kSearchTimeoutMs))
      << (failed.isEmpty() ? std::string("no answer") : failed.front().front().toString().toStdString());
}

void dropFile(ui::MainWindow& window, const QString& path) {
  QMimeData data;
  data.setUrls({QUrl::fromLocalFile(path)});
  const QPoint centre = window.rect().center();
  QDragEnterEvent enter(centre, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(&window, &enter);
  EXPECT_TRUE(enter.isAccepted());
  QDropEvent drop(centre, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(&window, &drop);
}

bool waitUntil(const std::function<bool()>& done, int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  while (!done() && clock.elapsed() < timeoutMs) QTest::qWait(10);
  return done();
}

QMessageBox* waitForMessageBox(const QWidget& window, const QString& objectName, int timeoutMs) {
  QMessageBox* found = nullptr;
  waitUntil(
      [&] {
        found = window.findChild<QMessageBox*>(objectName);
        return found != nullptr && found->isVisible();
      },
      timeoutMs);
  return found != nullptr && found->isVisible() ? found : nullptr;
}

QStringList answerFileDialog(const std::function<void()>& trigger, const std::function<void(QFileDialog&)>& answer,
                             bool* answered, int timeoutMs) {
  QStringList messages;
  bool done = false;
  QElapsedTimer clock;
  clock.start();
  QTimer timer;
  timer.setInterval(20);
  QObject::connect(&timer, &QTimer::timeout, [&] {
    QWidget* modal = QApplication::activeModalWidget();
    if (!modal) return;
    if (auto* box = qobject_cast<QMessageBox*>(modal)) {
      messages << box->text();
      box->done(QMessageBox::Cancel);
    } else if (auto* dialog = qobject_cast<QFileDialog*>(modal); dialog && !done) {
      done = true;
      answer(*dialog);
    } else if (auto* other = qobject_cast<QDialog*>(modal); other && (done || clock.elapsed() > timeoutMs)) {
      other->reject();  // a file dialog that refused the answer, or anything left at the end
    }
  });
  timer.start();
  trigger();
  timer.stop();
  if (answered) *answered = done;
  return messages;
}

void waitForRegrownSupports(ui::MainWindow& window) {
  if (!window.isGrowingSupports()) return;
  QSignalSpy regrown(&window, &ui::MainWindow::supportsRegrown);
  ASSERT_TRUE(regrown.wait(kSearchTimeoutMs)) << "the plan's supports were not regrown";
}

}  // namespace multidir::test
