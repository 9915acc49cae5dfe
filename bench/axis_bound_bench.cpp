// Where a 4-DOF plan's J_G lies: for each rotation axis of an axis search, the lower bound no plan on that axis
// can go below (search/unavoidable_risky_area.h: the faces no realizable direction saves, given that every plane clears the
// platform region) and, with --full 1, the J_G of the full search on that axis alone (and with --screen 1 of
// the axis search's screen: a beam of width 1, one scale, no refinement, on the model itself). One row per axis,
// then per model the least bound, the best full search's J_G, and the axis search's own plan for comparison.
//
//   multidir_axis_bound_bench [--models kitten,bunny,...] [--axes N] [--full 0|1] [--screen 0|1] [--polish 0|1]
//                             [--range DEGREES] [--threads N] [--search 0]
// --search 0: the bounds alone (no axis search; the shares of J_G before are then not printed).
// Up is +Y for every shared model; the axes are those of decomposeWithAxisSearch (the first along +X, then
// every 180/N degrees in the platform plane). J_G is the one definition of docs/jg-definition.md.
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "multidir/core/common/units.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/search/decompose.h"
#include "search/unavoidable_risky_area.h"
#include "bench_support.h"
#include "shared_model_path.h"

using namespace multidir::core;

using multidir::bench::commaList;
using multidir::bench::processCpuSeconds;

namespace {

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> models = {"kitten", "bunny",  "fertility", "3holes",     "cheburashka",
                                     "knight", "fandisk", "bumpy",     "screwdriver"};
  MachineSpec machine;
  machine.kind = MachineKind::RotaryPlatform;
  machine.up = Vec3::UnitY();
  machine.rotationAxis = Vec3::UnitX();
  SearchOptions options;
  int axes = 36;
  bool full = false, screen = false, search = true;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--models") models = commaList(value);
    else if (flag == "--axes") axes = std::atoi(value.c_str());
    else if (flag == "--full") full = value != "0";
    else if (flag == "--screen") screen = value != "0";
    else if (flag == "--search") search = value != "0";
    else if (flag == "--polish") options.polish = value != "0";
    else if (flag == "--threads") options.threads = std::atoi(value.c_str());
    else if (flag == "--range") {
      machine.minAngleDegrees = -std::atof(value.c_str());
      machine.maxAngleDegrees = std::atof(value.c_str());
    } else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  SearchOptions screening = options;
  screening.beamWidth = 1;
  screening.volumeScales = 1;
  screening.refinementRounds = 0;
  screening.polish = false;
  std::printf("4-DOF, range %.0f to %.0f degrees in steps of %.1f, alpha %.0f, %d axes, polish %s\n",
              machine.minAngleDegrees, machine.maxAngleDegrees, machine.angleStepDegrees, options.alphaMaxDegrees, axes,
              options.polish ? "on" : "off");
  for (const std::string& name : models) {
    auto loaded = loadMesh(multidir::bench::sharedModelPath(name));
    if (!loaded.ok()) {
      std::fprintf(stderr, "%s\n", loaded.error().describe().c_str());
      return 1;
    }
    const TriangleMesh& mesh = loaded->mesh;
    const PlatformRegion platform = platformRegionFor(mesh, machine, options.platformToleranceMm);
    JobContext job;
    const double cpuBefore = processCpuSeconds();
    Result<Decomposition> searched = Error{ErrorCode::Cancelled, "not run", "bench"};
    if (search) {
      searched = decomposeWithAxisSearch(mesh, machine, options, axes, job);
      if (!searched.ok()) {
        std::fprintf(stderr, "%s: %s\n", name.c_str(), searched.error().describe().c_str());
        return 1;
      }
    }
    const double searchCpu = processCpuSeconds() - cpuBefore;
    const double before = search ? searched->jgBeforeMm2 : NAN;
    std::printf("%s: J_G before %.2f mm^2, platform region radius %.1f mm\n", name.c_str(), before, platform.radiusMm);
    std::printf("  %5s %12s %8s", "axis", "bound mm^2", "bound %");
    if (full) std::printf(" %12s %8s %7s %7s", "full mm^2", "full %", "regions", "CPU s");
    if (screen) std::printf(" %12s %8s", "screen mm^2", "screen %");
    std::printf("\n");
    // The bounds alone, timed (the axis search computes them for every axis before its full searches).
    const double boundsCpuBefore = processCpuSeconds();
    double boundSum = 0.0;
    for (int a = 0; a < axes; ++a) {
      MachineSpec spec = machine;
      const double angle = kPi * a / axes;
      spec.rotationAxis =
          (std::cos(angle) * machine.rotationAxis + std::sin(angle) * machine.up.cross(machine.rotationAxis)).normalized();
      boundSum += detail::unavoidableRiskyAreaMm2(mesh, spec, platform, options.alphaMaxDegrees, options.supportedBandMm);
    }
    std::printf("  the %d axes' bounds: %.3f CPU s (sum %.2f mm^2)\n", axes, processCpuSeconds() - boundsCpuBefore, boundSum);
    double leastBound = INFINITY, bestFull = INFINITY;
    int leastBoundAxis = -1, bestFullAxis = -1;
    for (int a = 0; a < axes; ++a) {
      const double angle = kPi * a / axes;
      MachineSpec spec = machine;
      spec.rotationAxis =
          (std::cos(angle) * machine.rotationAxis + std::sin(angle) * machine.up.cross(machine.rotationAxis)).normalized();
      const double bound =
          detail::unavoidableRiskyAreaMm2(mesh, spec, platform, options.alphaMaxDegrees, options.supportedBandMm);
      if (bound < leastBound) leastBound = bound, leastBoundAxis = a;
      std::printf("  %5.1f %12.2f %8.2f", 180.0 * a / axes, bound, 100.0 * bound / before);
      if (full) {
        JobContext axisJob;
        const double cpu = processCpuSeconds();
        const auto plan = decompose(mesh, spec, options, axisJob);
        if (!plan.ok()) {
          std::fprintf(stderr, "%s: %s\n", name.c_str(), plan.error().describe().c_str());
          return 1;
        }
        if (plan->jgAfterMm2 < bestFull) bestFull = plan->jgAfterMm2, bestFullAxis = a;
        std::printf(" %12.2f %8.2f %7zu %7.2f%s", plan->jgAfterMm2, 100.0 * plan->jgAfterMm2 / before,
                    plan->regions.size(), processCpuSeconds() - cpu, plan->jgAfterMm2 < bound - 1e-6 ? "  BELOW THE BOUND" : "");
      }
      if (screen) {
        JobContext screenJob;
        const auto plan = decompose(mesh, spec, screening, screenJob);
        if (plan.ok()) std::printf(" %12.2f %8.2f", plan->jgAfterMm2, 100.0 * plan->jgAfterMm2 / before);
      }
      std::printf("\n");
      std::fflush(stdout);
    }
    std::printf("  least bound %.2f mm^2 (%.2f %%) on axis %.1f", leastBound, 100.0 * leastBound / before,
                180.0 * leastBoundAxis / axes);
    if (search)
      std::printf("; axis search: %.2f mm^2 (%.2f %%), %zu regions, %.2f CPU s", searched->jgAfterMm2,
                  100.0 * searched->jgAfterMm2 / before, searched->regions.size(), searchCpu);
    if (full)
      std::printf("; best full search %.2f mm^2 (%.2f %%) on axis %.1f", bestFull, 100.0 * bestFull / before,
                  180.0 * bestFullAxis / axes);
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}
