// Slicer runs side by side: their results come back in the tasks' order whatever order they finish in, runs
// going at the same time are each on a CPU of their own, and a thread allowed a single CPU runs them all on it.
#include "multidir/slicing/side_by_side.h"

#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "multidir/slicing/child_process.h"

using namespace multidir;
using namespace multidir::slicing;

namespace {

// A stand-in engine: each run takes longer the earlier its task (so later tasks finish first), answers with its
// mesh file's name as its G-code, and notes the CPU each run was given and which CPUs were busy at once.
class RecordingEngine : public SlicerEngine {
 public:
  explicit RecordingEngine(std::size_t taskCount) : m_taskCount(taskCount) {}
  std::string name() const override { return "recording"; }

  core::Result<SliceRun> slice(const SliceRequest& request, core::JobContext&) const override {
    const int cpu = request.cpu.value_or(-1);
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      cpus.push_back(cpu);
      started.push_back(request.meshFile);
      if (!busy.insert(cpu).second) sharedCpu = true;
      mostAtOnce = std::max(mostAtOnce, busy.size());
    }
    const std::size_t index = std::stoul(request.meshFile.substr(request.meshFile.find('-') + 1));
    std::this_thread::sleep_for(std::chrono::milliseconds(40 * (m_taskCount - index)));
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      busy.erase(cpu);
    }
    SliceRun run;
    run.gcode = request.meshFile;
    return run;
  }

  mutable std::vector<int> cpus;      // the CPU given to each run, in the order they started
  mutable std::vector<std::string> started;  // the runs' mesh files, in the order they started
  mutable std::set<int> busy;         // CPUs of the runs under way
  mutable std::size_t mostAtOnce = 0;
  mutable bool sharedCpu = false;     // two runs were given the same CPU at the same time

 private:
  std::size_t m_taskCount;
  mutable std::mutex m_mutex;
};

std::vector<SliceTask> tasksNamed(std::size_t count) {
  std::vector<SliceTask> tasks(count);
  for (std::size_t i = 0; i < count; ++i) tasks[i].request.meshFile = "step-" + std::to_string(i);
  return tasks;
}

}  // namespace

TEST(SideBySide, ResultsComeBackInTheTasksOrderWhateverOrderTheyFinishIn) {
  std::vector<SliceTask> tasks = tasksNamed(4);
  const RecordingEngine engine(tasks.size());
  core::JobContext context;
  ASSERT_TRUE(runSideBySide(engine, tasks, tasks.size(), static_cast<double>(tasks.size()), context).ok());
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    ASSERT_TRUE(tasks[i].run.has_value()) << "task " << i;
    EXPECT_EQ(tasks[i].run->gcode, "step-" + std::to_string(i));
  }
}

TEST(SideBySide, RunsGoingAtTheSameTimeAreEachOnAUsableCpuOfTheirOwn) {
  const std::vector<int> usable = usableCpus();
  std::vector<SliceTask> tasks = tasksNamed(2 * usable.size() + 1);
  const RecordingEngine engine(tasks.size());
  core::JobContext context;
  ASSERT_TRUE(runSideBySide(engine, tasks, tasks.size(), static_cast<double>(tasks.size()), context).ok());
  ASSERT_EQ(engine.cpus.size(), tasks.size());
  for (int cpu : engine.cpus)
    EXPECT_TRUE(std::find(usable.begin(), usable.end(), cpu) != usable.end()) << "CPU " << cpu << " is not usable";
  EXPECT_FALSE(engine.sharedCpu);
  EXPECT_EQ(engine.mostAtOnce, usable.size());  // side by side: one run per usable CPU
}

TEST(SideBySide, AThreadAllowedASingleCpuRunsEveryTaskOnItOneAfterTheOther) {
  const int only = usableCpus().back();
  std::vector<SliceTask> tasks = tasksNamed(3);
  const RecordingEngine engine(tasks.size());
  bool ran = false;
  // The one-CPU machine: a thread whose affinity allows one CPU (what usableCpus() reads).
  std::thread oneCpu([&] {
    cpu_set_t mask;
    CPU_ZERO(&mask);
    CPU_SET(static_cast<std::size_t>(only), &mask);
    ASSERT_EQ(::pthread_setaffinity_np(::pthread_self(), sizeof mask, &mask), 0);
    ASSERT_EQ(usableCpus(), std::vector<int>{only});
    core::JobContext context;
    ran = runSideBySide(engine, tasks, tasks.size(), static_cast<double>(tasks.size()), context).ok();
  });
  oneCpu.join();
  ASSERT_TRUE(ran);
  EXPECT_EQ(engine.cpus, std::vector<int>(tasks.size(), only));
  EXPECT_EQ(engine.mostAtOnce, 1u);
  for (std::size_t i = 0; i < tasks.size(); ++i) EXPECT_EQ(tasks[i].run->gcode, "step-" + std::to_string(i));
}

TEST(SideBySide, TheComparisonStartsBeforeTheStepsSoThatItDoesNotEndAlone) {
  std::vector<SliceTask> tasks = tasksNamed(4);  // steps 0 to 2, then the comparison
  const RecordingEngine engine(tasks.size());
  bool ran = false;
  std::thread oneCpu([&] {  // one worker: the start order is the order the tasks are taken in
    cpu_set_t mask;
    CPU_ZERO(&mask);
    CPU_SET(static_cast<std::size_t>(usableCpus().front()), &mask);
    ASSERT_EQ(::pthread_setaffinity_np(::pthread_self(), sizeof mask, &mask), 0);
    core::JobContext context;
    ran = runSideBySide(engine, tasks, 3, 4.0, context).ok();
  });
  oneCpu.join();
  ASSERT_TRUE(ran);
  EXPECT_EQ(engine.started, (std::vector<std::string>{"step-3", "step-0", "step-1", "step-2"}));
  for (std::size_t i = 0; i < tasks.size(); ++i) EXPECT_EQ(tasks[i].run->gcode, "step-" + std::to_string(i));
}
