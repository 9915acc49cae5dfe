#pragma once
// Private to mesh I/O: the readers and structure checks behind loadMesh, one file per format.
#include <cstdint>
#include <istream>
#include <string>

#include "multidir/core/mesh/mesh_io.h"

namespace multidir::core::detail {

// What a structure check learned about a file that OpenMesh will then read.
struct FileShape {
  std::size_t vertices = 0;  // as the file announces (and holds)
  std::size_t polygons = 0;
  std::size_t triangles = 0;  // after fanning polygons
  std::size_t shortPolygons = 0;  // polygons with fewer than three corners (degenerate, not passed on)
};

// Each check reads the whole file once, in bounded memory, and fails with MalformedFile, TooLarge,
// UnsupportedFormat or NonFiniteVertex (a coordinate OpenMesh's readers would silently misread).
// `name` is the file's name for messages.
// OFF: also writes the file in the one form OpenMesh's OFF reader reads reliably to `canonical` ("OFF",
// counts, one vertex per line, one face per line; no comments, blank lines, colours or normals): that
// reader misreads comments, counts on the keyword line and face colours, and reads uninitialised memory
// on short files.
Result<FileShape> checkOffStructure(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                                    const LoadOptions& options, std::ostream& canonical);
Result<FileShape> checkPlyStructure(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                                    const LoadOptions& options);
Result<FileShape> checkObjStructure(std::istream& in, const std::string& name, const LoadOptions& options);

// STL is read without OpenMesh: its reader welds vertices and drops degenerate facets without saying so.
Result<RawSoup> readStl(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                        const LoadOptions& options);
Status writeStl(const TriangleMesh& mesh, std::ostream& out, bool ascii);

// Reads an OFF, OBJ or PLY file that passed its structure check through OpenMesh's readers into a soup.
// `extension` is lower case without the dot ("off"). Reading from a stream also keeps OpenMesh's OBJ
// reader from opening material files next to the model.
Result<RawSoup> readWithOpenMesh(std::istream& in, const std::string& extension, const std::string& name,
                                 const FileShape& shape);

// Line-oriented text reading with a bound on line length, for the structure checks.
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
bool parseDouble(const std::string& token, double& value);
bool parseInteger(const std::string& token, long long& value);

// "first: 3, 7, 12" style lists; the caller passes at most a handful.
std::string joinIndices(const std::vector<std::int64_t>& indices);
// 1204 -> "1,204"
std::string withThousands(std::size_t n);

Error malformed(const std::string& name, const std::string& message);
// TooLarge once the faces read so far fan into more than options.maxTriangles triangles.
Status checkTriangleCount(std::size_t triangles, const LoadOptions& options, const std::string& name);

}  // namespace multidir::core::detail
