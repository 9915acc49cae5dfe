// PLY files (ASCII and binary, either byte order), read by MultiDir itself: header, counts against the
// file size, then one walk over the body that parses every value strictly and keeps the vertex positions
// and the faces' vertex indices.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <limits>
#include <vector>

#include "mesh/mesh_formats.h"

namespace multidir::core::detail {
namespace {

struct ScalarType {
  int bytes = 0;  // 0: unknown type name
  bool integer = false;
  bool isSigned = false;
};

ScalarType scalarType(const std::string& t) {
  if (t == "char" || t == "int8") return {1, true, true};
  if (t == "uchar" || t == "uint8") return {1, true, false};
  if (t == "short" || t == "int16") return {2, true, true};
  if (t == "ushort" || t == "uint16") return {2, true, false};
  if (t == "int" || t == "int32") return {4, true, true};
  if (t == "uint" || t == "uint32") return {4, true, false};
  if (t == "float" || t == "float32") return {4, false, true};
  if (t == "double" || t == "float64") return {8, false, true};
  return {};
}

struct Property {
  std::string name;
  ScalarType type;
  bool list = false;
  ScalarType countType;  // lists only
};

struct Element {
  std::string name;
  std::uintmax_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { Ascii, BinaryLittle, BinaryBig };

bool hostIsLittleEndian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Reads the body value by value, whatever the encoding.
class BodyReader {
 public:
  // `headerLines`: the lines before the body, so that ASCII line numbers count from the file's start.
  BodyReader(std::istream& in, Encoding encoding, std::size_t headerLines)
      : m_in(in), m_lines(in), m_encoding(encoding), m_headerLines(headerLines) {}

  enum class Value { Ok, End, NotANumber, NotFinite };
  // One value of `type`; in ASCII the token must be a plain decimal number (see parseCoordinate).
  Value read(const ScalarType& type, double& value) {
    if (m_encoding == Encoding::Ascii) {
      if (!nextToken()) return Value::End;
      m_token = std::move(m_tokens.front());
      m_tokens.pop_front();
      switch (parseCoordinate(m_token, value)) {
        case NumberStatus::Ok: return Value::Ok;
        case NumberStatus::NotFinite: return Value::NotFinite;
        case NumberStatus::NotANumber: return Value::NotANumber;
      }
      return Value::NotANumber;
    }
    unsigned char bytes[8];
    if (!m_in.read(reinterpret_cast<char*>(bytes), type.bytes)) return Value::End;
    if ((m_encoding == Encoding::BinaryBig) == hostIsLittleEndian()) std::reverse(bytes, bytes + type.bytes);
    value = decode(type, bytes);
    m_lastBinary = value;
    return isFiniteAsFloat(value) ? Value::Ok : Value::NotFinite;
  }
  // The ASCII token read last and its line (0 in binary files).
  std::string token() const {
    if (m_encoding == Encoding::Ascii) return m_token;
    char text[32];
    std::snprintf(text, sizeof text, "%g", m_lastBinary);
    return text;
  }
  std::size_t lineNumber() const { return m_encoding == Encoding::Ascii ? m_headerLines + m_lines.lineNumber() : 0; }
  bool binaryText() const { return m_lines.binary() || m_lines.tooLong(); }

 private:
  bool nextToken() {
    std::vector<std::string> split;
    std::string line;
    while (m_tokens.empty()) {
      if (!m_lines.next(line) || binaryText()) return false;
      splitTokens(line, split);
      m_tokens.insert(m_tokens.end(), split.begin(), split.end());
    }
    return true;
  }
  static double decode(const ScalarType& type, const unsigned char* b) {
    if (!type.integer) {
      if (type.bytes == 4) {
        float f;
        std::memcpy(&f, b, 4);
        return f;
      }
      double d;
      std::memcpy(&d, b, 8);
      return d;
    }
    switch (type.bytes) {
      case 1: return type.isSigned ? static_cast<double>(static_cast<std::int8_t>(b[0])) : b[0];
      case 2: {
        std::uint16_t u;
        std::memcpy(&u, b, 2);
        return type.isSigned ? static_cast<double>(static_cast<std::int16_t>(u)) : u;
      }
      default: {
        std::uint32_t u;
        std::memcpy(&u, b, 4);
        return type.isSigned ? static_cast<double>(static_cast<std::int32_t>(u)) : u;
      }
    }
  }

  std::istream& m_in;
  LineReader m_lines;
  Encoding m_encoding;
  std::deque<std::string> m_tokens;
  std::size_t m_headerLines;
  std::string m_token;
  double m_lastBinary = 0.0;
};

}  // namespace

Result<RawSoup> readPly(std::istream& in, std::uintmax_t fileSize, const std::string& name,
                        const LoadOptions& options) {
  LineReader header(in);
  std::string line;
  std::vector<std::string> tokens;
  auto headerError = [&](const std::string& what) {
    return malformed(name, "PLY header line " + std::to_string(header.lineNumber()) + ": " + what);
  };
  if (!header.next(line) || splitTokens(line, tokens) != 1 || tokens[0] != "ply")
    return malformed(name, "the file does not start with 'ply': it is not a PLY file");

  Encoding encoding = Encoding::Ascii;
  bool sawFormat = false, sawEnd = false;
  std::vector<Element> elements;
  std::size_t headerBytes = 4;
  while (!sawEnd && header.next(line)) {
    headerBytes += line.size() + 1;
    if (header.binary() || header.tooLong() || header.lineNumber() > 10000)
      return headerError("the header holds binary bytes or never ends (no 'end_header')");
    if (splitTokens(line, tokens) == 0) continue;
    const std::string& key = tokens[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      sawEnd = true;
    } else if (key == "format") {
      if (tokens.size() != 3) return headerError("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (tokens[1] == "ascii") encoding = Encoding::Ascii;
      else if (tokens[1] == "binary_little_endian") encoding = Encoding::BinaryLittle;
      else if (tokens[1] == "binary_big_endian") encoding = Encoding::BinaryBig;
      else return headerError("unknown format '" + tokens[1] + "'");
      sawFormat = true;
    } else if (key == "element") {
      long long count = -1;
      if (tokens.size() != 3 || !parseInteger(tokens[2], count) || count < 0)
        return headerError("expected 'element NAME COUNT'");
      elements.push_back({tokens[1], static_cast<std::uintmax_t>(count), {}});
    } else if (key == "property") {
      if (elements.empty()) return headerError("a property comes before any element");
      Property p;
      if (tokens.size() == 5 && tokens[1] == "list") {
        p = {tokens[4], scalarType(tokens[3]), true, scalarType(tokens[2])};
        if (p.countType.bytes == 0 || !p.countType.integer || p.type.bytes == 0)
          return headerError("unknown or unusable list types '" + tokens[2] + " " + tokens[3] + "'");
      } else if (tokens.size() == 3) {
        p = {tokens[2], scalarType(tokens[1]), false, {}};
        if (p.type.bytes == 0) return headerError("unknown property type '" + tokens[1] + "'");
      } else {
        return headerError("expected 'property TYPE NAME' or 'property list COUNTTYPE TYPE NAME'");
      }
      elements.back().properties.push_back(p);
    } else {
      return headerError("unknown keyword '" + key.substr(0, 20) + "'");
    }
  }
  if (!sawFormat || !sawEnd) return malformed(name, "the PLY header is incomplete (no 'format' or 'end_header' line)");

  // Which element and properties hold the mesh.
  const Element* vertexElement = nullptr;
  const Element* faceElement = nullptr;
  for (const Element& e : elements) {
    if (e.name == "vertex") vertexElement = &e;
    if (e.name == "face") faceElement = &e;
  }
  if (vertexElement == nullptr || faceElement == nullptr)
    return malformed(name, "the PLY file has no 'vertex' or no 'face' element: it holds no surface");
  int xyzIndex[3] = {-1, -1, -1};
  for (std::size_t i = 0; i < vertexElement->properties.size(); ++i) {
    const Property& p = vertexElement->properties[i];
    for (int axis = 0; axis < 3; ++axis)
      if (!p.list && p.name == std::string(1, static_cast<char>('x' + axis))) xyzIndex[axis] = static_cast<int>(i);
  }
  if (xyzIndex[0] < 0 || xyzIndex[1] < 0 || xyzIndex[2] < 0)
    return malformed(name, "the PLY vertices have no x, y and z properties");
  int indexList = -1;
  for (std::size_t i = 0; i < faceElement->properties.size(); ++i) {
    const Property& p = faceElement->properties[i];
    if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index") && p.type.integer)
      indexList = static_cast<int>(i);
  }
  if (indexList < 0) return malformed(name, "the PLY faces have no integer list 'vertex_indices'");

  const std::uintmax_t nv = vertexElement->count, nf = faceElement->count;
  if (nf > options.maxTriangles)
    return Error{ErrorCode::TooLarge,
                 "the file announces " + withThousands(nf) + " faces, more than the limit of " +
                     withThousands(options.maxTriangles) + " triangles; simplify the model first",
                 name};
  // Every element needs at least this many bytes: a lower bound that exposes counts the file cannot hold.
  const std::uintmax_t bodyBytes = fileSize > headerBytes ? fileSize - headerBytes : 0;
  std::uintmax_t needed = 0;
  for (const Element& e : elements) {
    std::uintmax_t perElement = 0;
    for (const Property& p : e.properties)
      perElement += encoding == Encoding::Ascii ? 2 : static_cast<std::uintmax_t>(p.list ? p.countType.bytes : p.type.bytes);
    if (perElement == 0) perElement = 1;
    if (e.count > bodyBytes / perElement || needed + e.count * perElement > bodyBytes)
      return malformed(name, "the header announces " + withThousands(e.count) + " " + e.name +
                                 " elements, more than the " + withThousands(bodyBytes) +
                                 " bytes after the header can hold: the file is truncated or its header is wrong");
    needed += e.count * perElement;
  }
  if (nv > static_cast<std::uintmax_t>(std::numeric_limits<std::int32_t>::max()))
    return Error{ErrorCode::TooLarge, "the file holds more vertices than MultiDir can index", name};

  RawSoup soup;
  soup.vertices.reserve(static_cast<std::size_t>(nv));
  soup.triangles.reserve(static_cast<std::size_t>(nf));
  BodyReader body(in, encoding, header.lineNumber());
  auto where = [&](const Element& e, std::uintmax_t i) {
    const std::size_t lineNumber = body.lineNumber();
    return (lineNumber > 0 ? "line " + std::to_string(lineNumber) + ", " : std::string()) + e.name + " " +
           std::to_string(i);
  };
  auto refused = [&](const Element& e, std::uintmax_t i, BodyReader::Value value) -> Error {
    if (body.binaryText())
      return malformed(name, "the ASCII body holds binary bytes or an overlong line (in " + where(e, i) + ")");
    if (value == BodyReader::Value::End)
      return malformed(name, "the data ends in " + e.name + " " + std::to_string(i) + " of " +
                                 withThousands(e.count) + ": the file is truncated");
    return malformed(name, where(e, i) + ": '" + body.token().substr(0, 40) +
                               "' is not a plain decimal number in range; the file is damaged, export it again");
  };
  std::vector<std::int32_t> corners;
  for (const Element& e : elements) {
    const bool isVertex = &e == vertexElement, isFace = &e == faceElement;
    for (std::uintmax_t i = 0; i < e.count; ++i) {
      Vec3 point = Vec3::Zero();
      for (std::size_t pi = 0; pi < e.properties.size(); ++pi) {
        const Property& p = e.properties[pi];
        double value = 0.0;
        if (!p.list) {
          const BodyReader::Value got = body.read(p.type, value);
          const int axis = !isVertex                          ? -1
                           : static_cast<int>(pi) == xyzIndex[0] ? 0
                           : static_cast<int>(pi) == xyzIndex[1] ? 1
                           : static_cast<int>(pi) == xyzIndex[2] ? 2
                                                                 : -1;
          if (axis >= 0 && got == BodyReader::Value::NotFinite)
            return coordinateError(name, body.lineNumber(), static_cast<std::size_t>(i), body.token(),
                                   NumberStatus::NotFinite);
          // Values MultiDir does not use (normals, colours) may be anything finite or not, but must be numbers.
          if (got != BodyReader::Value::Ok && !(axis < 0 && got == BodyReader::Value::NotFinite))
            return refused(e, i, got);
          if (axis >= 0) point[axis] = value;
          continue;
        }
        double countValue = 0.0;
        if (const BodyReader::Value got = body.read(p.countType, countValue); got != BodyReader::Value::Ok)
          return refused(e, i, got);
        if (countValue < 0 || countValue != std::floor(countValue) || countValue > static_cast<double>(bodyBytes))
          return malformed(name, where(e, i) + ": the list length '" + body.token().substr(0, 40) +
                                     "' is not a count this file can hold; the file is damaged");
        const auto count = static_cast<std::uintmax_t>(countValue);
        const bool isIndexList = isFace && static_cast<int>(pi) == indexList;
        if (isIndexList) corners.clear();
        for (std::uintmax_t k = 0; k < count; ++k) {
          const BodyReader::Value got = body.read(p.type, value);
          if (got != BodyReader::Value::Ok && !(!isIndexList && got == BodyReader::Value::NotFinite))
            return refused(e, i, got);
          if (!isIndexList) continue;
          if (value < 0 || value >= static_cast<double>(nv) || value != std::floor(value))
            return malformed(name, where(e, i) + " refers to vertex '" + body.token().substr(0, 40) +
                                       "', but the vertices are numbered 0 to " +
                                       std::to_string(static_cast<long long>(nv) - 1));
          corners.push_back(static_cast<std::int32_t>(value));
        }
        if (isIndexList)
          if (Status added = addPolygon(soup, corners, options, name); !added.ok()) return added.error();
      }
      if (isVertex) soup.vertices.push_back(point);
    }
  }
  return soup;
}

}  // namespace multidir::core::detail
