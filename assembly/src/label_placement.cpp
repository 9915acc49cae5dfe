// Where each part's number goes (docs/apart.md, "Part numbers").
#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/assembly/part_labels.h"
#include "shared_face.h"

namespace multidir::assembly {

using core::TriangleMesh;

namespace {

// A hole of a part: its axis from the face to its bottom, and its radius with the chamfer.
struct Hole {
  Vec3 mouth, bottom;
  double radiusMm;
};

double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

std::vector<std::vector<Hole>> holesByPart(const core::ApartPlan& plan, const DowelLayout& layout,
                                           const DowelOptions& o) {
  std::vector<std::vector<Hole>> holes(plan.parts.size());
  for (const Dowel& dowel : layout.dowels) {
    const core::ApartJoint& joint = plan.joints[static_cast<std::size_t>(dowel.joint)];
    const double depth = dowel.holeDepthMm(o), radius = dowel.holeRadiusMm(o) + o.chamferMm;
    holes[static_cast<std::size_t>(joint.upper)].push_back({dowel.centre, dowel.centre + depth * dowel.axis, radius});
    holes[static_cast<std::size_t>(joint.lower)].push_back({dowel.centre, dowel.centre - depth * dowel.axis, radius});
  }
  return holes;
}

// Of a joint face's grid points, the centre of a label of `halfDiagonal` farthest from the face's edge and from
// the part's holes, with the part deep enough below it; nullopt when none has room.
std::optional<Point2> bestCentre(const SharedFace& face, const Frame& frame, const Vec3& outward,
                                 const TriangleMesh& part, std::int32_t planeId, const std::vector<Hole>& holes,
                                 double halfDiagonal, const LabelOptions& o) {
  std::optional<Point2> best;
  double bestRoom = -1.0;
  const Point2 size = face.high - face.low;
  const double step = std::clamp(std::max(size.x(), size.y()) / 40.0, 0.5, 2.0);
  const double reach = halfDiagonal + o.marginMm;
  const Vec3 inward = -outward;
  for (double y = face.low.y() + 0.5 * step; y < face.high.y(); y += step)
    for (double x = face.low.x() + 0.5 * step; x < face.high.x(); x += step) {
      const Point2 p(x, y);
      if (!face.contains(p)) continue;
      double room = face.distanceToBoundary(p) - reach;
      if (room < 0) continue;
      const Vec3 centre = frame.at(x, y, 0);
      for (const Hole& h : holes) room = std::min(room, pointSegmentDistance(centre, h.mouth, h.bottom) - h.radiusMm - reach);
      if (room < 0 || room <= bestRoom) continue;
      // Deep enough: the recess and the margin below it, at the centre and around the label's corners.
      double depth = depthAlong(part, planeId, centre, inward);
      for (int k = 0; k < 8; ++k) {
        const double angle = 2.0 * core::kPi * k / 8;
        depth = std::min(depth, depthAlong(part, planeId, centre + halfDiagonal * (std::cos(angle) * frame.u +
                                                                                   std::sin(angle) * frame.v),
                                           inward));
      }
      if (depth < o.depthMm + o.marginMm) continue;
      bestRoom = room;
      best = p;
    }
  return best;
}

}  // namespace

std::vector<PartLabel> placeLabels(const core::ApartPlan& plan, const DowelLayout& layout, const DowelOptions& dowels,
                                   const LabelOptions& options) {
  const std::vector<std::vector<Hole>> holes = holesByPart(plan, layout, dowels);
  std::vector<PartLabel> labels;
  for (std::size_t p = 0; p < plan.parts.size(); ++p) {
    PartLabel label;
    label.part = static_cast<int>(p);
    label.text = std::to_string(p + 1);
    const core::ApartPart& part = plan.parts[p];
    // The part's joint faces, the one facing most upward as the part is printed first: its recess is a
    // pocket open to the nozzle, where one on the bed side would be a bridge.
    struct Side {
      std::size_t joint;
      Vec3 outward;
      double facing;
    };
    std::vector<Side> sides;
    for (std::size_t j = 0; j < plan.joints.size(); ++j) {
      const core::ApartJoint& joint = plan.joints[j];
      if (joint.upper != label.part && joint.lower != label.part) continue;
      const Vec3 outward = joint.upper == label.part ? Vec3(-joint.plane.normal) : joint.plane.normal;
      sides.push_back({j, outward, outward.dot(part.printingDirection)});
    }
    std::stable_sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.facing > b.facing; });
    for (const double height : options.heightsMm) {
      const double halfDiagonal = 0.5 * textSize(label.text, height, options).norm();
      for (const Side& side : sides) {
        const core::ApartJoint& joint = plan.joints[side.joint];
        const Frame frame(joint.plane.project(Vec3::Zero()), joint.plane.normal);
        const SharedFace face = sharedFace(plan, joint, frame);
        const std::optional<Point2> at =
            bestCentre(face, frame, side.outward, part.mesh, joint.planeId, holes[p], halfDiagonal, options);
        if (!at) continue;
        label.placed = true;
        label.joint = static_cast<int>(side.joint);
        label.centre = frame.at(at->x(), at->y(), 0);
        label.outward = side.outward;
        // right x up = outward: on the plane's positive side the frame's own axes, on the other u turned over.
        label.right = side.outward.dot(frame.w) > 0 ? frame.u : Vec3(-frame.u);
        label.heightMm = height;
        break;
      }
      if (label.placed) break;
    }
    if (!label.placed)
      label.note = sides.empty() ? "the part has no joint face to carry its number"
                                 : "no joint face has room for its number beside the dowel holes: mark it by hand";
    labels.push_back(std::move(label));
  }
  return labels;
}

}  // namespace multidir::assembly
