// OFF files (Geomview's Object File Format, ASCII form), read by MultiDir itself: OpenMesh's reader
// misread comments, counts on the keyword line, face colours and number tokens such as "1e39" or "0x10"
// (uninitialised indices, gigabytes requested for a small file).
#include <cmath>
#include <limits>
#include <vector>

#include "mesh/mesh_formats.h"

namespace multidir::core::detail {
namespace {

// The shortest a vertex ("0 0 0\n") and a face ("3 0 1 2\n" minus the digits it could share) can be.
constexpr std::uintmax_t kMinVertexBytes = 6;
constexpr std::uintmax_t kMinFaceBytes = 8;

// Reads the next line that holds data: comments (from '#') and blank lines are skipped.
bool nextDataLine(LineReader& reader, std::string& line, std::vector<std::string>& tokens) {
  while (reader.next(line)) {
    if (reader.binary() || reader.tooLong()) return true;  // the caller reports it
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (splitTokens(line, tokens) > 0) return true;
  }
  return false;
}

bool isOffKeyword(const std::string& word) {
  // [ST][C][N][4][n]OFF: the prefixes add per-vertex data; 4 and n change the dimension, which we refuse.
  if (word.size() < 3 || word.compare(word.size() - 3, 3, "OFF") != 0) return false;
  const std::string prefix = word.substr(0, word.size() - 3);
  for (char c : prefix)
    if (std::string("STCN4n").find(c) == std::string::npos) return false;
  return true;
}

}  // namespace

Result<RawSoup> readOff(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                        const LoadOptions& options) {
  LineReader reader(in);
  std::string line;
  std::vector<std::string> tokens;
  auto lineError = [&](const std::string& what) {
    const bool atEnd = in.rdbuf() == nullptr || in.rdbuf()->sgetc() == std::char_traits<char>::eof();
    return malformed(name, "line " + std::to_string(reader.lineNumber()) + ": " + what +
                               (atEnd ? ". The file ends on this line: it is truncated"
                                      : ". The file is not valid OFF; export it again from the program that made it") +
                               ".");
  };
  auto badText = [&]() -> Error {
    if (reader.binary())
      return malformed(name, "line " + std::to_string(reader.lineNumber()) +
                                 " holds binary bytes: this is not an ASCII OFF file (binary OFF is not supported; "
                                 "save it as ASCII OFF, STL, OBJ or PLY)");
    return lineError("the line is longer than " + std::to_string(LineReader::kMaxLineLength) + " characters");
  };

  if (!nextDataLine(reader, line, tokens)) return malformed(name, "the file is empty or holds only comments");
  if (reader.binary() || reader.tooLong()) return badText();
  if (!isOffKeyword(tokens[0]))
    return malformed(name, "the file does not start with the OFF keyword (found '" + tokens[0].substr(0, 20) +
                               "'); it is not an OFF file");
  if (tokens[0].find_first_of("4n") != std::string::npos)
    return Error{ErrorCode::UnsupportedFormat,
                 tokens[0] + " (4-D or n-D OFF) is not supported; only 3-D OFF is", name};
  if (tokens.size() > 1 && tokens[1] == "BINARY")
    return Error{ErrorCode::UnsupportedFormat,
                 "binary OFF is not supported; save the model as ASCII OFF, STL, OBJ or PLY", name};

  // The counts may share the keyword's line or follow on the next.
  std::vector<std::string> counts(tokens.begin() + 1, tokens.end());
  if (counts.empty()) {
    if (!nextDataLine(reader, line, tokens)) return malformed(name, "the file ends before the vertex and face counts");
    if (reader.binary() || reader.tooLong()) return badText();
    counts = tokens;
  }
  long long vertexCount = -1, faceCount = -1, edgeCount = 0;
  if (counts.size() < 2 || counts.size() > 3 || !parseInteger(counts[0], vertexCount) ||
      !parseInteger(counts[1], faceCount) || (counts.size() == 3 && !parseInteger(counts[2], edgeCount)) ||
      vertexCount < 0 || faceCount < 0)
    return lineError("expected the counts 'vertices faces edges' (three whole numbers)");

  const auto nv = static_cast<std::uintmax_t>(vertexCount);
  const auto nf = static_cast<std::uintmax_t>(faceCount);
  if (nf > options.maxTriangles)
    return Error{ErrorCode::TooLarge,
                 "the file announces " + withThousands(nf) + " faces, more than the limit of " +
                     withThousands(options.maxTriangles) + " triangles; simplify the model first (e.g. MeshLab's "
                     "'Quadric Edge Collapse Decimation')",
                 name};
  if (nv > static_cast<std::uintmax_t>(std::numeric_limits<std::int32_t>::max()) ||
      nv > fileSize / kMinVertexBytes || nf > fileSize / kMinFaceBytes ||
      nv * kMinVertexBytes + nf * kMinFaceBytes > fileSize)
    return malformed(name, "the header announces " + withThousands(nv) + " vertices and " + withThousands(nf) +
                               " faces, more than a file of " + withThousands(fileSize) +
                               " bytes can hold: the file is truncated or its header is wrong");

  RawSoup soup;
  soup.vertices.reserve(static_cast<std::size_t>(nv));
  soup.triangles.reserve(static_cast<std::size_t>(nf));
  for (std::uintmax_t v = 0; v < nv; ++v) {
    if (!nextDataLine(reader, line, tokens))
      return malformed(name, "the file ends after " + withThousands(v) + " of the " + withThousands(nv) +
                                 " vertices it announces: it is truncated");
    if (reader.binary() || reader.tooLong()) return badText();
    if (tokens.size() < 3) return lineError("vertex " + std::to_string(v) + " needs three numbers x y z");
    Vec3 p;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string& token = tokens[static_cast<std::size_t>(axis)];
      if (NumberStatus status = parseCoordinate(token, p[axis]); status != NumberStatus::Ok)
        return coordinateError(name, reader.lineNumber(), static_cast<std::size_t>(v), token, status);
    }
    soup.vertices.push_back(p);
  }

  std::vector<std::int32_t> corners;
  for (std::uintmax_t f = 0; f < nf; ++f) {
    if (!nextDataLine(reader, line, tokens))
      return malformed(name, "the file ends after " + withThousands(f) + " of the " + withThousands(nf) +
                                 " faces it announces: it is truncated");
    if (reader.binary() || reader.tooLong()) return badText();
    long long cornerCount = 0;
    if (!parseInteger(tokens[0], cornerCount) || cornerCount < 0 ||
        static_cast<std::uintmax_t>(cornerCount) + 1 > tokens.size())
      return lineError("face " + std::to_string(f) + " must give its corner count and that many vertex indices");
    corners.clear();
    for (long long k = 1; k <= cornerCount; ++k) {
      long long index = -1;
      if (!parseInteger(tokens[static_cast<std::size_t>(k)], index) || index < 0 ||
          static_cast<std::uintmax_t>(index) >= nv)
        return lineError("face " + std::to_string(f) + " refers to vertex '" + tokens[static_cast<std::size_t>(k)] +
                         "', but the vertices are numbered 0 to " + std::to_string(vertexCount - 1));
      corners.push_back(static_cast<std::int32_t>(index));
    }
    // What follows the indices is an optional colour: numbers, checked so that nothing is guessed at.
    for (std::size_t k = static_cast<std::size_t>(cornerCount) + 1; k < tokens.size(); ++k) {
      double ignored = 0.0;
      if (!parseDouble(tokens[k], ignored))
        return lineError("face " + std::to_string(f) + " ends with '" + tokens[k].substr(0, 20) +
                         "', which is not a colour value");
    }
    if (Status added = addPolygon(soup, corners, options, name); !added.ok()) return added.error();
  }
  return soup;
}

}  // namespace multidir::core::detail
