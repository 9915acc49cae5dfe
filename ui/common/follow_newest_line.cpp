#include "ui/common/follow_newest_line.h"

#include <QPlainTextEdit>
#include <QScrollBar>

namespace multidir::ui {

FollowNewestLine::FollowNewestLine(QPlainTextEdit* log) : QObject(log) {
  QScrollBar* bar = log->verticalScrollBar();
  // The reader's position: at the bottom means "follow". A new line grows the range without moving the value,
  // so it is not mistaken for the reader scrolling up.
  connect(bar, &QScrollBar::valueChanged, this, [this, bar](int value) { m_following = value >= bar->maximum(); });
  connect(bar, &QScrollBar::rangeChanged, this, [this, bar](int, int maximum) {
    if (m_following) bar->setValue(maximum);
  });
}

}  // namespace multidir::ui
