// Every number of a text mesh file is read strictly: plain decimal notation, finite as a double and as a
// float. Tokens other readers misread ("1e39", "0x10", "nan", "inf") are refused naming the line.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "multidir/core/mesh/mesh_io.h"
#include "support/mesh_fixtures.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::cubeMesh;
using multidir::test::scratchDirectory;

namespace {

std::string writeFile(const std::string& dir, const std::string& name, const std::string& content) {
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// The cube as OFF, OBJ or ASCII PLY with vertex 6 (10 10 10, on line `line`) written as `x 10 10`.
std::string cubeText(const std::string& format, const std::string& x, std::size_t& line) {
  const TriangleMesh cube = cubeMesh();
  std::ostringstream out;
  std::size_t headerLines = 0;
  if (format == "off") {
    out << "OFF\n8 12 0\n";
    headerLines = 2;
  } else if (format == "ply") {
    out << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 12\nproperty list uchar int vertex_indices\nend_header\n";
    headerLines = 9;
  }
  for (std::size_t v = 0; v < cube.vertices.size(); ++v) {
    const Vec3& p = cube.vertices[v];
    if (format == "obj") out << "v ";
    if (v == 6) out << x << " " << p.y() << " " << p.z() << "\n";
    else out << p.x() << " " << p.y() << " " << p.z() << "\n";
  }
  for (const Triangle& t : cube.triangles) {
    if (format == "obj") out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    else out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  }
  line = headerLines + 7;
  return out.str();
}

void expectRefusedNamingLine(const std::string& format, const std::string& token, ErrorCode code) {
  SCOPED_TRACE(format + " with x = " + token);
  // A folder of the test's own: ctest runs the tests of this file side by side, and in a shared folder one
  // test read the cube another had just written (0x10 refused as 1e39).
  const std::string dir =
      scratchDirectory(std::string("NumberTokens.") + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                       "." + format);
  std::size_t line = 0;
  const std::string text = cubeText(format, token, line);
  const Result<LoadedMesh> loaded = loadMesh(writeFile(dir, "cube." + format, text));
  ASSERT_FALSE(loaded.ok()) << "the token '" << token << "' was accepted";
  EXPECT_EQ(loaded.error().code, code) << loaded.error().describe();
  EXPECT_NE(loaded.error().message.find("line " + std::to_string(line)), std::string::npos)
      << loaded.error().describe();
  EXPECT_NE(loaded.error().message.find(token), std::string::npos) << loaded.error().describe();
}

}  // namespace

TEST(MeshNumberTokens, CoordinateBeyondFloatRangeIsRefusedNamingTheLine) {
  for (const char* format : {"off", "obj", "ply"}) {
    expectRefusedNamingLine(format, "1e39", ErrorCode::NonFiniteVertex);
    expectRefusedNamingLine(format, "-4e38", ErrorCode::NonFiniteVertex);
    expectRefusedNamingLine(format, "1e999", ErrorCode::NonFiniteVertex);
  }
}

TEST(MeshNumberTokens, HexadecimalCoordinateIsRefusedNamingTheLine) {
  for (const char* format : {"off", "obj", "ply"}) {
    expectRefusedNamingLine(format, "0x10", ErrorCode::MalformedFile);
    expectRefusedNamingLine(format, "0x1p3", ErrorCode::MalformedFile);
  }
}

TEST(MeshNumberTokens, NanAndInfinityAreRefusedAsNonFiniteNamingTheLine) {
  for (const char* format : {"off", "obj", "ply"})
    for (const char* token : {"nan", "NaN", "inf", "-Infinity", "nan(0x1)"})
      expectRefusedNamingLine(format, token, ErrorCode::NonFiniteVertex);
}

TEST(MeshNumberTokens, OtherNonDecimalSpellingsAreRefused) {
  for (const char* token : {"1e", "1.2.3", "--1", "1,5", "10f", ".", "+-1", "1e+"})
    expectRefusedNamingLine("off", token, ErrorCode::MalformedFile);
}

TEST(MeshNumberTokens, PlainDecimalFormsAreRead) {
  // All of these are the number ten (or as close as decimal gets): the cube must come back whole.
  for (const char* token : {"10", "+10", "10.", "10.0", "1e1", "1E+1", "100e-1", "0010"}) {
    SCOPED_TRACE(token);
    std::size_t line = 0;
    const Result<LoadedMesh> loaded =
        loadMesh(writeFile(scratchDirectory("NumberTokens.Plain"), "cube.off", cubeText("off", token, line)));
    ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
    EXPECT_NEAR(loaded->report.statistics.volumeMm3, 1000.0, 1e-9);
  }
}

TEST(MeshNumberTokens, TextCoordinatesKeepDoublePrecision) {
  // OpenMesh's readers kept floats (7 digits); MultiDir's own keep every digit a double holds.
  std::size_t line = 0;
  const Result<LoadedMesh> loaded = loadMesh(
      writeFile(scratchDirectory("NumberTokens.Precision"), "cube.obj", cubeText("obj", "10.000000000001", line)));
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->report.statistics.bounds.max.x(), 10.000000000001);
}

TEST(MeshNumberTokens, HexadecimalOrFractionalVertexIndexIsRefusedNamingTheLine) {
  const std::string dir = scratchDirectory("NumberTokens.Index");
  std::size_t line = 0;
  for (const char* index : {"0x1", "1.5", "1e0", "nan"}) {
    SCOPED_TRACE(index);
    std::string text = cubeText("off", "10", line);
    text.replace(text.find("3 0 2 1"), 7, std::string("3 0 2 ") + index);
    const Result<LoadedMesh> loaded = loadMesh(writeFile(dir, "cube.off", text));
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
    EXPECT_NE(loaded.error().message.find("line 11"), std::string::npos) << loaded.error().describe();
  }
}

TEST(MeshNumberTokens, BinaryPlyDoubleBeyondFloatRangeIsRefused) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty double x\nproperty double y\n"
      "property double z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n";
  const TriangleMesh cube = cubeMesh();
  for (std::size_t v = 0; v < cube.vertices.size(); ++v)
    for (int i = 0; i < 3; ++i) {
      const double c = v == 6 && i == 0 ? 1e39 : cube.vertices[v][i];
      bytes.append(reinterpret_cast<const char*>(&c), 8);
    }
  for (const Triangle& t : cube.triangles) {
    bytes.push_back(3);
    bytes.append(reinterpret_cast<const char*>(t.data()), 12);
  }
  const Result<LoadedMesh> loaded = loadMesh(writeFile(scratchDirectory("NumberTokens.BinaryPly"), "cube.ply", bytes));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NonFiniteVertex) << loaded.error().describe();
  EXPECT_NE(loaded.error().message.find("vertex 6"), std::string::npos) << loaded.error().describe();
}

TEST(MeshNumberTokens, AsciiStlCoordinatesAreReadAsStrictly) {
  std::ostringstream out;
  out << "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 0x10 0 0\n   vertex 0 1 0\n"
         "  endloop\n endfacet\nendsolid t\n";
  const Result<LoadedMesh> loaded = loadMesh(writeFile(scratchDirectory("NumberTokens.Stl"), "t.stl", out.str()));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(loaded.error().message.find("line 5"), std::string::npos) << loaded.error().describe();
}
