#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

#include "mesh/mesh_formats.h"

using namespace multidir::core;

namespace {

// A binary STL of `count` facets, facet f with corners (f, 0, 0), (f, 1, 0), (f, 0, 1).
std::string binaryStl(std::uint32_t count) {
  std::string bytes(80, ' ');
  for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<char>((count >> shift) & 0xff));
  for (std::uint32_t f = 0; f < count; ++f) {
    const float values[12] = {0, 0, 1, static_cast<float>(f), 0, 0, static_cast<float>(f), 1, 0, static_cast<float>(f), 0, 1};
    char facet[50] = {};
    std::memcpy(facet, values, sizeof values);  // little-endian, as on every machine MultiDir runs on
    bytes.append(facet, sizeof facet);
  }
  return bytes;
}

}  // namespace

TEST(StlBinaryReader, EveryFacetLandsInItsOwnSlotsAcrossChunks) {
  const std::uint32_t count = 70000;  // more than one chunk of 65,536 facets
  std::istringstream in(binaryStl(count));
  const auto soup = detail::readStl(in, 84 + 50ull * count, "many.stl", LoadOptions{});
  ASSERT_TRUE(soup.ok()) << soup.error().describe();
  ASSERT_EQ(soup->triangles.size(), count);
  ASSERT_EQ(soup->vertices.size(), 3u * count);
  for (const std::uint32_t f : {0u, 65535u, 65536u, 69999u}) {
    const auto first = static_cast<std::int32_t>(3 * f);
    EXPECT_EQ(soup->triangles[f], (Triangle{first, first + 1, first + 2}));
    EXPECT_EQ(soup->vertices[3 * f + 1], Vec3(f, 1, 0));
    EXPECT_EQ(soup->vertices[3 * f + 2], Vec3(f, 0, 1));
  }
}

TEST(StlBinaryReader, AStreamThatEndsEarlyNamesTheTriangleItEndsIn) {
  // The size says 70,000 facets (checked before reading); the stream stops inside facet 66,000.
  const std::uint32_t count = 70000;
  const std::string bytes = binaryStl(count).substr(0, 84 + 50 * 66000 + 20);
  std::istringstream in(bytes);
  const auto soup = detail::readStl(in, 84 + 50ull * count, "cut.stl", LoadOptions{});
  ASSERT_FALSE(soup.ok());
  EXPECT_EQ(soup.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(soup.error().message.find("ends inside triangle 66000"), std::string::npos) << soup.error().message;
}
