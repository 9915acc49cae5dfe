// Wavefront OBJ files, read by MultiDir itself: only vertices ("v") and faces ("f") matter to MultiDir.
#include <limits>
#include <vector>

#include "mesh/mesh_formats.h"

namespace multidir::core::detail {

Result<RawSoup> readObj(std::istream& in, const std::string& name, const LoadOptions& options) {
  LineReader reader(in);
  std::string line;
  std::vector<std::string> tokens;
  RawSoup soup;
  std::vector<std::int32_t> corners;
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
      // "v x y z [w]" or "v x y z r g b": only x y z matter.
      if (tokens.size() < 4) return lineError("a vertex needs three numbers x y z");
      Vec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        const std::string& token = tokens[static_cast<std::size_t>(axis) + 1];
        if (NumberStatus status = parseCoordinate(token, p[axis]); status != NumberStatus::Ok)
          return coordinateError(name, reader.lineNumber(), soup.vertices.size(), token, status);
      }
      if (soup.vertices.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        return Error{ErrorCode::TooLarge, "the file holds more vertices than MultiDir can index", name};
      soup.vertices.push_back(p);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) return lineError("a face needs at least three corners");
      corners.clear();
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        // A corner is v, v/vt, v/vt/vn or v//vn; only v matters here. Negative v counts back from the end.
        const std::string vertexPart = tokens[k].substr(0, tokens[k].find('/'));
        long long index = 0;
        if (!parseInteger(vertexPart, index) || index == 0)
          return lineError("face corner '" + tokens[k].substr(0, 40) + "' does not start with a vertex number");
        const auto defined = static_cast<long long>(soup.vertices.size());
        const long long resolved = index > 0 ? index - 1 : defined + index;
        if (resolved < 0 || resolved >= defined)
          return lineError("face corner '" + tokens[k].substr(0, 40) +
                           "' refers to a vertex that is not defined before it (" + std::to_string(defined) +
                           " so far)");
        corners.push_back(static_cast<std::int32_t>(resolved));
      }
      if (Status added = addPolygon(soup, corners, options, name); !added.ok()) return added.error();
    }
  }
  return soup;
}

}  // namespace multidir::core::detail
