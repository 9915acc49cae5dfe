#pragma once
// What the studio tests share: a window showing a sample, a search small enough for a test, and a plan
// folder opened again, each waiting for the signal that says it is done. The helpers report failures
// through GoogleTest; a fatal one ends only the helper, so callers that cannot go on without it wrap it in
// ASSERT_NO_FATAL_FAILURE or check what it returns.
#include <QSize>
#include <QString>

#include "multidir/core/search/decomposition.h"
#include "ui/jobs/search_job.h"

namespace multidir::ui {
class MainWindow;
}

namespace multidir::test {

// How long a test waits for a model to load or a search to finish before it gives up: guards against a
// hang, not limits the tests check (Xvfb draws in software, and ctest runs tests side by side).
constexpr int kLoadTimeoutMs = 120000;
constexpr int kSearchTimeoutMs = 240000;

// Resizes and shows `window`, starts the studio as without arguments and waits until the default sample
// (the snowman) is shown.
void showDefaultSample(ui::MainWindow& window, const QSize& size = QSize(1400, 900));

// Opens the built-in sample `id` and waits until it is shown.
void openSample(ui::MainWindow& window, const QString& id);

// Settings small enough for a search of a second or two. On the snowman they give three clipping planes,
// each as low as Criterion III allows, and leave risky area under its bottom (J_G > 0), so the plan needs
// supports.
core::SearchOptions quickSearchOptions();

// Runs a search with quickSearchOptions() from the window's Search panel and waits for its plan; an empty
// run (no plan) when it did not start or finish.
ui::SearchRun runQuickSearch(ui::MainWindow& window);

// Opens the plan folder `folder` in `window` and waits until the plan is shown.
void openPlanFolder(ui::MainWindow& window, const QString& folder);

}  // namespace multidir::test
