#include "ui/common/error_text.h"

#include <QCoreApplication>

namespace multidir::ui {
namespace {

// The translation context of the texts here (lupdate reads it from the macro).
struct ErrorText {
  Q_DECLARE_TR_FUNCTIONS(multidir::ui::ErrorText)
};

}  // namespace

QString errorHeadline(core::ErrorCode code) {
  switch (code) {
    case core::ErrorCode::FileNotFound:
      return ErrorText::tr("The file does not exist or cannot be read.");
    case core::ErrorCode::UnsupportedFormat:
      return ErrorText::tr("This file type is not supported: use STL, OBJ, OFF or PLY.");
    case core::ErrorCode::MalformedFile:
      return ErrorText::tr("The file is damaged or does not follow its format.");
    case core::ErrorCode::TooLarge:
      return ErrorText::tr("The model is larger than MultiDir accepts.");
    case core::ErrorCode::WriteFailed:
      return ErrorText::tr("The file could not be written.");
    case core::ErrorCode::EmptyMesh:
      return ErrorText::tr("The file contains no triangles.");
    case core::ErrorCode::NonFiniteVertex:
      return ErrorText::tr("Some vertex coordinates are not numbers.");
    case core::ErrorCode::NotManifold:
      return ErrorText::tr(
          "The surface is not a clean solid: some edges or vertices are shared by too many faces.");
    case core::ErrorCode::OpenBoundary:
      return ErrorText::tr(
          "The surface has holes, so it does not enclose a solid. Close them in a mesh repair tool.");
    case core::ErrorCode::InconsistentOrientation:
      return ErrorText::tr("The faces of the surface point in inconsistent directions.");
    case core::ErrorCode::InvalidParameter:
      return ErrorText::tr("A setting is out of its allowed range.");
    case core::ErrorCode::Cancelled:
      return ErrorText::tr("Cancelled.");
    case core::ErrorCode::DeviceUnreachable:
      return ErrorText::tr("The device does not answer: check its power, cable or network.");
    case core::ErrorCode::DeviceFault:
      return ErrorText::tr("The device reported an error.");
    case core::ErrorCode::ExternalToolFailed:
      return ErrorText::tr("A program MultiDir runs (the slicer) is missing or failed.");
    case core::ErrorCode::CheckFailed:
      return ErrorText::tr("The produced G-code failed MultiDir's safety checks.");
    case core::ErrorCode::Internal:
      break;
  }
  return ErrorText::tr("An internal error occurred: please report it with the model.");
}

}  // namespace multidir::ui
