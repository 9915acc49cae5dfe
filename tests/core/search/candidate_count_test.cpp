// A model in the wrong units is refused before the search allocates anything, with advice; offsets never
// overflow whatever the model's size.
#include <gtest/gtest.h>

#include "multidir/core/search/candidate_planes.h"
#include "multidir/core/search/decompose.h"
#include "support/primitives.h"

using namespace multidir::core;
using multidir::test::makeBox;

namespace {

TriangleMesh scaledBox(double size) { return makeBox(Vec3(-size / 2, -size / 2, 0), Vec3(size / 2, size / 2, size)); }

Result<Decomposition> decomposeOnce(const TriangleMesh& model) {
  JobContext job;
  return decompose(model, MachineSpec{}, SearchOptions{}, job);
}

}  // namespace

TEST(CandidateCount, ModelInMicrometresIsRefusedWithUnitsAdvice) {
  // A 100 mm part saved in micrometres reads as 100 m: 100,000 offsets for each of ~150 normals (the old
  // search asked for gigabytes and ended in bad_alloc).
  const Result<Decomposition> result = decomposeOnce(scaledBox(100'000.0));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::InvalidParameter);
  EXPECT_EQ(result.error().where, "model");
  EXPECT_NE(result.error().message.find("173.2 m wide"), std::string::npos) << result.error().describe();
  EXPECT_NE(result.error().message.find("Wrong units? Use --scale"), std::string::npos) << result.error().describe();
}

TEST(CandidateCount, ModelScaledBy1e8IsRefusedNotOverflowed) {
  const Result<Decomposition> result = decomposeOnce(scaledBox(1e10));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, ErrorCode::InvalidParameter);
}

TEST(CandidateCount, OrdinaryModelPassesTheCheck) {
  EXPECT_TRUE(checkCandidateCount(scaledBox(300.0), MachineSpec{}, CandidateOptions{}).ok());
}

TEST(CandidateCount, LargerOffsetStepAdmitsAWideModel) {
  const TriangleMesh wide = scaledBox(20'000.0);
  EXPECT_FALSE(checkCandidateCount(wide, MachineSpec{}, CandidateOptions{}).ok());
  CandidateOptions coarse;
  coarse.offsetStepMm = 100.0;
  EXPECT_TRUE(checkCandidateCount(wide, MachineSpec{}, coarse).ok());
}

TEST(CandidateCount, OffsetCountOfAHugeModelStaysBoundedAndPositive) {
  const OffsetGrid grid = candidateOffsets(scaledBox(1e10), Vec3(0, 0.6, 0.8), PlatformRegion{}, Vec3::UnitZ(),
                                           CandidateOptions{});
  EXPECT_GT(grid.count, 0);
  EXPECT_LE(grid.count, kMaxCandidatesPerLevel);
}
