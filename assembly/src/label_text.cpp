// Seven-segment digits as strokes, and the boxes a label removes (docs/apart.md, "Part numbers"): no font
// library, and strokes that never touch, so every box is a shell of its own in one boolean.
#include <array>
#include <cmath>

#include "multidir/assembly/part_labels.h"

namespace multidir::assembly {

namespace {

core::Error bad(const std::string& field, const std::string& rule) {
  return core::Error{core::ErrorCode::InvalidParameter, field + " " + rule, field};
}

// Segments a..g of a seven-segment digit (a top, b upper right, c lower right, d bottom, e lower left,
// f upper left, g middle), per digit 0..9.
constexpr std::array<const char*, 10> kSegments = {"abcdef", "bc", "abged", "abgcd", "fgbc",
                                                   "afgcd",  "afgedc", "abc", "abcdefg", "abcdfg"};

double strokeWidth(double heightMm, const LabelOptions& o) { return std::max(o.minStrokeMm, o.strokeShare * heightMm); }

// How far outside its face a label's box reaches, so the boolean never meets the face in a plane.
constexpr double kToolMarginMm = 0.5;

}  // namespace

core::Status validate(const LabelOptions& o) {
  if (o.heightsMm.empty()) return bad("label heights", "must name at least one height");
  for (double h : o.heightsMm)
    if (!(h >= 2 && h <= 100)) return bad("label height", "must be between 2 and 100 mm");
  if (!(o.widthShare >= 0.3 && o.widthShare <= 2)) return bad("label width share", "must be between 0.3 and 2");
  if (!(o.spacingShare >= 0 && o.spacingShare <= 2)) return bad("label spacing share", "must be between 0 and 2");
  if (!(o.minStrokeMm >= 0.2 && o.minStrokeMm <= 10)) return bad("label stroke", "must be between 0.2 and 10 mm");
  if (!(o.strokeShare > 0 && o.strokeShare <= 0.3)) return bad("label stroke share", "must be above 0, at most 0.3");
  if (!(o.gapMm >= 0.1 && o.gapMm <= 5)) return bad("label gap", "must be between 0.1 and 5 mm");
  if (!(o.depthMm >= 0.1 && o.depthMm <= 10)) return bad("label depth", "must be between 0.1 and 10 mm");
  if (!(o.marginMm >= 0 && o.marginMm <= 20)) return bad("label margin", "must be between 0 and 20 mm");
  for (double h : o.heightsMm)
    if (!(o.widthShare * h - 2.0 * (strokeWidth(h, o) + o.gapMm) > 0))
      return bad("label height", "leaves no room for a digit's horizontals between its verticals: make it taller");
  return core::Done{};
}

Eigen::Vector2d textSize(const std::string& text, double heightMm, const LabelOptions& o) {
  const auto n = static_cast<double>(text.size());
  const double width = o.widthShare * heightMm;
  return {n * width + std::max(0.0, n - 1) * o.spacingShare * heightMm, heightMm};
}

std::vector<Stroke> textStrokes(const std::string& text, double h, const LabelOptions& o) {
  std::vector<Stroke> strokes;
  const double w = o.widthShare * h, s = strokeWidth(h, o), g = o.gapMm;
  // The verticals run each half of the digit's height, a gap apart at the middle, so a 1 reads as one bar
  // broken once; the horizontals stand between them, a gap from each.
  const double mid = 0.5 * h;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] < '0' || text[k] > '9') continue;
    const double x0 = static_cast<double>(k) * (w + o.spacingShare * h);
    auto box = [&](double xa, double ya, double xb, double yb) {
      strokes.push_back({Eigen::Vector2d(x0 + xa, ya), Eigen::Vector2d(x0 + xb, yb)});
    };
    const double inner0 = s + g, inner1 = w - s - g;
    for (const char* c = kSegments[static_cast<std::size_t>(text[k] - '0')]; *c; ++c) switch (*c) {
        case 'a': box(inner0, h - s, inner1, h); break;
        case 'd': box(inner0, 0, inner1, s); break;
        case 'g': box(inner0, mid - 0.5 * s, inner1, mid + 0.5 * s); break;
        case 'f': box(0, mid + 0.5 * g, s, h); break;
        case 'b': box(w - s, mid + 0.5 * g, w, h); break;
        case 'e': box(0, 0, s, mid - 0.5 * g); break;
        case 'c': box(w - s, 0, w, mid - 0.5 * g); break;
        default: break;
      }
  }
  return strokes;
}

std::vector<core::TriangleMesh> labelTools(const PartLabel& label, const LabelOptions& o) {
  std::vector<core::TriangleMesh> tools;
  if (!label.placed) return tools;
  const Vec3 up = label.outward.cross(label.right);  // right x up = outward
  const Eigen::Vector2d half = 0.5 * textSize(label.text, label.heightMm, o);
  for (const Stroke& stroke : textStrokes(label.text, label.heightMm, o)) {
    core::TriangleMesh box;
    // Corner i at (x, y, z) bits of i, in the right-handed (right, up, outward) frame, so the faces below
    // face out of the box.
    for (int i = 0; i < 8; ++i) {
      const double x = (i & 1 ? stroke.high.x() : stroke.low.x()) - half.x();
      const double y = (i & 2 ? stroke.high.y() : stroke.low.y()) - half.y();
      const double z = i & 4 ? kToolMarginMm : -o.depthMm;
      box.vertices.push_back(label.centre + x * label.right + y * up + z * label.outward);
    }
    box.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                     {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    box.resetOrigins();
    tools.push_back(std::move(box));
  }
  return tools;
}

double labelVolumeMm3(const PartLabel& label, const LabelOptions& o) {
  if (!label.placed) return 0.0;
  double area = 0.0;
  for (const Stroke& s : textStrokes(label.text, label.heightMm, o)) area += (s.high - s.low).prod();
  return area * o.depthMm;
}

}  // namespace multidir::assembly
