#pragma once
// Part numbers debossed into a face of each part that gluing hides (docs/apart.md, "Part numbers"): the
// number the assembly sheet and the files give the part (part-NN), as seven-segment digits sunk into one of
// the part's joint faces, where the face has room away from its edge and from the dowel holes and the part is
// deep enough below it. A part without such room gets no number, and the sheet says so.
#include <array>
#include <string>
#include <vector>

#include "multidir/assembly/dowels.h"
#include "multidir/core/apart/apart_plan.h"
#include "multidir/core/common/result.h"

namespace multidir::assembly {

struct LabelOptions {
  std::vector<double> heightsMm = {10.0, 8.0, 6.0};  // digit heights tried, largest first
  double widthShare = 0.6;   // a digit's width per unit of height
  double spacingShare = 0.25;  // the space between two digits per unit of height
  double minStrokeMm = 0.8;  // two 0.4 mm perimeters, so a stroke prints as a groove
  double strokeShare = 0.125;  // a stroke's width per unit of height, at least minStrokeMm
  double gapMm = 0.4;  // between two segments of a digit (one nozzle width): the strokes never touch
  double depthMm = 0.6;  // three 0.2 mm layers: readable, and shallow beside the dowels' holes
  double marginMm = 1.2;  // plastic kept between the number and the face's edge, a hole or the far wall
};

core::Status validate(const LabelOptions& options);

// One segment of a digit: an axis-aligned rectangle in the text's plane (mm, x to the right, y up).
struct Stroke {
  Eigen::Vector2d low, high;
};

// The strokes of `text` (digits only) with digits `heightMm` tall, the first digit's lower left corner at
// the origin: seven-segment digits whose segments keep `gapMm` apart, so no two strokes touch or overlap.
std::vector<Stroke> textStrokes(const std::string& text, double heightMm, const LabelOptions& options);
// The box the strokes fill: width and height (mm).
Eigen::Vector2d textSize(const std::string& text, double heightMm, const LabelOptions& options);

struct PartLabel {
  int part = 0;
  std::string text;     // the part's number, "1" for part-01
  bool placed = false;  // false: no face had room, `note` says so
  int joint = -1;       // the joint whose face carries it
  Vec3 centre;          // the text's centre on the face (model frame, mm)
  Vec3 outward;         // unit normal of the face, out of the part
  Vec3 right;           // unit, along the text's lines; right x up = outward, so it reads from outside
  double heightMm = 0.0;
  std::string note;
};

// Where each part's number goes: on the face of one of its joints (the one facing most upward as the part
// is printed first, so the recess prints as a pocket rather than a bridge), at the grid point of the shared
// face farthest from the face's edge and from every hole of the part, in the largest height that fits.
std::vector<PartLabel> placeLabels(const core::ApartPlan& plan, const DowelLayout& layout,
                                   const DowelOptions& dowels, const LabelOptions& options);

// The closed solids a label removes from its part: one box per stroke, from `depthMm` below the face to a
// margin outside it (so the boolean never meets the face in a plane).
std::vector<core::TriangleMesh> labelTools(const PartLabel& label, const LabelOptions& options);
// The volume a label removes from its part (the strokes' area times the depth).
double labelVolumeMm3(const PartLabel& label, const LabelOptions& options);

// The parts with their numbers sunk in (CGAL corefinement; each result checked to be a closed, oriented
// solid). Errors: Internal naming the part.
core::Result<std::vector<core::TriangleMesh>> debossLabels(const std::vector<core::TriangleMesh>& parts,
                                                           const std::vector<PartLabel>& labels,
                                                           const LabelOptions& options);

}  // namespace multidir::assembly
