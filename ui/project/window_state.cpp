#include "ui/project/window_state.h"

#include <QMainWindow>
#include <QSettings>

namespace multidir::ui {
namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");

}  // namespace

void saveWindowState(const QMainWindow& window) {
  QSettings settings;
  settings.setValue(kGeometryKey, window.saveGeometry());
  settings.setValue(kStateKey, window.saveState());
}

QSize initialWindowSize(const QSize& available) {
  // What a window manager usually adds: a title bar of up to ~40 px and borders of a few px each side.
  constexpr int kFrameWidth = 16;
  constexpr int kFrameHeight = 48;
  return kPreferredWindowSize.boundedTo(QSize(available.width() - kFrameWidth, available.height() - kFrameHeight))
      .expandedTo(QSize(1, 1));
}

bool restoreWindowState(QMainWindow& window) {
  const QSettings settings;
  const QByteArray geometry = settings.value(kGeometryKey).toByteArray();
  const QByteArray state = settings.value(kStateKey).toByteArray();
  if (geometry.isEmpty() && state.isEmpty()) return false;
  bool restored = true;
  if (!geometry.isEmpty()) restored = window.restoreGeometry(geometry) && restored;
  if (!state.isEmpty()) restored = window.restoreState(state) && restored;
  return restored;
}

}  // namespace multidir::ui
