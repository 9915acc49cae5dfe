#include "ui/common/picture_file.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QImageWriter>

namespace multidir::ui {
namespace {

// The translation context of the free functions here (lupdate reads it from the macro).
struct PictureFileText {
  Q_DECLARE_TR_FUNCTIONS(multidir::ui::PictureFile)
};

// "PNG" or "JPEG" for a name savePicture accepts, else empty.
QByteArray formatFor(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == QLatin1String("png")) return QByteArrayLiteral("PNG");
  if (suffix == QLatin1String("jpg") || suffix == QLatin1String("jpeg")) return QByteArrayLiteral("JPEG");
  return {};
}

}  // namespace

bool isPictureFileName(const QString& path) { return !formatFor(path).isEmpty(); }

bool savePicture(const QImage& picture, const QString& path, QString* error) {
  auto fail = [error](const QString& message) {
    if (error) *error = message;
    return false;
  };
  if (picture.isNull()) return fail(PictureFileText::tr("Could not save %1: there is no picture to save.").arg(path));
  const QByteArray format = formatFor(path);
  if (format.isEmpty()) {
    return fail(PictureFileText::tr("Could not save %1: give the file name the extension .png or .jpg.").arg(path));
  }
  QImageWriter writer(path, format);
  // JPEG has no alpha channel: a transparent pixel would come out black.
  const QImage image = format == "JPEG" ? picture.convertToFormat(QImage::Format_RGB32) : picture;
  if (!writer.write(image)) {
    if (writer.error() == QImageWriter::DeviceError) {
      return fail(PictureFileText::tr("Could not save %1: the file cannot be written there; check that its folder "
                                      "exists and may be written to.").arg(path));
    }
    return fail(PictureFileText::tr("Could not save %1: %2").arg(path, writer.errorString()));
  }
  return true;
}

}  // namespace multidir::ui
