#pragma once
// Keeps a log view on its newest line as lines arrive, unless the reader scrolled up to read an older one;
// scrolling back to the bottom follows again. Works while the view is hidden too (a dock tabbed away): it
// opens on the newest line.
#include <QObject>

class QPlainTextEdit;

namespace multidir::ui {

class FollowNewestLine : public QObject {
  Q_OBJECT

 public:
  // Follows `log` (owned by it).
  explicit FollowNewestLine(QPlainTextEdit* log);
  [[nodiscard]] bool isFollowing() const { return m_following; }

 private:
  bool m_following = true;
};

}  // namespace multidir::ui
