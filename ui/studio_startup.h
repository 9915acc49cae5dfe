#pragma once
// How multidir-studio starts: its command line, what it opens first, and the --screenshot mode that
// renders the window to a PNG and quits (for the docs and smoke tests). Kept out of main() so tests can
// drive it.
#include <QString>
#include <QStringList>
#include <optional>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::ui {

class MainWindow;

// Makes OpenGL 3.2 core (depth 24, stencil 8) the default surface format, as VTK's OpenGL2 backend needs.
// Call before the QApplication is created.
void setDefaultSurfaceFormat();

// MultiDir's version ("0.1.0"), from the CMake project.
QString studioVersion();

struct StudioOptions {
  QString modelPath;              // empty: open the first sample
  std::optional<core::Vec3> up;   // --up; unset: +Z
  QString screenshotPath;         // --screenshot; non-empty: save the window there and quit
};

// What the command line asks for: options to run with, or a text to print and an exit code.
struct StudioCommandLine {
  StudioOptions options;
  bool exitNow = false;  // --help, --version, or an error
  int exitCode = 0;      // 0 after --help/--version, 2 for a usage error
  QString text;          // what to print (to stdout when exitCode == 0, else to stderr)
};

// Reads `arguments` (arguments[0] is the program): [model] [--up DIR] [--screenshot FILE.png].
// DIR is what core::parseDirection accepts: x, -y, +z or a,b,c.
StudioCommandLine parseStudioCommandLine(const QStringList& arguments);

// Sets the up direction and starts loading the model (or the first sample) in `window`.
void startStudio(MainWindow& window, const StudioOptions& options);

// Waits until `window` has finished loading (at most `timeoutMs`), lets it render, and saves a picture
// of the whole window to `path`. Returns 0 when a model is shown and the file was written, 1 otherwise,
// with the reason in `error`.
int saveScreenshotWhenReady(MainWindow& window, const QString& path, QString* error, int timeoutMs = 120000);

}  // namespace multidir::ui
