// The emergency stop every printer link latches (printer/latched_emergency_stop.h), on its own: what the
// links' tests show through a simulator, here one rule at a time.
#include "printer/latched_emergency_stop.h"

#include <gtest/gtest.h>

#include <chrono>

namespace multidir::hardware {
namespace {

bool ended(const std::future<core::Status>& future) {
  return future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

TEST(LatchedEmergencyStop, ALatchedStopIsDueAndCannotBeClearedUntilConfirmed) {
  LatchedEmergencyStop stop;
  auto future = stop.latch();
  EXPECT_TRUE(stop.latched());
  EXPECT_TRUE(stop.due());
  EXPECT_EQ(stop.state().problem, "not sent yet");
  const core::Status refused = stop.clear("test printer");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, core::ErrorCode::InvalidParameter);
  EXPECT_NE(refused.error().message.find("not confirmed the emergency stop yet (not sent yet)"), std::string::npos)
      << refused.error().message;
  stop.confirm(stop.take());
  EXPECT_FALSE(stop.due());
  ASSERT_TRUE(ended(future));
  EXPECT_TRUE(future.get().ok());
  EXPECT_TRUE(stop.state().confirmed);
  EXPECT_EQ(stop.state().writes, 1u);
  EXPECT_TRUE(stop.clear("test printer").ok());
  EXPECT_FALSE(stop.latched());
}

TEST(LatchedEmergencyStop, AnAnswerToAnEarlierSendLeavesALaterStopUnconfirmed) {
  LatchedEmergencyStop stop;
  auto first = stop.latch();
  const std::uint64_t sent = stop.take();
  auto second = stop.latch();  // asked again while the first was on its way
  stop.confirm(sent);
  ASSERT_TRUE(ended(first));
  EXPECT_TRUE(first.get().ok());
  EXPECT_FALSE(ended(second));
  EXPECT_FALSE(stop.state().confirmed);
  EXPECT_TRUE(stop.due());
  EXPECT_FALSE(stop.clear("test printer").ok());
  stop.confirm(stop.take());
  ASSERT_TRUE(ended(second));
  EXPECT_TRUE(stop.state().confirmed);
}

TEST(LatchedEmergencyStop, DisconnectingEndsTheWaitersCancelledAndKeepsTheStopLatched) {
  LatchedEmergencyStop stop;
  auto future = stop.latch();
  stop.cancelWaiters("test printer");
  ASSERT_TRUE(ended(future));
  const core::Status cancelled = future.get();
  ASSERT_FALSE(cancelled.ok());
  EXPECT_EQ(cancelled.error().code, core::ErrorCode::Cancelled);
  EXPECT_NE(cancelled.error().message.find("sent first on the next connect"), std::string::npos);
  EXPECT_TRUE(stop.latched());
  EXPECT_TRUE(stop.due());
}

}  // namespace
}  // namespace multidir::hardware
