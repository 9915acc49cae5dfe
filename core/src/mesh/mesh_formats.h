#pragma once
// Private to mesh I/O: the readers and structure checks behind loadMesh, one file per format.
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

#include "multidir/core/mesh/mesh_io.h"

namespace multidir::core::detail {

// The readers: each reads the whole file once and builds the soup as the file gives it (polygons fanned
// into triangles), in memory proportional to what the file really holds (announced counts are checked
// against the file size before anything is reserved). Every number is parsed here, strictly (see
// parseCoordinate), so no third-party reader ever guesses at a malformed token. Errors: MalformedFile,
// TooLarge, UnsupportedFormat, NonFiniteVertex, each naming the line (or element) at fault. `name` is the
// file's name for messages.
// OFF: ASCII OFF with optional colour/normal prefixes (ST, C, N); 4-D, n-D and binary OFF are refused.
Result<RawSoup> readOff(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                        const LoadOptions& options);
// PLY: ASCII and binary (either byte order); the 'vertex' element's x, y, z and the 'face' element's
// vertex_indices (or vertex_index) list; other elements and properties are read past.
Result<RawSoup> readPly(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                        const LoadOptions& options);
// OBJ: 'v' and 'f' lines (f v, v/vt, v/vt/vn or v//vn; negative indices count back); the rest is ignored.
Result<RawSoup> readObj(std::istream& in, const std::string& name, const LoadOptions& options);

// STL: ASCII or binary, told apart by size.
Result<RawSoup> readStl(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                        const LoadOptions& options);
Status writeStl(const TriangleMesh& mesh, std::ostream& out, bool ascii);

// Line-oriented text reading with a bound on line length, for the readers.
class LineReader {
 public:
  static constexpr std::size_t kMaxLineLength = 1 << 20;
  explicit LineReader(std::istream& in) : m_in(in) {}
  // Reads the next line into `line` (without the end of line). False at the end of the input.
  // Sets tooLong()/binary() when the line is longer than kMaxLineLength or holds control bytes.
  bool next(std::string& line);
  std::size_t lineNumber() const { return m_lineNumber; }
  bool tooLong() const { return m_tooLong; }
  bool binary() const { return m_binary; }

 private:
  std::istream& m_in;
  std::size_t m_lineNumber = 0;
  bool m_tooLong = false;
  bool m_binary = false;
};

// Splits on blanks. Returns the number of tokens written to `tokens` (cleared first).
std::size_t splitTokens(const std::string& line, std::vector<std::string>& tokens);
// Strict number parsing: the whole token must be the number.
enum class NumberStatus { Ok, NotANumber, NotFinite };
// A coordinate in plain decimal notation ([+-]digits[.digits][e[+-]digits], locale-independent) whose value
// is finite both as a double and as a float (|x| <= 3.4e38: binary STL, the GPU and other tools store
// floats). "nan", "inf" and values out of range are NotFinite; hexadecimal and other spellings NotANumber.
NumberStatus parseCoordinate(const std::string& token, double& value);
bool isFiniteAsFloat(double value);
// parseCoordinate(...) == Ok.
bool parseDouble(const std::string& token, double& value);
// The error for a coordinate token parseCoordinate refused; `line` 0 when there is no line (binary data).
Error coordinateError(const std::string& name, std::size_t line, std::size_t vertex, const std::string& token,
                      NumberStatus status);
bool parseInteger(const std::string& token, long long& value);

// "first: 3, 7, 12" style lists; the caller passes at most a handful.
std::string joinIndices(const std::vector<std::int64_t>& indices);
// 1204 -> "1,204"
std::string withThousands(std::size_t n);

Error malformed(const std::string& name, const std::string& message);
// Fans a polygon (corner indices already checked) into the soup's triangles: exact for the convex polygons
// exporters write. A polygon with fewer than three corners is counted in droppedByReader (degenerate).
// TooLarge once the soup holds more than options.maxTriangles triangles.
Status addPolygon(RawSoup& soup, const std::vector<std::int32_t>& corners, const LoadOptions& options,
                  const std::string& name);
// TooLarge once the faces read so far fan into more than options.maxTriangles triangles.
Status checkTriangleCount(std::size_t triangles, const LoadOptions& options, const std::string& name);

}  // namespace multidir::core::detail
