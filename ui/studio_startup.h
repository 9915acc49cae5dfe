#pragma once
// How multidir-studio starts: its command line, what it opens first, and the --screenshot mode that
// renders the window to a PNG and quits (for the docs and smoke tests). Kept out of main() so tests can
// drive it.
#include <QString>
#include <QStringList>
#include <optional>

#include "multidir/core/mesh/triangle_mesh.h"
#include "ui/common/studio_version.h"

namespace multidir::ui {

class MainWindow;

// Makes OpenGL 3.2 core (depth 24, stencil 8) the default surface format, as VTK's OpenGL2 backend needs.
// Call before the QApplication is created.
void setDefaultSurfaceFormat();

struct StudioOptions {
  QString modelPath;              // empty: open the first sample
  std::optional<core::Vec3> up;   // --up; unset: +Z
  QString screenshotPath;         // --screenshot; non-empty: save the window there and quit
  QString language;               // --lang: "de", "zh_CN" or "en"; empty: the saved setting or the system's
  bool runSearch = false;         // --search: run a search with the panel's settings once the model is shown
  double alphaMaxDegrees = -1.0;  // --alpha: the Overhangs panel's alpha_max (degrees); < 0: leave it
};

// What the command line asks for: options to run with, or a text to print and an exit code.
struct StudioCommandLine {
  StudioOptions options;
  bool exitNow = false;  // --help, --version, or an error
  int exitCode = 0;      // 0 after --help/--version, 2 for a usage error
  QString text;          // what to print (to stdout when exitCode == 0, else to stderr)
};

// Reads `arguments` (arguments[0] is the program): [model] [--up DIR] [--screenshot FILE.png]
// [--lang de|zh_CN|en] [--search] [--alpha DEGREES]. DIR is what core::parseDirection accepts: x, -y, +z or
// a,b,c.
StudioCommandLine parseStudioCommandLine(const QStringList& arguments);

// The languages the studio is translated into, besides English: "de", "zh_CN".
QStringList studioLanguages();

// Which language to show: `requested` when it is one of "en" and studioLanguages(), else the QSettings value
// "language" when it is, else the system locale's ("de_AT" -> "de", "zh_CN"/"zh" -> "zh_CN"), else "en".
QString chooseLanguage(const QString& requested);

// Installs the translations (embedded .qm files: the studio's and Qt's own, qtbase) for `language` into the
// application, replacing ones installed earlier, and makes the language's locale the default for numbers;
// "en" installs none and restores the locale the studio started with. Returns false when `language` has no translation. Call before
// creating windows: texts are translated when widgets are built.
bool installTranslations(const QString& language);

// Sets the up direction and starts loading the model (or the first sample; a .multidir opens as a project)
// in `window`; with runSearch, the search starts once the model is shown. Without --screenshot, an autosave
// left by a crash is offered for recovery (ProjectSession::offerRecovery).
void startStudio(MainWindow& window, const StudioOptions& options);

// Waits until `window` has finished loading (at most `timeoutMs`), lets it render, and saves a picture
// of the whole window to `path`. Returns 0 when a model is shown and the file was written, 1 otherwise,
// with the reason in `error`.
int saveScreenshotWhenReady(MainWindow& window, const QString& path, QString* error, int timeoutMs = 120000);

}  // namespace multidir::ui
