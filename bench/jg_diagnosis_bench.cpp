// Where a plan's remaining J_G lies (docs/search.md, "Where the remaining J_G lies"): runs the search on the
// shared models and sorts every risky face of the final plan by what could save it.
//
//   multidir_jg_diagnosis_bench [--models kitten,knight,...] [--normals N] [--polish 0|1] [--threads N]
//                               [--directions N] [--faces K]
//
// Per region of the plan (printing order; region 0 stands on the platform): its tilt from up, its risky area,
// and that area split by
//   - turn: how far the region's direction would have to turn for the face to be safe (the angle between the
//     face's normal and the direction, less 90 + alpha_max): < 2 degrees is what polishing's turns reach;
//   - reach: of the faces that need less than 5 degrees, those whose turned direction (d turned towards the
//     face's normal by that angle) the machine still reaches: a region at the tilt limit cannot turn further;
//   - base: faces with a corner within 1 mm of the region's base (cut plane or bed): what hangs beside a cap;
//   - cap: faces that are caps of another plane (a cut face that hangs over air);
//   - other dir: faces safe along another region's direction of the same plan (a different plane could move
//     them there);
//   - nowhere: faces risky along every direction the machine reaches (sampled, --directions on the sphere).
// --faces K: the K largest risky faces, one line each: region, area, turn, height above the region's base,
// distance to the nearest plane of the plan, and for the platform's region whether the face lies over the
// platform region P (its centre's distance from P's axis within P's radius), where no plane may pass below it.
// The plane-gain threshold is printed too: a plane added to save risky area must save at least that much.
// Then a bound for the model alone, independent of any plan: the area of the faces risky along up (above the
// bed's band) that no plane clearing the platform region P (Criterion III) can put above itself in a direction
// they are safe along: such faces stay in the platform's region or in a region they are risky in. Sampled over
// the reachable directions, and Criterion II (every piece below stands on the platform) and the minimum region
// height are left out, so it is a lower bound only up to the sampling.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "multidir/core/analysis/overhang.h"
#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/search/candidate_planes.h"
#include "multidir/core/search/decompose.h"
#include "bench_support.h"
#include "shared_model_path.h"

using namespace multidir::core;

using multidir::bench::commaList;

namespace {

double degrees(double radians) { return radians * 180.0 / kPi; }

// The highest point of the platform region P along d: P is a disc on the platform plane (normal up).
double highestOfPlatform(const PlatformRegion& p, const Vec3& up, const Vec3& d) {
  const Vec3 inPlane = d - d.dot(up) * up;
  return d.dot(p.center) + p.radiusMm * inPlane.norm();
}

struct Split {
  double total = 0, turn2 = 0, turn5 = 0, turn15 = 0, turnMore = 0, reach = 0, base = 0, cap = 0, otherDirection = 0,
         nowhere = 0;
  void add(const Split& o) {
    total += o.total, turn2 += o.turn2, turn5 += o.turn5, turn15 += o.turn15, turnMore += o.turnMore, reach += o.reach;
    base += o.base, cap += o.cap, otherDirection += o.otherDirection, nowhere += o.nowhere;
  }
};

void printSplit(const char* label, const Split& s) {
  std::printf("  %-14s %9.2f %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %9.2f %8.2f\n", label, s.total, s.turn2,
              s.turn5, s.turn15, s.turnMore, s.reach, s.base, s.cap, s.otherDirection, s.nowhere);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> models = {"kitten", "fertility", "knight"};
  MachineSpec machine;
  machine.up = Vec3::UnitY();
  SearchOptions options;
  int directionSamples = 4000;
  int faceLines = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--models") models = commaList(value);
    else if (flag == "--normals") options.candidates.normalSamples = std::atoi(value.c_str());
    else if (flag == "--polish") options.polish = value != "0";
    else if (flag == "--threads") options.threads = std::atoi(value.c_str());
    else if (flag == "--directions") directionSamples = std::atoi(value.c_str());
    else if (flag == "--faces") faceLines = std::atoi(value.c_str());
    else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  const double sinAlpha = std::sin(degToRad(options.alphaMaxDegrees));
  CandidateOptions dense;
  dense.normalSamples = directionSamples;
  std::vector<Vec3> reachable = candidateNormals(machine, dense);
  reachable.push_back(machine.up);

  for (const std::string& name : models) {
    auto loaded = loadMesh(multidir::bench::sharedModelPath(name));
    if (!loaded.ok()) {
      std::fprintf(stderr, "%s\n", loaded.error().describe().c_str());
      return 1;
    }
    const TriangleMesh& model = loaded->mesh;
    JobContext job;
    const auto plan = decompose(model, machine, options, job);
    if (!plan.ok()) {
      std::fprintf(stderr, "%s: %s\n", name.c_str(), plan.error().describe().c_str());
      return 1;
    }
    const double minGain =
        std::max(options.minPlaneGainMm2, options.minPlaneGainPercent / 100.0 * plan->jgBeforeMm2);
    std::printf("%s: J_G %.2f of %.2f mm^2 (%.3f %%), %zu regions; a plane must gain %.2f mm^2\n", name.c_str(),
                plan->jgAfterMm2, plan->jgBeforeMm2, 100.0 * plan->jgAfterMm2 / plan->jgBeforeMm2,
                plan->regions.size(), minGain);
    const PlatformRegion platform = platformRegionFor(model, machine);
    struct Face {
      double area;
      std::size_t region;
      double turn, height, planeDistance;
      bool overPlatform;
    };
    std::vector<Face> faces;
    std::printf("  %-14s %9s %8s %8s %8s %8s %8s %8s %8s %9s %8s\n", "region (tilt)", "risky", "turn<2", "2-5", "5-15",
                ">=15", "reach", "base", "cap", "other dir", "nowhere");
    Split all;
    for (std::size_t r = 0; r < plan->regions.size(); ++r) {
      const Region& region = plan->regions[r];
      const Vec3 d = region.printingDirection.normalized();
      OverhangOptions overhang;
      overhang.alphaMaxDegrees = options.alphaMaxDegrees;
      overhang.base = region.basePlane ? RegionBase::CutPlane : RegionBase::Platform;
      const auto analysis = analyzeOverhang(region.mesh, d, overhang);
      if (!analysis.ok()) return 1;
      Split s;
      for (std::size_t f = 0; f < region.mesh.faceCount(); ++f) {
        const double a = analysis->riskyFaceAreaMm2[f];
        if (!(a > 0)) continue;
        const Vec3 n = region.mesh.faceNormal(f);
        const double turn = degrees(std::acos(std::clamp(n.dot(d), -1.0, 1.0))) - 90.0 - options.alphaMaxDegrees;
        s.total += a;
        (turn < 2 ? s.turn2 : turn < 5 ? s.turn5 : turn < 15 ? s.turn15 : s.turnMore) += a;
        const Vec3 axis = d.cross(n);
        if (turn < 5 && region.basePlane && axis.norm() > 1e-9) {
          const Vec3 turned = Eigen::AngleAxisd(degToRad(turn + 0.05), axis.normalized()) * d;
          const double tilt = degrees(std::acos(std::clamp(turned.dot(machine.up), -1.0, 1.0)));
          if (tilt <= machine.maxTiltDegrees) s.reach += a;
        }
        double lowest = INFINITY;
        for (int k = 0; k < 3; ++k) lowest = std::min(lowest, d.dot(region.mesh.corner(f, k)));
        if (lowest - analysis->platformHeightMm < 1.0) s.base += a;
        double planeDistance = INFINITY;
        for (const Plane& plane : plan->clippingPlanes)
          for (int k = 0; k < 3; ++k)
            planeDistance = std::min(planeDistance, std::abs(plane.signedDistance(region.mesh.corner(f, k))));
        const Vec3 centre = (region.mesh.corner(f, 0) + region.mesh.corner(f, 1) + region.mesh.corner(f, 2)) / 3;
        const Vec3 across = (centre - platform.center) - (centre - platform.center).dot(machine.up) * machine.up;
        faces.push_back({a, r, turn, lowest - analysis->platformHeightMm, planeDistance,
                         !region.basePlane && across.norm() <= platform.radiusMm});
        if (region.mesh.origins[f].isCap()) s.cap += a;
        const bool elsewhere = std::any_of(plan->regions.begin(), plan->regions.end(), [&](const Region& other) {
          return &other != &region && n.dot(other.printingDirection.normalized()) + sinAlpha >= 0;
        });
        if (elsewhere) s.otherDirection += a;
        const bool somewhere =
            std::any_of(reachable.begin(), reachable.end(), [&](const Vec3& e) { return n.dot(e) + sinAlpha >= 0; });
        if (!somewhere) s.nowhere += a;
      }
      char label[40];
      std::snprintf(label, sizeof label, "%zu (%.0f deg)", r, degrees(std::acos(std::clamp(d.dot(machine.up), -1.0, 1.0))));
      if (s.total > 0) printSplit(label, s);
      all.add(s);
    }
    printSplit("all", all);
    std::stable_sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.area > b.area; });
    double overPlatform = 0;
    for (const Face& f : faces) overPlatform += f.overPlatform ? f.area : 0.0;
    std::printf("  risky area of the platform's region over P: %.2f mm^2 (P: radius %.1f mm)\n", overPlatform,
                platform.radiusMm);
    for (int i = 0; i < faceLines && i < static_cast<int>(faces.size()); ++i) {
      const Face& f = faces[static_cast<std::size_t>(i)];
      std::printf("    face %2d: region %zu, %.2f mm^2, turn %.1f deg, %.2f mm above its base, %.2f mm from a plane%s\n",
                  i, f.region, f.area, f.turn, f.height, f.planeDistance, f.overPlatform ? ", over P" : "");
    }

    // The bound without a plan: a risky face (along up, above the band) is saved only in a region above a plane
    // that clears P, printed along a direction it is safe along. A face all of whose corners lie at or below P's
    // highest point along every such direction cannot be put there.
    OverhangOptions upOptions;
    upOptions.alphaMaxDegrees = options.alphaMaxDegrees;
    const auto upAnalysis = analyzeOverhang(model, machine.up, upOptions);
    if (!upAnalysis.ok()) return 1;
    double bound = 0;
    for (std::size_t f = 0; f < model.faceCount(); ++f) {
      const double a = upAnalysis->riskyFaceAreaMm2[f];
      if (!(a > 0)) continue;
      const Vec3 n = model.faceNormal(f);
      const bool separable = std::any_of(reachable.begin(), reachable.end(), [&](const Vec3& e) {
        if (n.dot(e) + sinAlpha < 0) return false;
        double highest = -INFINITY;
        for (int k = 0; k < 3; ++k) highest = std::max(highest, e.dot(model.corner(f, k)));
        return highest > highestOfPlatform(platform, machine.up, e);
      });
      if (!separable) bound += a;
    }
    std::printf("  bound (Criterion III, %zu directions): %.2f mm^2 (%.3f %% of J_G before)\n", reachable.size(), bound,
                100.0 * bound / plan->jgBeforeMm2);
  }
  return 0;
}
