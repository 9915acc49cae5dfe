#include "ui/error_text.h"

#include <QCoreApplication>

namespace multidir::ui {

QString errorHeadline(core::ErrorCode code) {
  const char* context = "multidir::ui::ErrorText";
  switch (code) {
    case core::ErrorCode::FileNotFound:
      return QCoreApplication::translate(context, "The file does not exist or cannot be read.");
    case core::ErrorCode::UnsupportedFormat:
      return QCoreApplication::translate(context, "This file type is not supported: use STL, OBJ, OFF or PLY.");
    case core::ErrorCode::MalformedFile:
      return QCoreApplication::translate(context, "The file is damaged or does not follow its format.");
    case core::ErrorCode::TooLarge:
      return QCoreApplication::translate(context, "The model is larger than MultiDir accepts.");
    case core::ErrorCode::WriteFailed:
      return QCoreApplication::translate(context, "The file could not be written.");
    case core::ErrorCode::EmptyMesh:
      return QCoreApplication::translate(context, "The file contains no triangles.");
    case core::ErrorCode::NonFiniteVertex:
      return QCoreApplication::translate(context, "Some vertex coordinates are not numbers.");
    case core::ErrorCode::NotManifold:
      return QCoreApplication::translate(
          context, "The surface is not a clean solid: some edges or vertices are shared by too many faces.");
    case core::ErrorCode::OpenBoundary:
      return QCoreApplication::translate(
          context, "The surface has holes, so it does not enclose a solid. Close them in a mesh repair tool.");
    case core::ErrorCode::InconsistentOrientation:
      return QCoreApplication::translate(context, "The faces of the surface point in inconsistent directions.");
    case core::ErrorCode::InvalidParameter:
      return QCoreApplication::translate(context, "A setting is out of its allowed range.");
    case core::ErrorCode::Cancelled:
      return QCoreApplication::translate(context, "Cancelled.");
    case core::ErrorCode::Internal:
      break;
  }
  return QCoreApplication::translate(context, "An internal error occurred: please report it with the model.");
}

}  // namespace multidir::ui
