// Runs the decomposition search on the shared real models and prints one row per model:
// triangles, candidates, wall seconds, CPU seconds (all threads' user and system time, which the machine's load
// does not change), peak memory, regions, J_G before and after.
//
//   multidir_search_bench [--models kitten,bunny,...] [--machine 5dof|4dof] [--axes N] [--threads N]
//                         [--scheme beam|greedy|cgreedy] [--beam-width B] [--w W] [--scales S] [--refine ROUNDS]
//                         [--min-region-height MM] [--min-plane-gain PERCENT] [--pose auto] [--poses N]
//                         [--subdivide K] [--proxy-faces N] [--normals N] [--polish 0|1] [--polish-effort E]
//                         [--polish-finalists 0|1] [--search-tails 0|1]
// --subdivide K: each model subdivided K times first (4^K as many faces, the same surface): the scaling runs.
// --proxy-faces N: search a decimated proxy of models above N faces (0: always the full mesh).
// --polish 0: the search's plan unpolished (--no-polish); a polished plan gets a line "polish:" below its row with
// J_G before and after polishing, the plans it evaluated and its seconds (part of the row's seconds).
// --pose auto: after each --up y search, also the pose search (decomposeWithPoseSearch), on one line below:
// the chosen up, regions, J_G after as a share of the up-y J_G before, its seconds and its time over up y's (wall,
// and CPU: all threads' user and system time, which the machine's load does not change).
// --pose-searches K: poses given the full search (default 3).
// The default runs all nine shared models. J_G is the one definition of docs/jg-definition.md.
// Up is +Y for every shared model. Peak memory is the process's maximum resident set so far.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <algorithm>
#include <filesystem>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "multidir/core/search/pose_search.h"
#include "multidir/core/plan/plan_file.h"
#include "multidir/core/search/decompose.h"
#include "bench_support.h"
#include "shared_model_path.h"

using namespace multidir::core;

using multidir::bench::commaList;
using multidir::bench::processCpuSeconds;

namespace {

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// User and system time of every thread of the process: what a loaded machine does not change, unlike the wall.
}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> models = {"kitten", "bunny",  "fertility", "3holes",     "cheburashka",
                                     "knight", "fandisk", "bumpy",     "screwdriver"};
  MachineSpec machine;
  machine.up = Vec3::UnitY();
  SearchOptions options;
  int axes = 0;
  bool verbose = false;
  bool autoPose = false;
  int subdivisions = 0;  // each multiplies the faces by 4 (the same surface): the scaling runs
  PoseOptions poseOptions;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--models") models = commaList(value);
    else if (flag == "--machine") machine.kind = parseMachineKind(value).value();
    else if (flag == "--axes") axes = std::atoi(value.c_str());
    else if (flag == "--threads") options.threads = std::atoi(value.c_str());
    else if (flag == "--scheme") options.scheme = parseScheme(value).value();
    else if (flag == "--beam-width") options.beamWidth = std::atoi(value.c_str());
    else if (flag == "--w") options.minVolumeDivisor = std::atof(value.c_str());
    else if (flag == "--scales") options.volumeScales = std::atoi(value.c_str());
    else if (flag == "--diversity-offset") options.diversityOffsetMm = std::atof(value.c_str());
    else if (flag == "--diversity-cosine") options.diversityCosine = std::atof(value.c_str());
    else if (flag == "--normals") options.candidates.normalSamples = std::atoi(value.c_str());
    else if (flag == "--refine") options.refinementRounds = std::atoi(value.c_str());
    else if (flag == "--min-region-height") options.minRegionHeightMm = std::atof(value.c_str());
    else if (flag == "--min-plane-gain") options.minPlaneGainPercent = std::atof(value.c_str());
    else if (flag == "--verbose") verbose = value == "1";
    else if (flag == "--subdivide") subdivisions = std::atoi(value.c_str());
    else if (flag == "--proxy-faces") options.proxyFaces = std::atoi(value.c_str());
    else if (flag == "--polish") options.polish = value != "0";
    else if (flag == "--polish-effort") options.polishEffort = std::atoi(value.c_str());
    else if (flag == "--polish-finalists") options.polishFinalists = value == "1";
    else if (flag == "--search-tails") options.searchTails = value == "1";
    else if (flag == "--pose") autoPose = value == "auto";
    else if (flag == "--poses") poseOptions.poses = std::atoi(value.c_str());
    else if (flag == "--pose-searches") poseOptions.fullSearches = std::atoi(value.c_str());
    else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  if (machine.kind == MachineKind::RotaryPlatform) machine.rotationAxis = Vec3::UnitX();

  std::printf("machine %s, scheme %s, beam width %d, alpha %.0f, normals %d, refinement rounds %d, offset step %.1f mm, "
              "w %.0f, scales %d, polish %s%s\n",
              machineKindName(machine.kind), schemeName(options.scheme), options.beamWidth, options.alphaMaxDegrees,
              options.candidates.normalSamples, options.refinementRounds, options.candidates.offsetStepMm, options.minVolumeDivisor,
              options.volumeScales, options.polish ? ("effort " + std::to_string(options.polishEffort)).c_str() : "off",
              axes ? (", axis search over " + std::to_string(axes) + " axes").c_str() : "");
  std::printf("%-12s %9s %11s %9s %7s %9s %7s %12s %12s %8s %6s\n", "model", "triangles", "candidates", "seconds",
              "CPU s", "peak MiB", "regions", "J_G before", "J_G after", "after %", "saved");
  std::vector<double> shares;
  std::vector<double> autoShares;
  for (const std::string& name : models) {
    auto loaded = loadMesh(multidir::bench::sharedModelPath(name));
    if (!loaded.ok()) {
      std::fprintf(stderr, "%s\n", loaded.error().describe().c_str());
      return 1;
    }
    if (subdivisions > 0) {
      auto fine = subdivided(loaded->mesh, subdivisions);
      if (!fine.ok()) {
        std::fprintf(stderr, "%s\n", fine.error().describe().c_str());
        return 1;
      }
      loaded->mesh = std::move(*fine);
    }
    JobContext job;
    const double cpuBefore = processCpuSeconds();
    const auto wallBefore = std::chrono::steady_clock::now();
    auto plan = axes > 0 ? decomposeWithAxisSearch(loaded->mesh, machine, options, axes, job)
                               : decompose(loaded->mesh, machine, options, job, [&](const SearchProgress& p) {
                                   if (verbose)
                                     std::printf("    level %d: %d beams alive, best J_G %.2f, %lld scored\n", p.level,
                                                 p.beamsAlive, p.bestJgMm2, p.candidatesScored);
                                 });
    // The search alone, before the plan is saved: the wall time a user waits for it (measured here, not taken from
    // the plan's statistics, so that nothing the search leaves out of its own clock is missed) and its CPU time.
    const double planWall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallBefore).count();
    const double planCpu = processCpuSeconds() - cpuBefore;
    if (!plan.ok()) {
      std::fprintf(stderr, "%s: %s\n", name.c_str(), plan.error().describe().c_str());
      return 1;
    }
    // Every plan must save: written to a scratch folder and removed again, one of this process's own (two benches
    // side by side removed each other's).
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("multidir-bench-" + name + "-" + std::to_string(getpid()));
    PlanMetadata metadata;
    metadata.machine = machine;
    metadata.up = machine.up;
    metadata.options = options;
    const Status saved = savePlan(*plan, metadata, folder.string());
    std::filesystem::remove_all(folder);
    const double share = 100.0 * plan->jgAfterMm2 / plan->jgBeforeMm2;
    shares.push_back(share);
    std::printf("%-12s %9zu %11d %9.2f %7.2f %9.1f %7zu %12.2f %12.2f %8.2f %6s\n", name.c_str(),
                loaded->mesh.faceCount(), plan->statistics.candidatesPerLevel, planWall, planCpu, peakMemoryMiB(),
                plan->regions.size(),
                plan->jgBeforeMm2, plan->jgAfterMm2, share, saved.ok() ? "yes" : "NO");
    if (!saved.ok()) std::printf("    not saved: %s\n", saved.error().describe().c_str());
    if (const SearchStatistics& st = plan->statistics; st.jgBeforePolishMm2 >= 0)
      std::printf("  polish: J_G %.2f -> %.2f mm^2 (%.2f %% -> %.2f %%), %d plans evaluated, %.2f s\n",
                  st.jgBeforePolishMm2, plan->jgAfterMm2, 100.0 * st.jgBeforePolishMm2 / plan->jgBeforeMm2, share,
                  st.polishEvaluations, st.polishSeconds);
    if (verbose)
      for (const std::string& note : plan->statistics.notes) std::printf("    %s\n", note.c_str());
    if (verbose)
      for (std::size_t r = 0; r < plan->regions.size(); ++r) {
        const Region& region = plan->regions[r];
        std::printf("    region %zu: direction (%.3f %.3f %.3f) tilt %.1f volume %.0f risky %.2f\n", r + 1,
                    region.printingDirection.x(), region.printingDirection.y(), region.printingDirection.z(),
                    region.angles.tiltDegrees, region.volumeMm3, region.riskyAreaMm2);
      }
    if (autoPose) {
      const double searchCpu = planCpu;
      JobContext poseJob;
      const double poseCpuBefore = processCpuSeconds();
      const auto posed = decomposeWithPoseSearch(loaded->mesh, machine, options, poseOptions, poseJob);
      if (!posed.ok()) {
        std::fprintf(stderr, "%s: pose search: %s\n", name.c_str(), posed.error().describe().c_str());
        return 1;
      }
      const double autoShare = 100.0 * posed->plan.jgAfterMm2 / plan->jgBeforeMm2;
      autoShares.push_back(autoShare);
      std::printf("  auto: up (%.2f %.2f %.2f) %-7s %2zu regions, J_G %.2f -> %.2f, %.2f %% of up-y J_G before, "
                  "%.2f s (x%.1f; CPU x%.2f)%s\n",
                  posed->chosen.up.x(), posed->chosen.up.y(), posed->chosen.up.z(), poseSourceName(posed->chosen.source),
                  posed->plan.regions.size(), posed->plan.jgBeforeMm2, posed->plan.jgAfterMm2, autoShare,
                  posed->seconds, posed->seconds / std::max(1e-9, planWall),
                  (processCpuSeconds() - poseCpuBefore) / std::max(1e-9, searchCpu),
                  posed->plan.jgAfterMm2 > plan->jgAfterMm2 + 1e-6 ? "  WORSE than up y" : "");
    }
    std::fflush(stdout);
  }
  if (!autoShares.empty()) {
    std::sort(autoShares.begin(), autoShares.end());
    const std::size_t n = autoShares.size();
    std::printf("auto: median after/(up-y before) %.2f %%\n",
                n % 2 ? autoShares[n / 2] : 0.5 * (autoShares[n / 2 - 1] + autoShares[n / 2]));
  }
  if (!shares.empty()) {
    std::sort(shares.begin(), shares.end());
    const std::size_t n = shares.size();
    const double median = n % 2 ? shares[n / 2] : 0.5 * (shares[n / 2 - 1] + shares[n / 2]);
    std::printf("median after/before %.2f %%, worst %.2f %%\n", median, shares.back());
  }
  return 0;
}
