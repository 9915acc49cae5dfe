// Conversion speed of `multidir robot-program`: a sliced job turned into the cell's URScript programs, repeated,
// the median reported with the moves converted and the time per million moves. Reading the job (meshes, G-code)
// is inside the time, as the command does it. Not run by ctest.
//   multidir_robot_program_bench JOB CELL [REPEATS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "multidir/robot/cell.h"
#include "multidir/robot/robot_program.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s JOB CELL [REPEATS]\n", argv[0]);
    return 2;
  }
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;
  const auto cell = multidir::robot::loadCell(argv[2]);
  if (!cell) {
    std::fprintf(stderr, "%s\n", cell.error().describe().c_str());
    return 1;
  }
  std::vector<double> seconds;
  multidir::robot::RobotJob last;
  for (int r = 0; r < repeats; ++r) {
    const auto started = std::chrono::steady_clock::now();
    auto job = multidir::robot::planRobotJob(argv[1], cell.value(), {}, multidir::core::JobContext());
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    if (!job) {
      std::fprintf(stderr, "%s\n", job.error().describe().c_str());
      return 1;
    }
    last = std::move(job).value();
  }
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  long moves = 0;
  double robot = 0, slicer = 0;
  double worstReach = 1e18;
  for (const auto& s : last.steps) {
    moves += s.moves;
    robot += s.seconds;
    slicer += s.slicerSeconds;
    worstReach = std::min(worstReach, s.reachMarginMm);
    std::printf("step %d: %d moves, reach margin %.1f mm, wrist margin %.1f deg, robot %.0f s, slicer %.0f s, "
                "filament %.1f of %.1f mm, slowdowns %d\n",
                s.step, s.moves, s.reachMarginMm, s.wristMarginDegrees, s.seconds, s.slicerSeconds, s.filamentMm,
                s.gcodeFilamentMm, s.slowdowns);
  }
  std::printf("%ld moves, median of %d: %.3f s (%.2f us per move, %.1f s per million moves); least reach margin "
              "%.1f mm; robot time %.1f min against the slicer's %.1f min\n",
              moves, repeats, median, 1e6 * median / static_cast<double>(moves),
              1e6 * median / static_cast<double>(moves), worstReach, robot / 60, slicer / 60);
  return 0;
}
