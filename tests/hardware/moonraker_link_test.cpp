// Moonraker only: the simulator's timing (addresses: printer_url_test.cpp). The behaviour every link shares is in
// printer_link_test.cpp.
#include "multidir/hardware/moonraker_link.h"

#include <gtest/gtest.h>

#include <atomic>

#include "multidir/hardware/moonraker_simulator.h"
#include "printer_test_support.h"

namespace multidir::hardware {
namespace {

// The simulator's own clock, set by the test: the print's timing follows the G-code's feed rates exactly.
TEST(MoonrakerSimulatorTiming, PrintsTheFileInTheTimeItsHeatingAndFeedRatesTake) {
  static std::atomic<long long> elapsedMs{0};
  elapsedMs = 0;
  const auto origin = std::chrono::steady_clock::now();
  MoonrakerSimulatorOptions options;
  options.speed = 1.0;
  options.steadyNow = [origin] { return origin + std::chrono::milliseconds(elapsedMs.load()); };
  MoonrakerSimulator sim(options);
  ASSERT_TRUE(sim.start().ok());
  const std::string gcode = test::shortGcodeFile("simulator-timing");
  auto link = test::moonrakerLinkTo(sim.port());
  ASSERT_TRUE(link->connect().ok());
  ASSERT_TRUE(test::outcome(link->upload(gcode, "step-01.gcode")).ok());
  ASSERT_TRUE(test::outcome(link->startPrint("step-01.gcode")).ok());
  // M109 S200 from 22 C at 10 C/s ends within 1 C of 200: 17.7 s. Then 0.015 s to the first layer's height and
  // 20 moves of 10 mm (the first) or sqrt(101) mm at 1200 mm/min: 10.047 s. Done at 27.762 s.
  elapsedMs = 17600;
  SimulatedPrinterState s = sim.state();
  EXPECT_EQ(s.jobState, "printing");
  EXPECT_NEAR(s.extruder.actualC, 198.0, 1e-6);
  const double heatingProgress = s.progress;
  elapsedMs = 22700;  // 5 s into the moves: about half of them
  s = sim.state();
  EXPECT_GT(s.progress, heatingProgress + 0.3);
  EXPECT_LT(s.progress, 0.8);
  elapsedMs = 27700;
  EXPECT_EQ(sim.state().jobState, "printing");
  elapsedMs = 27800;
  s = sim.state();
  EXPECT_EQ(s.jobState, "complete");
  EXPECT_DOUBLE_EQ(s.progress, 1.0);
}

}  // namespace
}  // namespace multidir::hardware
