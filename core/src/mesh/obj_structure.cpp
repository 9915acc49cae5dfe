// Structure check of Wavefront OBJ files: only vertices ("v") and faces ("f") matter to MultiDir.
#include <cmath>
#include <limits>
#include <vector>

#include "mesh/mesh_formats.h"

namespace multidir::core::detail {

Result<FileShape> checkObjStructure(std::istream& in, const std::string& name, const LoadOptions& options) {
  LineReader reader(in);
  std::string line;
  std::vector<std::string> tokens;
  FileShape shape;
  auto lineError = [&](const std::string& what) {
    return malformed(name, "line " + std::to_string(reader.lineNumber()) + ": " + what +
                               ". The file is not valid OBJ; export it again from the program that made it.");
  };
  while (reader.next(line)) {
    if (reader.binary())
      return malformed(name, "line " + std::to_string(reader.lineNumber()) +
                                 " holds binary bytes: this is not an OBJ file (OBJ is text)");
    if (reader.tooLong())
      return lineError("the line is longer than " + std::to_string(LineReader::kMaxLineLength) + " characters");
    if (splitTokens(line, tokens) == 0 || tokens[0][0] == '#') continue;
    if (tokens[0] == "v") {
      double xyz[3] = {0, 0, 0};
      if (tokens.size() < 4 || !parseDouble(tokens[1], xyz[0]) || !parseDouble(tokens[2], xyz[1]) ||
          !parseDouble(tokens[3], xyz[2]))
        return lineError("a vertex needs three numbers x y z");
      for (double c : xyz)
        if (!std::isfinite(c))
          return Error{ErrorCode::NonFiniteVertex,
                       "vertex " + std::to_string(shape.vertices) + " (line " +
                           std::to_string(reader.lineNumber()) +
                           ") has a coordinate that is not a finite number; fix or remove it in a mesh editor",
                       name};
      if (++shape.vertices > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        return Error{ErrorCode::TooLarge, "the file holds more vertices than MultiDir can index", name};
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) return lineError("a face needs at least three corners");
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        // A corner is v, v/vt, v/vt/vn or v//vn; only v matters here. Negative v counts back from the end.
        const std::string vertexPart = tokens[k].substr(0, tokens[k].find('/'));
        long long index = 0;
        if (!parseInteger(vertexPart, index) || index == 0)
          return lineError("face corner '" + tokens[k] + "' does not start with a vertex number");
        const long long resolved = index > 0 ? index - 1 : static_cast<long long>(shape.vertices) + index;
        if (resolved < 0 || resolved >= static_cast<long long>(shape.vertices))
          return lineError("face corner '" + tokens[k] + "' refers to a vertex that is not defined before it (" +
                           std::to_string(shape.vertices) + " so far)");
      }
      ++shape.polygons;
      shape.triangles += tokens.size() - 3;
      if (Status count = checkTriangleCount(shape.triangles, options, name); !count.ok()) return count.error();
    }
  }
  return shape;
}

}  // namespace multidir::core::detail
