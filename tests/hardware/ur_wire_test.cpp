// UR's binary formats: the real-time package's size and field offsets, robot messages read back as written.
#include "ur/ur_wire.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

using namespace multidir::hardware::ur;

double doubleAt(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits = (bits << 8) | bytes[offset + static_cast<std::size_t>(i)];
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

TEST(UrWire, TheRealTimePackageHasUrsSizeAndOffsets) {
  UrRealtimeState s;
  s.time = 12.5;
  s.qActual = {0.1, -1.2, 1.3, -1.4, 1.5, -1.6};
  s.toolVectorActual = {0.4, -0.1, 0.3, 0.0, 3.1, 0.0};
  s.robotMode = UrRobotMode::Running;
  s.safetyMode = UrSafetyMode::ProtectiveStop;
  s.programState = UrProgramState::Playing;
  const std::vector<std::uint8_t> bytes = encodeRealtime(s);
  ASSERT_EQ(bytes.size(), 1108u);
  EXPECT_EQ(packageSize(bytes.data(), bytes.size()), 1108u);
  // UR's Client Interface: time at byte 4, q actual at 252, tool vector actual at 444, robot mode at 756,
  // safety mode at 812, program state at 1052.
  EXPECT_DOUBLE_EQ(doubleAt(bytes, 4), 12.5);
  EXPECT_DOUBLE_EQ(doubleAt(bytes, 252 + 8), -1.2);
  EXPECT_DOUBLE_EQ(doubleAt(bytes, 444 + 32), 3.1);
  EXPECT_DOUBLE_EQ(doubleAt(bytes, 756), 7.0);
  EXPECT_DOUBLE_EQ(doubleAt(bytes, 812), 3.0);
  EXPECT_DOUBLE_EQ(doubleAt(bytes, 1052), 2.0);
  const auto back = decodeRealtime(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->qActual, s.qActual);
  EXPECT_EQ(back->safetyMode, UrSafetyMode::ProtectiveStop);
  EXPECT_EQ(back->programState, UrProgramState::Playing);
  EXPECT_FALSE(decodeRealtime(bytes.data(), 1000));
}

TEST(UrWire, ARuntimeExceptionReadsBackWithItsLineColumnAndText) {
  UrRobotMessage m;
  m.kind = UrRobotMessage::Kind::RuntimeException;
  m.timestampUs = 123456;
  m.line = 7;
  m.column = 3;
  m.text = "Compile error: 'servoj' is not in the subset";
  const std::vector<std::uint8_t> bytes = encodeRobotMessage(m);
  EXPECT_EQ(packageSize(bytes.data(), bytes.size()), bytes.size());
  EXPECT_EQ(bytes[4], 20);   // robot message
  EXPECT_EQ(bytes[14], 10);  // runtime exception
  const auto back = decodeRobotMessage(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->kind, UrRobotMessage::Kind::RuntimeException);
  EXPECT_EQ(back->line, 7);
  EXPECT_EQ(back->column, 3);
  EXPECT_EQ(back->text, m.text);
  EXPECT_EQ(back->timestampUs, 123456u);
}

}  // namespace
