#pragma once
// What the studio tests share: a window showing a sample, a search small enough for a test, and a plan
// folder opened again, each waiting for the signal that says it is done. The helpers report failures
// through GoogleTest; a fatal one ends only the helper, so callers that cannot go on without it wrap it in
// ASSERT_NO_FATAL_FAILURE or check what it returns.
#include <QSize>
#include <QString>
#include <functional>

#include "multidir/core/search/decomposition.h"
#include "ui/jobs/search_job.h"

namespace multidir::ui {
class MainWindow;
class SearchPanel;
class ProjectSession;
}

class QFileDialog;
class QMessageBox;
class QTemporaryDir;
class QWidget;

namespace multidir::test {

// How long a test waits for a model to load or a search to finish before it gives up: guards against a
// hang, not limits the tests check (Xvfb draws in software, and ctest runs tests side by side).
constexpr int kLoadTimeoutMs = 120000;
constexpr int kSearchTimeoutMs = 240000;

// Empties what outlives a test process: settings of recent files, the window layout, autosaves and the
// dialogs' folders, and autosave files no running studio owns.
void resetStudioSettings();

// Resizes and shows `window`, starts the studio as without arguments and waits until the default sample
// (the snowman) is shown.
void showDefaultSample(ui::MainWindow& window, const QSize& size = QSize(1400, 900));

// Opens the built-in sample `id` and waits until it is shown.
void openSample(ui::MainWindow& window, const QString& id);

// Settings small enough for a search of a second or two. On the snowman they give three clipping planes,
// each as low as Criterion III allows, and leave risky area under its bottom (J_G > 0), so the plan needs
// supports.
core::SearchOptions quickSearchOptions();

// Settings for a search that runs for many seconds (thousands of normals, a wide beam): one to interrupt. It
// stops within a moment when cancelled.
core::SearchOptions longSearchOptions();

// Runs a search with quickSearchOptions() from the window's Search panel and waits for its plan; an empty
// run (no plan) when it did not start or finish.
ui::SearchRun runQuickSearch(ui::MainWindow& window);

// Runs a search with the options the window's Search panel shows, as Run search does, and waits for its plan;
// an empty run when it did not start or finish.
ui::SearchRun runSearchAsSet(ui::MainWindow& window);

// Whether `field` of `panel` is locked while the panel shows a search running, and editable again once it
// finished (a plan of 100 mm^2 shown).
bool lockedWhilePanelSearches(ui::SearchPanel& panel, const QWidget& field);

// Opens the plan folder `folder` in `window` and waits until the plan is shown.
void openPlanFolder(ui::MainWindow& window, const QString& folder);

// Opens the mesh file `path` (the program's way, without asking) and waits until it is shown.
void openModelFile(ui::MainWindow& window, const QString& path);

// Writes the T-bar (a stem with two overhanging wings, +Z up) as a mesh file `name` in `dir`; its path.
QString writeTBar(const QTemporaryDir& dir, const QString& name);

// Opens a project (or an autosave) with `start` and waits until its plan is shown.
void waitProjectOpened(ui::ProjectSession* session, const std::function<bool()>& start);

// Drops the file `path` on `window` as a file manager would (drag enter, then drop).
void dropFile(ui::MainWindow& window, const QString& path);

// Runs the event loop until `done` holds, for at most `timeoutMs`; returns done().
bool waitUntil(const std::function<bool()>& done, int timeoutMs = 10000);

// The visible message box named `objectName` among `window`'s children, waiting up to `timeoutMs` for it to
// appear (the studio's questions are asynchronous: nothing blocks until one is answered); null if none came.
QMessageBox* waitForMessageBox(const QWidget& window, const QString& objectName, int timeoutMs = 10000);

// Runs `trigger`, which opens a modal file dialog (as the File menu's actions do), and lets `answer` fill it
// in and accept or reject it. Message boxes shown meanwhile (by the dialog, or by the studio after it) are
// closed, and their texts returned. Nothing waits for ever: after `timeoutMs` every modal widget still open
// is closed. `answered` (if given) tells whether a file dialog came at all.
QStringList answerFileDialog(const std::function<void()>& trigger, const std::function<void(QFileDialog&)>& answer,
                             bool* answered = nullptr, int timeoutMs = 10000);

// Waits until supports grown for the plan shown (after it came without them) have been attached.
void waitForRegrownSupports(ui::MainWindow& window);

}  // namespace multidir::test
