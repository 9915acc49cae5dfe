// loadMesh: find the format, read the file into a soup (each reader checks its structure and every number),
// then check and repair the soup.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <new>

#include "mesh/mesh_formats.h"
#include "multidir/core/mesh/mesh_io.h"

namespace multidir::core {
namespace {

namespace fs = std::filesystem;

constexpr double kMinScale = 1e-6;
constexpr double kMaxScale = 1e6;

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

Result<RawSoup> readSoup(const std::string& path, const std::string& ext, const std::string& name,
                         std::uintmax_t size, const LoadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::FileNotFound, "the file cannot be opened (check its permissions): " + path, name};
  if (ext == "stl") return detail::readStl(in, size, name, options);
  if (ext == "off") return detail::readOff(in, size, name, options);
  if (ext == "obj") return detail::readObj(in, name, options);
  return detail::readPly(in, size, name, options);
}

}  // namespace

Result<LoadedMesh> loadMesh(const std::string& path, const LoadOptions& options) {
  const fs::path filePath(path);
  const std::string name = filePath.filename().string().empty() ? path : filePath.filename().string();
  try {
    const std::string ext = lowerExtension(filePath);
    if (ext != "stl" && ext != "obj" && ext != "off" && ext != "ply")
      return Error{ErrorCode::UnsupportedFormat,
                   (ext.empty() ? std::string("the file name has no extension") : "'." + ext + "' files are not supported") +
                       "; MultiDir reads .stl, .obj, .off and .ply",
                   name};
    std::error_code ec;
    const fs::file_status status = fs::status(filePath, ec);
    if (ec || !fs::exists(status)) return Error{ErrorCode::FileNotFound, "no such file: " + path, name};
    if (fs::is_directory(status)) return Error{ErrorCode::FileNotFound, "this is a folder, not a file: " + path, name};
    const std::uintmax_t size = fs::file_size(filePath, ec);
    if (ec) return Error{ErrorCode::FileNotFound, "the file size cannot be read: " + path, name};
    if (size == 0) return Error{ErrorCode::MalformedFile, "the file is empty (0 bytes)", name};

    if (!(options.scale >= kMinScale && options.scale <= kMaxScale))
      return Error{ErrorCode::InvalidParameter,
                   "the scale must be a number from 0.000001 to 1000000 (0.001 turns micrometres into millimetres, "
                   "25.4 inches), not " + std::to_string(options.scale),
                   "scale"};
    Result<RawSoup> soup = readSoup(path, ext, name, size, options);
    if (!soup) return soup.error();
    if (options.scale != 1.0)
      for (Vec3& v : soup->vertices) v *= options.scale;
    return checkAndRepair(*soup, options, name);
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::TooLarge, "there is not enough memory to load this model", name};
  } catch (const std::exception& e) {
    return Error{ErrorCode::Internal, std::string("unexpected failure while loading (") + e.what() +
                                          "); please report it with this file", name};
  }
}

}  // namespace multidir::core
