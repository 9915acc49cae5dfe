#include "ui/device/device_reading.h"

#include <QLabel>

namespace multidir::ui {

QString DeviceReading::clockTime(const QDateTime& time) { return time.toString(QStringLiteral("HH:mm:ss")); }

void DeviceReading::show(QLabel* label, const QString& value, bool linkOpen, bool hasRead,
                         const std::optional<QDateTime>& staleSince) {
  if (!linkOpen) {
    label->setText(QStringLiteral("—"));
    label->setStyleSheet(QString());
  } else if (!hasRead) {
    label->setText(tr("unknown: not read yet"));
    label->setStyleSheet(QString::fromLatin1(kStaleStyle));
  } else if (staleSince) {
    label->setText(tr("unknown since %1 (last read: %2)").arg(clockTime(*staleSince), value));
    label->setStyleSheet(QString::fromLatin1(kStaleStyle));
  } else {
    label->setText(value);
    label->setStyleSheet(QString());
  }
}

}  // namespace multidir::ui
