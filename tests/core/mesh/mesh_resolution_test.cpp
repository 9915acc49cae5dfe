#include <gtest/gtest.h>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "support/test_models.h"

using namespace multidir::core;

TEST(Subdivided, EachLevelQuadruplesTheFacesAndKeepsTheSolid) {
  const TriangleMesh kitten = multidir::test::loadSharedModel("kitten.off");
  const auto fine = subdivided(kitten, 2);
  ASSERT_TRUE(fine.ok()) << fine.error().message;
  EXPECT_EQ(fine->faceCount(), kitten.faceCount() * 16);
  EXPECT_TRUE(edgeCensus(*fine).closedOriented());
  EXPECT_NEAR(signedVolume(*fine), signedVolume(kitten), 1e-9 * signedVolume(kitten));
  EXPECT_NEAR(surfaceArea(*fine), surfaceArea(kitten), 1e-9 * surfaceArea(kitten));
}

TEST(Subdivided, TooManyLevelsAreRefusedByName) {
  const auto refused = subdivided(multidir::test::loadSharedModel("kitten.off"), 7);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::InvalidParameter);
}
