#pragma once
// Writing pictures of the studio to files: the --screenshot option (the whole window) and File > Export
// Screenshot (the 3D view) both go through savePicture, so they accept the same names and fail the same way.
#include <QImage>
#include <QString>

namespace multidir::ui {

// The picture formats savePicture writes, by file name extension (lower case): "png", "jpg", "jpeg".
[[nodiscard]] bool isPictureFileName(const QString& path);

// Saves `picture` to `path` as PNG or JPEG, chosen by the extension (.png, .jpg or .jpeg, any case). Returns
// false, with a translated sentence naming the file and the problem in `error`, for a null picture, another
// extension, or a file that cannot be written (a missing folder, no permission).
bool savePicture(const QImage& picture, const QString& path, QString* error = nullptr);

}  // namespace multidir::ui
