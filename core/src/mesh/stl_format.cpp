// STL, ASCII and binary, read and written by MultiDir itself. OpenMesh's STL reader welds vertices and
// drops degenerate facets silently, which would hide defects the checks must report.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <ostream>
#include <vector>

#include "detail/huge_pages.h"
#include "detail/parallel.h"
#include "mesh/mesh_formats.h"

namespace multidir::core::detail {
namespace {

constexpr std::uintmax_t kHeaderBytes = 84;  // 80 bytes of text, then the uint32 triangle count
constexpr std::uintmax_t kFacetBytes = 50;   // normal, three corners (12 floats), uint16 attribute

std::uint32_t readLittle32(const unsigned char* b) {
  return static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
         (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}

float readLittleFloat(const unsigned char* b) {
  const std::uint32_t bits = readLittle32(b);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

void writeLittle32(std::ostream& out, std::uint32_t v) {
  const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                              static_cast<unsigned char>(v >> 16), static_cast<unsigned char>(v >> 24)};
  out.write(reinterpret_cast<const char*>(b), 4);
}

void appendLittleFloat(std::vector<unsigned char>& out, double value) {
  const auto f = static_cast<float>(value);
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<unsigned char>(bits >> shift));
}

Error tooMany(const std::string& name, std::uintmax_t count, const LoadOptions& options) {
  return Error{ErrorCode::TooLarge,
               "the file holds " + withThousands(count) + " triangles, more than the limit of " +
                   withThousands(options.maxTriangles) + "; simplify the model first (e.g. MeshLab's "
                   "'Quadric Edge Collapse Decimation')",
               name};
}

// Reads the facets a chunk at a time and parses each chunk on threads, every facet into its own slots (its
// three corners, its triangle), so the soup is the same for any thread count.
Result<RawSoup> readBinary(std::istream& in, std::uintmax_t count, const std::string& name) {
  constexpr std::size_t kChunkFacets = 65536;  // 3.2 MB read at once
  constexpr int kParseBlock = 4096;            // facets per parsing task
  RawSoup soup;
  reserveInHugePages(soup.vertices, count * 3);
  reserveInHugePages(soup.triangles, count);
  soup.vertices.resize(count * 3);  // Vec3's default constructor leaves it unwritten: no pass over it here
  soup.triangles.resize(count);
  const int threads = resolveThreadCount(0);
  std::vector<unsigned char> chunk(std::min<std::uintmax_t>(count, kChunkFacets) * kFacetBytes);
  for (std::size_t start = 0; start < count; start += kChunkFacets) {
    const std::size_t facets = std::min<std::size_t>(kChunkFacets, count - start);
    in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(facets * kFacetBytes));
    if (static_cast<std::size_t>(in.gcount()) != facets * kFacetBytes)
      return malformed(name, "the file ends inside triangle " +
                                 std::to_string(start + static_cast<std::size_t>(in.gcount()) / kFacetBytes) +
                                 ": it is truncated");
    const int blocks = static_cast<int>((facets + kParseBlock - 1) / kParseBlock);
    parallelFor(blocks, threads, [&](int block) {
      const std::size_t end = std::min(facets, static_cast<std::size_t>(block + 1) * kParseBlock);
      for (std::size_t i = static_cast<std::size_t>(block) * kParseBlock; i < end; ++i) {
        const std::size_t f = start + i;
        const auto first = static_cast<std::int32_t>(3 * f);
        for (int corner = 0; corner < 3; ++corner) {
          const unsigned char* p = chunk.data() + i * kFacetBytes + 12 + 12 * corner;  // after the normal, recomputed
          soup.vertices[3 * f + static_cast<std::size_t>(corner)] =
              Vec3(readLittleFloat(p), readLittleFloat(p + 4), readLittleFloat(p + 8));
        }
        soup.triangles[f] = {first, first + 1, first + 2};
      }
    });
  }
  return soup;
}

Result<RawSoup> readAscii(std::istream& in, const std::string& name, const LoadOptions& options) {
  enum class State { Outside, InSolid, InFacet, InLoop, AfterLoop };
  State state = State::Outside;
  LineReader reader(in);
  std::string line;
  std::vector<std::string> tokens;
  RawSoup soup;
  std::vector<std::int32_t> loop;
  auto lineError = [&](const std::string& what) {
    return malformed(name, "line " + std::to_string(reader.lineNumber()) + ": " + what +
                               ". The file is not valid ASCII STL; export it again from the program that made it.");
  };
  while (reader.next(line)) {
    if (reader.binary())
      return malformed(name, "the file starts with 'solid' but holds binary bytes (line " +
                                 std::to_string(reader.lineNumber()) +
                                 ") and its size does not match a binary STL: it is damaged or truncated");
    if (reader.tooLong()) return lineError("the line is too long");
    if (splitTokens(line, tokens) == 0) continue;
    const std::string& key = tokens[0];
    switch (state) {
      case State::Outside:
        if (key != "solid") return lineError("expected 'solid'");
        state = State::InSolid;
        break;
      case State::InSolid:
        if (key == "endsolid") {
          state = State::Outside;
        } else if (key == "facet") {
          state = State::InFacet;
        } else {
          return lineError("expected 'facet' or 'endsolid', found '" + key.substr(0, 20) + "'");
        }
        break;
      case State::InFacet:
        if (tokens.size() != 2 || key != "outer" || tokens[1] != "loop") return lineError("expected 'outer loop'");
        loop.clear();
        state = State::InLoop;
        break;
      case State::InLoop:
        if (key == "vertex") {
          Vec3 p;
          if (tokens.size() != 4) return lineError("a vertex needs three numbers x y z");
          for (int axis = 0; axis < 3; ++axis) {
            const std::string& token = tokens[static_cast<std::size_t>(axis) + 1];
            if (NumberStatus status = parseCoordinate(token, p[axis]); status != NumberStatus::Ok)
              return coordinateError(name, reader.lineNumber(), soup.vertices.size(), token, status);
          }
          if (soup.vertices.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
            return tooMany(name, soup.triangles.size(), options);
          loop.push_back(static_cast<std::int32_t>(soup.vertices.size()));
          soup.vertices.push_back(p);
        } else if (key == "endloop") {
          if (loop.size() < 3) return lineError("a facet needs at least three vertices");
          for (std::size_t k = 1; k + 1 < loop.size(); ++k) soup.triangles.push_back({loop[0], loop[k], loop[k + 1]});
          if (soup.triangles.size() > options.maxTriangles) return tooMany(name, soup.triangles.size(), options);
          state = State::AfterLoop;
        } else {
          return lineError("expected 'vertex' or 'endloop'");
        }
        break;
      case State::AfterLoop:
        if (key != "endfacet") return lineError("expected 'endfacet'");
        state = State::InSolid;
        break;
    }
  }
  if (state != State::Outside)
    return malformed(name, "the file ends inside a " + std::string(state == State::InSolid ? "solid" : "facet") +
                               " (no 'endsolid'): it is truncated");
  return soup;
}

bool startsWithSolid(const unsigned char* bytes, std::size_t size) {
  std::size_t i = 0;
  while (i < size && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) ++i;
  return size - i >= 5 && std::memcmp(bytes + i, "solid", 5) == 0;
}

}  // namespace

Result<RawSoup> readStl(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                        const LoadOptions& options) {
  if (fileSize == 0) return malformed(name, "the file is empty");
  std::array<unsigned char, kHeaderBytes> header{};
  const std::size_t headerRead = static_cast<std::size_t>(std::min<std::uintmax_t>(fileSize, kHeaderBytes));
  if (!in.read(reinterpret_cast<char*>(header.data()), static_cast<std::streamsize>(headerRead)))
    return Error{ErrorCode::FileNotFound, "the file could not be read", name};
  const bool solid = startsWithSolid(header.data(), headerRead);

  // A binary STL may start with "solid" too (many exporters write it into the 80-byte header), so the
  // size decides: a binary file is exactly 84 + 50 * count bytes long.
  if (fileSize >= kHeaderBytes) {
    const std::uintmax_t count = readLittle32(header.data() + 80);
    if (kHeaderBytes + kFacetBytes * count == fileSize) {
      if (count > options.maxTriangles ||
          count * 3 > static_cast<std::uintmax_t>(std::numeric_limits<std::int32_t>::max()))
        return tooMany(name, count, options);
      return readBinary(in, count, name);
    }
    if (!solid)
      return malformed(name, "the binary STL header announces " + withThousands(count) + " triangles, which take " +
                                 withThousands(kHeaderBytes + kFacetBytes * count) + " bytes, but the file has " +
                                 withThousands(fileSize) + " bytes: it is truncated or not an STL file");
  } else if (!solid) {
    return malformed(name, "the file is " + std::to_string(fileSize) +
                               " bytes long, too short for a binary STL (84 bytes at least), and does not start "
                               "with 'solid': it is not an STL file");
  }
  in.clear();
  in.seekg(0);
  return readAscii(in, name, options);
}

Status writeStl(const TriangleMesh& mesh, std::ostream& out, bool ascii) {
  if (ascii) {
    out.precision(17);
    out << "solid multidir\n";
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const Vec3 n = mesh.areaNormal(f).normalized();
      out << "  facet normal " << (n.allFinite() ? n.x() : 0.0) << ' ' << (n.allFinite() ? n.y() : 0.0) << ' '
          << (n.allFinite() ? n.z() : 0.0) << "\n    outer loop\n";
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.corner(f, k);
        out << "      vertex " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
      }
      out << "    endloop\n  endfacet\n";
    }
    out << "endsolid multidir\n";
    return Done{};
  }
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max())
    return Error{ErrorCode::WriteFailed, "binary STL holds at most 4,294,967,295 triangles", "stl"};
  // The 80-byte header must not start with "solid", or some readers take the file for ASCII.
  char text[80] = {};
  std::strncpy(text, "binary STL written by MultiDir, millimetres", sizeof(text) - 1);
  out.write(text, 80);
  writeLittle32(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  // Facets gathered in a buffer and written a block at a time: thirteen stream writes per facet were most of
  // the time of saving a region of a million faces.
  constexpr std::size_t kFacetsPerWrite = 4096;
  std::vector<unsigned char> block;
  block.reserve(kFacetsPerWrite * kFacetBytes);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    Vec3 n = mesh.areaNormal(f).normalized();
    if (!n.allFinite()) n = Vec3::Zero();
    for (int i = 0; i < 3; ++i) appendLittleFloat(block, n[i]);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) appendLittleFloat(block, mesh.corner(f, k)[i]);
    block.push_back(0);  // the attribute: two zero bytes
    block.push_back(0);
    if (block.size() >= kFacetsPerWrite * kFacetBytes || f + 1 == mesh.triangles.size()) {
      out.write(reinterpret_cast<const char*>(block.data()), static_cast<std::streamsize>(block.size()));
      block.clear();
    }
  }
  return Done{};
}

}  // namespace multidir::core::detail
