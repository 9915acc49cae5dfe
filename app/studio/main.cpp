// multidir-studio: the desktop application. Everything but process set-up lives in multidir_ui.
#include <QApplication>
#include <QTextStream>
#include <cstdio>
#include <exception>

#include "ui/main_window.h"
#include "ui/studio_startup.h"

namespace {

int run(int argc, char** argv) {
  QApplication::setApplicationName(QStringLiteral("MultiDir Studio"));
  QApplication::setOrganizationName(QStringLiteral("MultiDir"));
  QApplication::setApplicationVersion(multidir::ui::studioVersion());

  multidir::ui::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  // Parsed after QApplication, which takes its own options (-platform, -style, ...) out first.
  const multidir::ui::StudioCommandLine commandLine = multidir::ui::parseStudioCommandLine(QApplication::arguments());
  // Before any window exists: widgets translate their texts when they are built.
  multidir::ui::installTranslations(multidir::ui::chooseLanguage(commandLine.options.language));
  if (commandLine.exitNow) {
    QTextStream(commandLine.exitCode == 0 ? stdout : stderr) << commandLine.text << '\n';
    return commandLine.exitCode;
  }

  multidir::ui::MainWindow window;
  window.show();
  multidir::ui::startStudio(window, commandLine.options);
  if (!commandLine.options.screenshotPath.isEmpty()) {
    QString error;
    const int code = multidir::ui::saveScreenshotWhenReady(window, commandLine.options.screenshotPath, &error);
    if (code != 0) QTextStream(stderr) << error << '\n';
    return code;
  }
  return QApplication::exec();
}

}  // namespace

int main(int argc, char** argv) {
  // Nothing escapes main: an unexpected failure becomes a message and exit code 3.
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "multidir-studio: unexpected error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "multidir-studio: unexpected error\n");
  }
  return 3;
}
