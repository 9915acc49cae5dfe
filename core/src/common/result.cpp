#include "multidir/core/common/result.h"

namespace multidir::core {

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::FileNotFound: return "FileNotFound";
    case ErrorCode::UnsupportedFormat: return "UnsupportedFormat";
    case ErrorCode::MalformedFile: return "MalformedFile";
    case ErrorCode::TooLarge: return "TooLarge";
    case ErrorCode::WriteFailed: return "WriteFailed";
    case ErrorCode::EmptyMesh: return "EmptyMesh";
    case ErrorCode::NonFiniteVertex: return "NonFiniteVertex";
    case ErrorCode::NotManifold: return "NotManifold";
    case ErrorCode::OpenBoundary: return "OpenBoundary";
    case ErrorCode::InconsistentOrientation: return "InconsistentOrientation";
    case ErrorCode::InvalidParameter: return "InvalidParameter";
    case ErrorCode::Cancelled: return "Cancelled";
    case ErrorCode::DeviceUnreachable: return "DeviceUnreachable";
    case ErrorCode::DeviceFault: return "DeviceFault";
    case ErrorCode::Internal: return "Internal";
    case ErrorCode::ExternalToolFailed: return "ExternalToolFailed";
    case ErrorCode::CheckFailed: return "CheckFailed";
  }
  return "Unknown";
}

}  // namespace multidir::core
