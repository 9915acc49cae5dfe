#include "ui/studio_startup.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QLocale>
#include <QPixmap>
#include <cmath>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTimer>
#include <QTranslator>
#include <memory>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/samples/samples.h"
#include "ui/main_window.h"
#include "ui/common/picture_file.h"
#include "ui/panels/overhang_panel.h"
#include "ui/project/project_session.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::ui {
namespace {

// The translation context of the free functions here (lupdate reads it from the macro).
struct StudioStartupText {
  Q_DECLARE_TR_FUNCTIONS(multidir::ui::StudioStartup)
};

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

StudioCommandLine parseStudioCommandLine(const QStringList& arguments) {
  StudioCommandLine result;
  QCommandLineParser parser;
  parser.setApplicationDescription(StudioStartupText::tr("MultiDir Studio: plans multi-directional 3D prints."));
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  const QCommandLineOption up(QStringLiteral("up"),
                              StudioStartupText::tr("Printing (up) direction of the model: x, -y, +z or a,b,c. Default: +z."),
                              StudioStartupText::tr("direction"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      StudioStartupText::tr("Render the window to this PNG file and quit."), StudioStartupText::tr("file"));
  const QCommandLineOption lang(QStringLiteral("lang"), StudioStartupText::tr("Language of the user interface: de, zh_CN or en."),
                                StudioStartupText::tr("language"));
  const QCommandLineOption search(QStringLiteral("search"),
                                  StudioStartupText::tr("Run a search with the default settings once the model is shown."));
  const QCommandLineOption alpha(QStringLiteral("alpha"), StudioStartupText::tr("Maximal overhang angle in degrees (0-89)."),
                                 StudioStartupText::tr("degrees"));
  parser.addOption(up);
  parser.addOption(screenshot);
  parser.addOption(lang);
  parser.addOption(search);
  parser.addOption(alpha);
  parser.addPositionalArgument(QStringLiteral("model"),
                               StudioStartupText::tr("Mesh file (.stl .obj .off .ply) or MultiDir project (.multidir) to open. Default: the first sample."),
                               StudioStartupText::tr("[model]"));

  auto fail = [&result](const QString& message) {
    result.exitNow = true;
    result.exitCode = 2;
    result.text = message + QLatin1Char('\n') + StudioStartupText::tr("Try --help for usage.");
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
  if (positional.size() > 1) return fail(StudioStartupText::tr("Give at most one model; got %1.").arg(positional.size()));
  if (!positional.isEmpty()) result.options.modelPath = positional.front();
  if (parser.isSet(up)) {
    const core::Result<core::Vec3> direction = core::parseDirection(parser.value(up).toStdString());
    if (!direction) return fail(StudioStartupText::tr("--up: %1").arg(QString::fromStdString(direction.error().describe())));
    result.options.up = direction.value();
  }
  if (parser.isSet(lang)) {
    const QString value = parser.value(lang);
    if (value != QLatin1String("en") && !studioLanguages().contains(value))
      return fail(StudioStartupText::tr("--lang: '%1' is not available; use de, zh_CN or en.").arg(value));
    result.options.language = value;
  }
  result.options.runSearch = parser.isSet(search);
  if (parser.isSet(alpha)) {
    bool ok = false;
    const double degrees = parser.value(alpha).toDouble(&ok);
    if (!ok || degrees < 0.0 || degrees > 89.0) return fail(StudioStartupText::tr("--alpha must be a number from 0 to 89."));
    result.options.alphaMaxDegrees = degrees;
  }
  if (parser.isSet(screenshot)) {
    result.options.screenshotPath = parser.value(screenshot);
    if (result.options.screenshotPath.isEmpty()) return fail(StudioStartupText::tr("--screenshot needs a file name."));
  }
  return result;
}

QStringList studioLanguages() { return {QStringLiteral("de"), QStringLiteral("zh_CN")}; }

QString chooseLanguage(const QString& requested) {
  const QStringList available = studioLanguages();
  auto known = [&available](const QString& language) {
    return language == QLatin1String("en") || available.contains(language);
  };
  if (known(requested)) return requested;
  const QString saved = QSettings().value(QStringLiteral("language")).toString();
  if (known(saved)) return saved;
  const QString system = QLocale::system().name();  // "de_DE", "zh_CN", "en_US"
  if (system.startsWith(QLatin1String("de"))) return QStringLiteral("de");
  if (system.startsWith(QLatin1String("zh"))) return QStringLiteral("zh_CN");
  return QStringLiteral("en");
}

bool installTranslations(const QString& language) {
  // The translators live as long as the application; a second call replaces the first's.
  static std::unique_ptr<QTranslator> studio;
  static std::unique_ptr<QTranslator> qtBase;
  // Numbers follow the language chosen ("1.507,2" in German); English keeps the locale the studio started with.
  static const QLocale startLocale;
  for (auto* translator : {&studio, &qtBase}) {
    if (*translator) QCoreApplication::removeTranslator(translator->get());
    translator->reset();
  }
  if (language == QLatin1String("en")) {
    QLocale::setDefault(startLocale);
    return true;
  }
  if (!studioLanguages().contains(language)) return false;
  auto own = std::make_unique<QTranslator>();
  if (!own->load(QStringLiteral(":/i18n/multidir_%1.qm").arg(language))) return false;
  QCoreApplication::installTranslator(own.get());
  studio = std::move(own);
  QLocale::setDefault(QLocale(language));
  // Qt's own texts (standard buttons, file dialogs, context menus): embedded when the build had them, else
  // the system's.
  auto qt = std::make_unique<QTranslator>();
  if (qt->load(QStringLiteral(":/i18n/qtbase_%1.qm").arg(language)) ||
      qt->load(QLocale(language), QStringLiteral("qtbase"), QStringLiteral("_"),
               QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
    QCoreApplication::installTranslator(qt.get());
    qtBase = std::move(qt);
  }
  return true;
}

void startStudio(MainWindow& window, const StudioOptions& options) {
  // Interactive runs offer what a crashed studio autosaved (a non-modal question; --screenshot never asks).
  if (options.screenshotPath.isEmpty()) window.projectSession()->offerRecovery();
  if (options.up) window.setUpDirection(*options.up);
  if (options.alphaMaxDegrees >= 0.0) {
    window.overhangPanel()->setAlphaMaxDegrees(options.alphaMaxDegrees);
  }
  if (options.runSearch) {
    // Once, for the first model shown.
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection = QObject::connect(&window, &MainWindow::modelShown, &window, [&window, connection] {
      QObject::disconnect(*connection);
      window.runSearch();
    });
  }
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
    setError(StudioStartupText::tr("The model did not finish loading within %1 s.").arg(timeoutMs / 1000));
    return 1;
  }
  // A search started with the model (--search) is waited for too: the picture shows its plan.
  QCoreApplication::processEvents();
  // So is a project's plan being rebuilt from its planes.
  if (!processEventsUntil([&window] { return !window.isSearching() && !window.projectSession()->isOpening(); },
                          timeoutMs)) {
    setError(StudioStartupText::tr("The search or the project's plan did not finish within %1 s.").arg(timeoutMs / 1000));
    return 1;
  }
  // Layout, then at least one rendered frame, before the picture is taken.
  MeshViewerWidget* viewer = window.viewer();
  const std::size_t before = viewer->framesRendered();
  viewer->update();
  processEventsUntil([viewer, before] { return viewer->framesRendered() > before; }, 10000);
  QString problem;
  if (!savePicture(window.grab().toImage(), path, &problem)) {
    setError(problem);
    return 1;
  }
  if (!window.hasModel()) {
    setError(StudioStartupText::tr("No model is shown; the screenshot %1 shows the empty window.").arg(path));
    return 1;
  }
  return 0;
}

}  // namespace multidir::ui
