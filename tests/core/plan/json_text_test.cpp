// JSON text checked in memory: the field of a number no double holds or a token JSON lacks is named, and a
// machine profile is read without a file (issue 28: `multidir run` wrote the job's machine to a predictable
// temporary file to check it).
#include "multidir/core/plan/json_text.h"

#include <gtest/gtest.h>

#include "multidir/core/plan/plan_file.h"

namespace multidir::core {
namespace {

TEST(JsonText, NaNIsRefusedNamingItsField) {
  const Status checked = checkJsonText("{\"steps\": [{\"angles\": {\"rotaryDegrees\": NaN}}]}", "print-job.json");
  ASSERT_FALSE(checked.ok());
  EXPECT_EQ(checked.error().code, ErrorCode::MalformedFile);
  EXPECT_NE(checked.error().message.find("steps[0].angles.rotaryDegrees"), std::string::npos)
      << checked.error().message;
  EXPECT_NE(checked.error().message.find("NaN"), std::string::npos) << checked.error().message;
}

TEST(JsonText, ANumberBeyondDoubleIsRefusedNamingItsField) {
  const Status checked = checkJsonText("{\"steps\": [{}, {\"angles\": {\"rotaryDegrees\": 1e999}}]}", "print-job.json");
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().message.find("steps[1].angles.rotaryDegrees is '1e999'"), std::string::npos)
      << checked.error().message;
}

TEST(MachineProfile, ParsedFromMemoryWithTheChecksOfAFile) {
  const Result<MachineSpec> read = parseMachineProfile(
      "{\"schema\": \"multidir-machine\", \"version\": 1, \"kind\": \"4dof\", \"minAngleDegrees\": -30, "
      "\"maxAngleDegrees\": 45}",
      "machine");
  ASSERT_TRUE(read.ok()) << read.error().describe();
  EXPECT_EQ(read->kind, MachineKind::RotaryPlatform);
  EXPECT_DOUBLE_EQ(read->maxAngleDegrees, 45.0);
  const Result<MachineSpec> refused = parseMachineProfile(
      "{\"schema\": \"multidir-machine\", \"version\": 1, \"kind\": \"4dof\", \"angleStepDegrees\": -1}", "machine");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().where, "machine");
}

}  // namespace
}  // namespace multidir::core
