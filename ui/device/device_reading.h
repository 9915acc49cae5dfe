#pragma once
// How the Hardware dock shows what a device last reported, the same for the platform or arm and the printer:
// a value is only shown as the device's state while it is fresh. Without a link a field shows "—"; before the
// first read "unknown: not read yet" (a driver's defaults are not the device's state); once the link is lost
// "unknown since HH:mm:ss (last read: value)", greyed.
#include <QCoreApplication>
#include <QDateTime>
#include <QString>
#include <optional>

class QLabel;

namespace multidir::ui {

class DeviceReading {
  Q_DECLARE_TR_FUNCTIONS(DeviceReading)

 public:
  static constexpr const char* kStaleStyle = "color: #8a8a8a;";  // a value that is not the device's state now
  static constexpr const char* kFaultStyle = "color: #c62828;";  // a fault or an error the device reported

  // The clock time of a reading, as every device field shows it.
  static QString clockTime(const QDateTime& time);

  // Shows `value` in `label` as described above.
  static void show(QLabel* label, const QString& value, bool linkOpen, bool hasRead,
                   const std::optional<QDateTime>& staleSince);
};

}  // namespace multidir::ui
