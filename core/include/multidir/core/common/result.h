#pragma once
// Errors as values: core's public functions return Result<T>, a value or an Error that says what went
// wrong, where, and what the user can do about it. Exceptions never cross core's public API.
#include <string>
#include <utility>
#include <variant>

namespace multidir::core {

enum class ErrorCode {
  FileNotFound,      // the path does not exist or cannot be opened
  UnsupportedFormat, // the extension is not one of .stl .obj .off .ply
  MalformedFile,     // the file's content does not follow its format (truncated, lying counts, bad numbers)
  TooLarge,          // a count or size in the file is beyond what MultiDir accepts, or a part beyond a printer's volume
  WriteFailed,       // the file could not be written
  EmptyMesh,         // no vertices or no faces, or a closed shell that encloses no volume (flat)
  NonFiniteVertex,   // a coordinate is NaN or infinite
  NotManifold,       // an edge with other than two faces, or a vertex whose faces do not form one fan
  OpenBoundary,      // the surface has holes: it does not enclose a solid
  InconsistentOrientation, // neighbouring faces disagree on orientation and it could not be repaired
  InvalidParameter,  // a parameter is out of its documented range
  Cancelled,         // the caller cancelled the job
  DeviceUnreachable, // a printer device did not answer, or its link is down or reconnecting
  DeviceFault,       // a printer device answered with an error (a Modbus exception) or reports a fault
  Internal,          // a bug in MultiDir: please report it with the input that caused it
  ExternalToolFailed, // a program MultiDir runs (the slicer) is missing, failed or wrote nothing usable
  CheckFailed,       // a produced file (G-code) failed MultiDir's checks; the message names where and why
};

// Short, stable, English name of a code ("NotManifold"), for logs and JSON.
const char* errorCodeName(ErrorCode code);

struct Error {
  ErrorCode code;
  std::string message;  // what is wrong and what to do, for a person
  std::string where;    // the file, face or parameter concerned ("kitten.off", "face 12", "--alpha")

  // "where: message", the form printed by the command line and shown by the GUI.
  std::string describe() const { return where.empty() ? message : where + ": " + message; }
};

template <typename T>
class Result {
 public:
  Result(T value) : m_state(std::move(value)) {}      // NOLINT: implicit by design
  Result(Error error) : m_state(std::move(error)) {}  // NOLINT: implicit by design

  bool ok() const { return std::holds_alternative<T>(m_state); }
  explicit operator bool() const { return ok(); }

  const T& value() const& { return std::get<T>(m_state); }
  T& value() & { return std::get<T>(m_state); }
  T&& value() && { return std::get<T>(std::move(m_state)); }
  const Error& error() const { return std::get<Error>(m_state); }

  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }

 private:
  std::variant<T, Error> m_state;
};

// For functions that return nothing but may fail.
struct Done {};
using Status = Result<Done>;

}  // namespace multidir::core
