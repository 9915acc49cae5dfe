#include "ui/studio_startup.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QPixmap>
#include <QSurfaceFormat>
#include <QTimer>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/samples/samples.h"
#include "ui/main_window.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("multidir::ui::StudioStartup", text); }

// Runs the event loop until `done()` holds or `timeoutMs` has passed; returns done().
template <typename Predicate>
bool processEventsUntil(Predicate done, int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  while (!done() && clock.elapsed() < timeoutMs) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  }
  return done();
}

}  // namespace

void setDefaultSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  // VTK renders into its own framebuffer and blits it into the widget's, so Qt's needs no multisampling.
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
}

QString studioVersion() { return QStringLiteral(MULTIDIR_VERSION); }

StudioCommandLine parseStudioCommandLine(const QStringList& arguments) {
  StudioCommandLine result;
  QCommandLineParser parser;
  parser.setApplicationDescription(tr("MultiDir Studio: plans multi-directional 3D prints."));
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  const QCommandLineOption up(QStringLiteral("up"),
                              tr("Printing (up) direction of the model: x, -y, +z or a,b,c. Default: +z."),
                              tr("direction"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      tr("Render the window to this PNG file and quit."), tr("file"));
  parser.addOption(up);
  parser.addOption(screenshot);
  parser.addPositionalArgument(QStringLiteral("model"),
                               tr("Mesh file to open (.stl .obj .off .ply). Default: the first sample."),
                               tr("[model]"));

  auto fail = [&result](const QString& message) {
    result.exitNow = true;
    result.exitCode = 2;
    result.text = message + QLatin1Char('\n') + tr("Try --help for usage.");
    return result;
  };
  if (!parser.parse(arguments)) return fail(parser.errorText());
  if (parser.isSet(help)) {
    result.exitNow = true;
    result.text = parser.helpText();
    return result;
  }
  if (parser.isSet(version)) {
    result.exitNow = true;
    result.text = QCoreApplication::applicationName() + QLatin1Char(' ') + QCoreApplication::applicationVersion();
    return result;
  }
  const QStringList positional = parser.positionalArguments();
  if (positional.size() > 1) return fail(tr("Give at most one model; got %1.").arg(positional.size()));
  if (!positional.isEmpty()) result.options.modelPath = positional.front();
  if (parser.isSet(up)) {
    const core::Result<core::Vec3> direction = core::parseDirection(parser.value(up).toStdString());
    if (!direction) return fail(tr("--up: %1").arg(QString::fromStdString(direction.error().describe())));
    result.options.up = direction.value();
  }
  if (parser.isSet(screenshot)) {
    result.options.screenshotPath = parser.value(screenshot);
    if (result.options.screenshotPath.isEmpty()) return fail(tr("--screenshot needs a file name."));
  }
  return result;
}

void startStudio(MainWindow& window, const StudioOptions& options) {
  if (options.up) window.setUpDirection(*options.up);
  if (!options.modelPath.isEmpty()) {
    window.openFile(options.modelPath);
    return;
  }
  const std::vector<core::samples::SampleInfo>& samples = core::samples::catalogue();
  if (!samples.empty()) window.openSample(QString::fromStdString(samples.front().id));
}

int saveScreenshotWhenReady(MainWindow& window, const QString& path, QString* error, int timeoutMs) {
  auto setError = [error](const QString& message) {
    if (error) *error = message;
  };
  if (!processEventsUntil([&window] { return !window.isLoading(); }, timeoutMs)) {
    setError(tr("The model did not finish loading within %1 s.").arg(timeoutMs / 1000));
    return 1;
  }
  // Layout, then at least one rendered frame, before the picture is taken.
  MeshViewerWidget* viewer = window.viewer();
  const std::size_t before = viewer->framesRendered();
  viewer->update();
  processEventsUntil([viewer, before] { return viewer->framesRendered() > before; }, 10000);
  const QPixmap picture = window.grab();
  if (picture.isNull() || !picture.save(path)) {
    setError(tr("Could not write the screenshot to %1.").arg(path));
    return 1;
  }
  if (!window.hasModel()) {
    setError(tr("No model is shown; the screenshot %1 shows the empty window.").arg(path));
    return 1;
  }
  return 0;
}

}  // namespace multidir::ui
