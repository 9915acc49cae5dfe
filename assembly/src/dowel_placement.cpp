// Where the dowels of each joint go (docs/apart.md, "Dowels").
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <map>

#include "geometry_kernels.h"
#include "shared_face.h"
#include "multidir/assembly/dowels.h"

namespace multidir::assembly {

using core::TriangleMesh;

namespace {

// A hole already placed in a part: its axis from the face to its bottom, and its radius with the chamfer.
struct PlacedHole {
  Vec3 mouth, bottom;
  double radiusMm;
};

double segmentsDistance(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  // Sampled: holes are short and the wall needed is millimetres, so 17 points each side is plenty.
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 16; ++i) {
    const Vec3 p = a0 + (a1 - a0) * (i / 16.0);
    const Vec3 ab = b1 - b0;
    const double t = std::clamp((p - b0).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (b0 + t * ab - p).norm());
  }
  return best;
}

struct Candidate {
  Point2 at;
  Vec3 centre;
  double lengthMm;
};

}  // namespace

DowelLayout placeDowels(const core::ApartPlan& plan, const DowelOptions& options) {
  DowelLayout layout;
  std::vector<std::vector<PlacedHole>> holes(plan.parts.size());
  const double c = options.chamferMm, wall = options.minWallMm;
  for (std::size_t j = 0; j < plan.joints.size(); ++j) {
    const core::ApartJoint& joint = plan.joints[j];
    JointDowels record;
    record.joint = static_cast<int>(j);
    const Frame frame(joint.plane.project(Vec3::Zero()), joint.plane.normal);
    const SharedFace face = sharedFace(plan, joint, frame);
    const TriangleMesh& upper = plan.parts[static_cast<std::size_t>(joint.upper)].mesh;
    const TriangleMesh& lower = plan.parts[static_cast<std::size_t>(joint.lower)].mesh;

    // Diameters: the first from the face's size, the others one key step thinner.
    const double fromFace = std::floor(options.diameterShare * std::sqrt(face.areaMm2) / 0.5) * 0.5;
    const double first = std::clamp(fromFace, options.minDiameterMm + options.keyStepMm, options.maxDiameterMm);
    const double others = std::max(options.minDiameterMm, first - options.keyStepMm);

    // The valid centres for a dowel of diameter d: inside the face with the chamfer and a wall to its edge,
    // deep enough on both sides (the longest length that is), clear of the holes already in either part.
    auto candidates = [&](double d) {
      std::vector<Candidate> valid;
      if (face.triangles.empty()) return valid;
      const double hole = 0.5 * d + options.radialClearanceMm;
      const double edgeRoom = hole + c + wall;
      const Point2 size = face.high - face.low;
      const double step = std::clamp(std::max(size.x(), size.y()) / 40.0, 0.5, 2.0);
      for (double y = face.low.y() + 0.5 * step; y < face.high.y(); y += step)
        for (double x = face.low.x() + 0.5 * step; x < face.high.x(); x += step) {
          const Point2 p(x, y);
          const bool inside = std::any_of(face.triangles.begin(), face.triangles.end(),
                                          [&](const auto& t) { return inTriangle(p, t[0], t[1], t[2]); });
          if (!inside) continue;
          const bool roomy = std::none_of(face.boundary.begin(), face.boundary.end(),
                                          [&](const auto& e) { return segmentDistance(p, e[0], e[1]) < edgeRoom; });
          if (!roomy) continue;
          const Vec3 centre = frame.at(x, y, 0);
          // Depth: at the centre the hole and a wall below it, around it (a wall out) the hole's depth.
          double depth = std::numeric_limits<double>::infinity();
          for (const auto& [part, sign] : {std::pair{&upper, 1.0}, std::pair{&lower, -1.0}}) {
            const Vec3 dir = sign * frame.w;
            depth = std::min(depth, depthAlong(*part, joint.planeId, centre, dir) - wall);
            for (int k = 0; k < 8 && depth > 0; ++k) {
              const double angle = 2.0 * core::kPi * k / 8;
              const Vec3 ring = centre + (hole + wall) * (std::cos(angle) * frame.u + std::sin(angle) * frame.v);
              depth = std::min(depth, depthAlong(*part, joint.planeId, ring, dir));
            }
          }
          // The longest of lengthRatio x d, then shorter by half diameters down to d, whose holes fit.
          double length = 0;
          for (double ratio = options.lengthRatio; ratio >= 1.0 - 1e-9; ratio -= 0.5)
            if (0.5 * ratio * d + options.depthClearanceMm <= depth) {
              length = ratio * d;
              break;
            }
          if (length <= 0) continue;
          const double holeDepth = 0.5 * length + options.depthClearanceMm;
          bool clear = true;
          for (const auto& [part, sign] : {std::pair{joint.upper, 1.0}, std::pair{joint.lower, -1.0}})
            for (const PlacedHole& h : holes[static_cast<std::size_t>(part)])
              if (segmentsDistance(centre, centre + sign * holeDepth * frame.w, h.mouth, h.bottom) <
                  hole + c + h.radiusMm + wall)
                clear = false;
          if (clear) valid.push_back({p, centre, length});
        }
      return valid;
    };

    // The rays sample the wall; a hole about to be taken is measured all over (holeWallMm) in both parts.
    const auto wallHolds = [&](const Candidate& k, double d) {
      Dowel dowel;
      dowel.centre = k.centre;
      dowel.axis = frame.w;
      dowel.diameterMm = d;
      dowel.lengthMm = k.lengthMm;
      return holeWallMm(upper, joint.planeId, dowel, true, options) >= wall &&
             holeWallMm(lower, joint.planeId, dowel, false, options) >= wall;
    };
    std::vector<Candidate> chosen;
    std::vector<double> diameters;
    std::vector<Candidate> big = candidates(first);
    std::vector<Candidate> small = options.dowelsPerJoint > 1 ? candidates(others) : std::vector<Candidate>{};
    const double apart = (0.5 * first + 0.5 * others) + 2.0 * (options.radialClearanceMm + c) + wall;
    // Two dowels as far apart as the face allows: they keep the parts from turning.
    double bestGap = -1;
    std::size_t bi = 0, si = 0;
    for (int attempt = 0; attempt < 64; ++attempt) {
      bestGap = -1;
      for (std::size_t a = 0; a < big.size(); ++a)
        for (std::size_t b = 0; b < small.size(); ++b) {
          const double gap = (big[a].at - small[b].at).norm();
          if (gap >= apart && gap > bestGap) {
            bestGap = gap;
            bi = a;
            si = b;
          }
        }
      if (bestGap < 0) break;
      const bool bigHolds = wallHolds(big[bi], first), smallHolds = wallHolds(small[si], others);
      if (bigHolds && smallHolds) break;
      if (!bigHolds) big.erase(big.begin() + static_cast<std::ptrdiff_t>(bi));
      if (!smallHolds) small.erase(small.begin() + static_cast<std::ptrdiff_t>(si));
      bestGap = -1;
    }
    if (bestGap > 0) {
      chosen = {big[bi], small[si]};
      diameters = {first, others};
      // More, each as far from the chosen ones as can be.
      while (static_cast<int>(chosen.size()) < options.dowelsPerJoint) {
        double farthest = -1;
        std::size_t pick = 0;
        for (std::size_t b = 0; b < small.size(); ++b) {
          double nearest = INFINITY;
          for (const Candidate& k : chosen) nearest = std::min(nearest, (k.at - small[b].at).norm());
          const double need = others + 2.0 * (options.radialClearanceMm + c) + wall;
          if (nearest >= need && nearest > farthest && wallHolds(small[b], others)) {
            farthest = nearest;
            pick = b;
          }
        }
        if (farthest < 0) break;
        chosen.push_back(small[pick]);
        diameters.push_back(others);
      }
    } else {
      // One dowel: the thinnest that fits, as central as it can be (the valid point nearest the middle).
      for (const double d : {first, others}) {
        std::vector<Candidate> one = d == first ? big : candidates(d);
        const Point2 middle = 0.5 * (face.low + face.high);
        std::stable_sort(one.begin(), one.end(), [&](const Candidate& a, const Candidate& b) {
          return (a.at - middle).norm() < (b.at - middle).norm();
        });
        for (std::size_t k = 0; k < one.size() && k < 64 && chosen.empty(); ++k)
          if (wallHolds(one[k], d)) {
            chosen = {one[k]};
            diameters = {d};
          }
        if (!chosen.empty()) break;
      }
      char text[96];
      std::snprintf(text, sizeof text, "the face has no room for a dowel of %.1f mm: glue it without", others);
      record.note = chosen.empty() ? std::string(text) : "the face has room for one dowel only";
    }
    if (static_cast<int>(chosen.size()) < options.dowelsPerJoint && record.note.empty())
      record.note = "the face has room for " + std::to_string(chosen.size()) + " dowels";
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      Dowel dowel;
      dowel.joint = static_cast<int>(j);
      dowel.centre = chosen[k].centre;
      dowel.axis = frame.w;
      dowel.diameterMm = diameters[k];
      dowel.lengthMm = chosen[k].lengthMm;
      const double depth = dowel.holeDepthMm(options), radius = dowel.holeRadiusMm(options) + c;
      holes[static_cast<std::size_t>(joint.upper)].push_back({dowel.centre, dowel.centre + depth * frame.w, radius});
      holes[static_cast<std::size_t>(joint.lower)].push_back({dowel.centre, dowel.centre - depth * frame.w, radius});
      layout.dowels.push_back(dowel);
    }
    record.count = static_cast<int>(chosen.size());
    layout.joints.push_back(record);
  }
  return layout;
}

}  // namespace multidir::assembly
