// loadMesh and saveMesh on files: every format, malformed and hostile files, the shared real models and
// round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "multidir/core/mesh/mesh_io.h"
#include "support/mesh_fixtures.h"
#include "support/test_models.h"

using namespace multidir::core;
using multidir::test::cubeMesh;
using multidir::test::cubeSoup;
using multidir::test::scratchDirectory;
using multidir::test::sharedModelPath;

namespace {

std::string writeFile(const std::string& dir, const std::string& name, const std::string& content) {
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

std::string asciiStl(const TriangleMesh& mesh) {
  std::ostringstream out;
  out << "solid cube\n";
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (int k = 0; k < 3; ++k)
      out << "   vertex " << mesh.corner(f, k).x() << " " << mesh.corner(f, k).y() << " " << mesh.corner(f, k).z() << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid cube\n";
  return out.str();
}

// A binary STL; `header` fills the 80-byte header, `announced` overrides the triangle count.
std::string binaryStl(const TriangleMesh& mesh, const std::string& header = "binary cube",
                      long long announced = -1) {
  std::string out(80, '\0');
  std::memcpy(out.data(), header.data(), std::min<std::size_t>(header.size(), 80));
  auto put32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  };
  auto putFloat = [&](double d) {
    const auto f = static_cast<float>(d);
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put32(bits);
  };
  put32(static_cast<std::uint32_t>(announced >= 0 ? announced : static_cast<long long>(mesh.faceCount())));
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    for (int i = 0; i < 3; ++i) putFloat(0.0);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) putFloat(mesh.corner(f, k)[i]);
    out.append(2, '\0');
  }
  return out;
}

std::string cubeOff() {
  std::ostringstream out;
  const TriangleMesh cube = cubeMesh();
  out << "OFF\n8 12 0\n";
  for (const Vec3& p : cube.vertices) out << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const Triangle& t : cube.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return out.str();
}

std::string garbage(std::size_t bytes) {
  std::string out;
  std::uint32_t state = 12345;
  for (std::size_t i = 0; i < bytes; ++i) {
    state = state * 1664525u + 1013904223u;
    out.push_back(static_cast<char>(state >> 24));
  }
  return out;
}

void expectCube(const Result<LoadedMesh>& loaded) {
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  EXPECT_EQ(loaded->mesh.faceCount(), 12u);
  EXPECT_EQ(loaded->mesh.vertexCount(), 8u);
  EXPECT_TRUE(loaded->report.statistics.closed);
  EXPECT_NEAR(loaded->report.statistics.volumeMm3, 1000.0, 1e-9);
}

const MeshDefect* findDefect(const MeshReport& report, const std::string& kind) {
  for (const MeshDefect& d : report.defects)
    if (d.kind == kind) return &d;
  return nullptr;
}

}  // namespace

// --- STL -------------------------------------------------------------------------------------------

TEST(MeshIo, AsciiStlCubeIsWeldedIntoEightVertices) {
  const std::string dir = scratchDirectory("MeshIo.AsciiStl");
  auto loaded = loadMesh(writeFile(dir, "cube.stl", asciiStl(cubeMesh())));
  expectCube(loaded);
  const MeshDefect* d = findDefect(loaded->report, "duplicate-vertices");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->count, 28u);
  EXPECT_TRUE(d->repaired);
}

TEST(MeshIo, BinaryStlCubeIsWeldedIntoEightVertices) {
  const std::string dir = scratchDirectory("MeshIo.BinaryStl");
  auto loaded = loadMesh(writeFile(dir, "cube.stl", binaryStl(cubeMesh())));
  expectCube(loaded);
  ASSERT_NE(findDefect(loaded->report, "duplicate-vertices"), nullptr);
}

TEST(MeshIo, BinaryStlWhoseHeaderStartsWithSolidIsReadAsBinary) {
  const std::string dir = scratchDirectory("MeshIo.BinarySolid");
  expectCube(loadMesh(writeFile(dir, "cube.STL", binaryStl(cubeMesh(), "solid cube exported by some CAD"))));
}

TEST(MeshIo, StlWithoutRepairIsAnErrorBecauseItNeedsWelding) {
  const std::string dir = scratchDirectory("MeshIo.StlNoRepair");
  LoadOptions options;
  options.repair = false;
  auto loaded = loadMesh(writeFile(dir, "cube.stl", binaryStl(cubeMesh())), options);
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message.find("duplicate"), std::string::npos) << loaded.error().message;
}

TEST(MeshIo, TruncatedBinaryStlIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.TruncatedStl");
  std::string bytes = binaryStl(cubeMesh());
  bytes.resize(bytes.size() - 30);
  auto loaded = loadMesh(writeFile(dir, "cut.stl", bytes));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_EQ(loaded.error().where, "cut.stl");
}

TEST(MeshIo, BinaryStlWithALyingCountIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.LyingStl");
  auto loaded = loadMesh(writeFile(dir, "liar.stl", binaryStl(cubeMesh(), "binary", 4000000000LL)));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(loaded.error().message.find("announces 4,000,000,000 triangles"), std::string::npos)
      << loaded.error().message;
}

TEST(MeshIo, BinaryStlBeyondTheTriangleLimitIsTooLarge) {
  const std::string dir = scratchDirectory("MeshIo.LargeStl");
  LoadOptions options;
  options.maxTriangles = 10;
  auto loaded = loadMesh(writeFile(dir, "cube.stl", binaryStl(cubeMesh())), options);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::TooLarge);
}

TEST(MeshIo, TruncatedAsciiStlIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.TruncatedAsciiStl");
  std::string text = asciiStl(cubeMesh());
  text.resize(text.size() / 2);
  auto loaded = loadMesh(writeFile(dir, "half.stl", text));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
}

TEST(MeshIo, StlWithNanCoordinateIsNonFinite) {
  const std::string dir = scratchDirectory("MeshIo.NanStl");
  std::string text = asciiStl(cubeMesh());
  text.replace(text.find("vertex 0 0 0"), 12, "vertex 0 nan 0");
  auto loaded = loadMesh(writeFile(dir, "nan.stl", text));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NonFiniteVertex);
}

// --- OFF, OBJ, PLY -------------------------------------------------------------------------------

TEST(MeshIo, OffCubeLoadsWithoutDefects) {
  const std::string dir = scratchDirectory("MeshIo.Off");
  auto loaded = loadMesh(writeFile(dir, "cube.off", cubeOff()));
  expectCube(loaded);
  EXPECT_TRUE(loaded->report.defects.empty());
}

TEST(MeshIo, OffWithCommentsColoursAndCountsOnTheKeywordLineIsRead) {
  const std::string dir = scratchDirectory("MeshIo.OffVariants");
  std::string text = cubeOff();
  text.replace(0, 11, "COFF 8 12 0\n# a comment\n\n");
  // Vertex colours after each coordinate triple.
  std::string withColours;
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  while (std::getline(lines, line)) {
    if (lineNumber >= 3 && lineNumber < 11) line += " 255 0 0 255";
    withColours += line + "\n";
    ++lineNumber;
  }
  expectCube(loadMesh(writeFile(dir, "cube.off", withColours)));
}

TEST(MeshIo, OffWithAbsurdCountsIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.AbsurdOff");
  auto loaded = loadMesh(writeFile(dir, "absurd.off", "OFF\n2000000000 40000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(loaded.error().message.find("more than a file of"), std::string::npos) << loaded.error().message;
}

TEST(MeshIo, OffAnnouncingMoreFacesThanTheLimitIsTooLarge) {
  const std::string dir = scratchDirectory("MeshIo.LargeOff");
  auto loaded = loadMesh(writeFile(dir, "large.off", "OFF\n3 999999999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::TooLarge);
}

TEST(MeshIo, TruncatedOffIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.TruncatedOff");
  std::string text = cubeOff();
  text.resize(text.size() - 20);
  auto loaded = loadMesh(writeFile(dir, "cut.off", text));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(loaded.error().message.find("truncated"), std::string::npos) << loaded.error().message;
}

TEST(MeshIo, OffFaceWithAVertexIndexOutOfRangeIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.OffIndex");
  std::string text = cubeOff();
  text.replace(text.rfind("3 1 6 5"), 7, "3 1 6 8");
  auto loaded = loadMesh(writeFile(dir, "index.off", text));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(loaded.error().message.find("numbered 0 to 7"), std::string::npos) << loaded.error().message;
}

TEST(MeshIo, OffWithNanCoordinateIsNonFinite) {
  const std::string dir = scratchDirectory("MeshIo.NanOff");
  std::string text = cubeOff();
  text.replace(text.find("10 10 10"), 8, "10 nan 10");
  auto loaded = loadMesh(writeFile(dir, "nan.off", text));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NonFiniteVertex);
}

TEST(MeshIo, ObjQuadsAreFannedIntoTriangles) {
  const std::string dir = scratchDirectory("MeshIo.ObjQuads");
  const std::string text =
      "# cube of quads, some corners with texture and normal indices\n"
      "mtllib missing.mtl\n"
      "v 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 0\nv 0 0 10\nv 10 0 10\nv 10 10 10\nv 0 10 10\n"
      "vt 0 0\nvn 0 0 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1/1/1 2/1/1 6/1/1 5/1/1\nf 4 8 7 3\nf 1 5 8 4\nf -7 -6 -2 -3\n";
  expectCube(loadMesh(writeFile(dir, "cube.obj", text)));
}

TEST(MeshIo, ObjFaceWithARepeatedCornerCountsAsDegenerate) {
  const std::string dir = scratchDirectory("MeshIo.ObjRepeated");
  std::ostringstream text;
  const TriangleMesh cube = cubeMesh();
  for (const Vec3& p : cube.vertices) text << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const Triangle& t : cube.triangles) text << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  text << "f 1 1 2\n";
  auto loaded = loadMesh(writeFile(dir, "cube.obj", text.str()));
  expectCube(loaded);
  const MeshDefect* d = findDefect(loaded->report, "degenerate-faces");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->count, 1u);
}

TEST(MeshIo, ObjFaceBeforeItsVerticesIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.ObjForward");
  auto loaded = loadMesh(writeFile(dir, "forward.obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
}

TEST(MeshIo, AsciiPlyCubeLoads) {
  const std::string dir = scratchDirectory("MeshIo.AsciiPly");
  std::ostringstream text;
  const TriangleMesh cube = cubeMesh();
  text << "ply\nformat ascii 1.0\ncomment cube\nelement vertex 8\nproperty float x\nproperty float y\n"
          "property float z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : cube.vertices) text << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const Triangle& t : cube.triangles) text << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  expectCube(loadMesh(writeFile(dir, "cube.ply", text.str())));
}

TEST(MeshIo, BinaryPlyCubeLoads) {
  const std::string dir = scratchDirectory("MeshIo.BinaryPly");
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
      "property float z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n";
  const TriangleMesh cube = cubeMesh();
  auto put = [&](const void* data, std::size_t n) { bytes.append(static_cast<const char*>(data), n); };
  for (const Vec3& p : cube.vertices)
    for (int i = 0; i < 3; ++i) {
      const auto f = static_cast<float>(p[i]);
      put(&f, 4);  // the test machine is little-endian, like every machine MultiDir targets
    }
  for (const Triangle& t : cube.triangles) {
    const unsigned char three = 3;
    put(&three, 1);
    for (std::int32_t v : t) put(&v, 4);
  }
  expectCube(loadMesh(writeFile(dir, "cube.ply", bytes)));
}

TEST(MeshIo, PlyWithAbsurdCountsIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.AbsurdPly");
  auto loaded = loadMesh(writeFile(dir, "absurd.ply",
                                   "ply\nformat binary_little_endian 1.0\nelement vertex 900000000\nproperty float x\n"
                                   "property float y\nproperty float z\nelement face 1\n"
                                   "property list uchar int vertex_indices\nend_header\n"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
}

TEST(MeshIo, TruncatedBinaryPlyIsMalformed) {
  const std::string dir = scratchDirectory("MeshIo.TruncatedPly");
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  bytes.append(3 * 12, '\0');
  bytes.push_back('\3');
  bytes.append(2 * 4, '\0');  // two of the three indices
  auto loaded = loadMesh(writeFile(dir, "cut.ply", bytes));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
}

// --- hostile and missing files ---------------------------------------------------------------------

TEST(MeshIo, GarbageBytesAreMalformedInEveryFormat) {
  const std::string dir = scratchDirectory("MeshIo.Garbage");
  for (const std::string ext : {"stl", "off", "obj", "ply"}) {
    const std::string name = "garbage." + ext;
    auto loaded = loadMesh(writeFile(dir, name, garbage(5000)));
    ASSERT_FALSE(loaded.ok()) << name;
    EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile) << name << ": " << loaded.error().describe();
    EXPECT_EQ(loaded.error().where, name);
  }
}

TEST(MeshIo, EmptyFileIsMalformedInEveryFormat) {
  const std::string dir = scratchDirectory("MeshIo.Empty");
  for (const std::string ext : {"stl", "off", "obj", "ply"}) {
    auto loaded = loadMesh(writeFile(dir, "empty." + ext, ""));
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error().code, ErrorCode::MalformedFile);
    EXPECT_EQ(loaded.error().describe(), "empty." + ext + ": the file is empty (0 bytes)");
  }
}

TEST(MeshIo, ObjWithoutFacesIsAnEmptyMesh) {
  const std::string dir = scratchDirectory("MeshIo.NoFaces");
  auto loaded = loadMesh(writeFile(dir, "points.obj", "v 0 0 0\nv 1 0 0\n"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::EmptyMesh);
}

TEST(MeshIo, MissingFileIsNotFoundAndNamed) {
  auto loaded = loadMesh("/nonexistent/folder/ghost.off");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::FileNotFound);
  EXPECT_EQ(loaded.error().where, "ghost.off");
}

TEST(MeshIo, UnknownExtensionIsUnsupported) {
  const std::string dir = scratchDirectory("MeshIo.Unknown");
  auto loaded = loadMesh(writeFile(dir, "model.3ds", cubeOff()));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::UnsupportedFormat);
  EXPECT_NE(loaded.error().message.find(".stl, .obj, .off and .ply"), std::string::npos);
}

// --- shared models ---------------------------------------------------------------------------------

TEST(MeshIo, OpenHalfTunnelIsRejectedWithItsBoundaryEdges) {
  auto loaded = loadMesh(sharedModelPath("defective/halftunnel-open.off"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::OpenBoundary);
  EXPECT_EQ(loaded.error().describe().rfind("halftunnel-open.off: not a solid: 96 open boundary edges (first: edges ", 0),
            0u)
      << loaded.error().describe();
}

TEST(MeshIo, NonManifoldBeetleIsRejected) {
  auto loaded = loadMesh(sharedModelPath("defective/beetle-nonmanifold.off"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().code, ErrorCode::NotManifold);
  EXPECT_EQ(loaded.error().where, "beetle-nonmanifold.off");
}

TEST(MeshIo, EveryClosedSharedModelLoadsCleanWithItsReadmeStatistics) {
  const std::map<std::string, std::pair<std::size_t, long long>> expected = {
      {"kitten.off", {10000, 1}},    {"fertility.off", {9000, 4}},  {"bunny.off", {6966, 0}},
      {"3holes.off", {7200, 3}},     {"cheburashka.off", {13334, 0}}, {"knight.off", {1000, 0}},
      {"fandisk.off", {14454, 0}},   {"bumpy.off", {2496, 0}},      {"screwdriver.off", {6786, 0}}};
  for (const std::string& model : multidir::test::closedSharedModels()) {
    auto loaded = loadMesh(sharedModelPath(model));
    ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
    EXPECT_TRUE(loaded->report.defects.empty()) << model << ": " << loaded->report.defects.front().description;
    const MeshStatistics& s = loaded->report.statistics;
    EXPECT_EQ(s.triangles, expected.at(model).first) << model;
    EXPECT_EQ(s.genus, expected.at(model).second) << model;
    EXPECT_EQ(s.shells, 1u) << model;
    EXPECT_TRUE(s.closed) << model;
    EXPECT_GT(s.volumeMm3, 0.0) << model;
  }
}

TEST(MeshIo, KittenIsAboutTheSizeTheReadmeGives) {
  auto loaded = loadMesh(sharedModelPath("kitten.off"));
  ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
  const Vec3 size = loaded->report.statistics.bounds.size();
  EXPECT_NEAR(size.x(), 76.0, 1.0);
  EXPECT_NEAR(size.y(), 116.0, 1.0);
  EXPECT_NEAR(size.z(), 69.0, 1.0);
}

// --- saving and round trips ------------------------------------------------------------------------

TEST(MeshIo, EveryFormatRoundTripsTheKitten) {
  const std::string dir = scratchDirectory("MeshIo.RoundTrip");
  auto original = loadMesh(sharedModelPath("kitten.off"));
  ASSERT_TRUE(original.ok()) << original.error().describe();
  const double volume = original->report.statistics.volumeMm3;
  struct Case {
    std::string file;
    SaveOptions options;
  };
  SaveOptions ascii;
  ascii.asciiStl = true;
  for (const Case& c : {Case{"kitten.stl", {}}, Case{"kitten-ascii.stl", ascii}, Case{"kitten.obj", {}},
                        Case{"kitten.off", {}}, Case{"kitten.ply", {}}}) {
    const std::string path = dir + "/" + c.file;
    const Status saved = saveMesh(original->mesh, path, c.options);
    ASSERT_TRUE(saved.ok()) << saved.error().describe();
    auto again = loadMesh(path);
    ASSERT_TRUE(again.ok()) << again.error().describe();
    EXPECT_EQ(again->mesh.faceCount(), original->mesh.faceCount()) << c.file;
    EXPECT_EQ(again->mesh.vertexCount(), original->mesh.vertexCount()) << c.file;
    // Binary STL stores floats; the text formats keep every double (OFF is read in full precision).
    const double tolerance = c.file == "kitten.stl" ? 1e-6 : 1e-9;
    EXPECT_NEAR(again->report.statistics.volumeMm3, volume, tolerance * volume) << c.file;
    EXPECT_EQ(again->report.statistics.genus, 1) << c.file;
  }
}

TEST(MeshIo, TextFormatsKeepDoublesExactly) {
  const std::string dir = scratchDirectory("MeshIo.Doubles");
  TriangleMesh cube = cubeMesh(Vec3(0.1, 0.2, 0.3), 1.0 / 3.0);
  SaveOptions ascii;
  ascii.asciiStl = true;
  ASSERT_TRUE(saveMesh(cube, dir + "/cube.stl", ascii).ok());
  auto again = loadMesh(dir + "/cube.stl");  // MultiDir's own STL reader reads doubles
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_EQ(again->mesh.vertices[0], cube.vertices[0]);
  EXPECT_NEAR(again->report.statistics.volumeMm3, signedVolume(cube), 1e-15);
}

TEST(MeshIo, SavingWithAnUnknownExtensionIsUnsupported) {
  const std::string dir = scratchDirectory("MeshIo.SaveUnknown");
  const Status saved = saveMesh(cubeMesh(), dir + "/cube.xyz");
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::UnsupportedFormat);
}

TEST(MeshIo, SavingIntoAMissingFolderFailsAndLeavesNothing) {
  const Status saved = saveMesh(cubeMesh(), "/nonexistent/folder/cube.stl");
  ASSERT_FALSE(saved.ok());
  EXPECT_EQ(saved.error().code, ErrorCode::WriteFailed);
}
