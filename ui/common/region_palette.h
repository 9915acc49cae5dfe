#pragma once
// Colours of a plan's regions, shared by the 3D view, the legend and the tests: 16 hues far enough apart
// to tell neighbouring regions apart, none of them close to the model's grey-blue or the overhang colour.
#include <QColor>

namespace multidir::ui {

// Number of distinct colours; region i gets colour i modulo this.
constexpr int kRegionColorCount = 16;

// The colour of region `index` (0 = printed first). A negative index counts as 0.
[[nodiscard]] QColor regionColor(int index);

// The colour of support structures: one for every region, a blue-violet whose hue is far from every region
// colour (and from blends of two of them), the model's grey-blue, the platform and the background.
[[nodiscard]] QColor supportColor();

// The G-code preview's warning colour for extrusions that rest on nothing printed before them (the audit's
// check (b)): a saturated magenta between the palette's red and its pink-violet, far from both.
[[nodiscard]] QColor unsupportedExtrusionColor();

}  // namespace multidir::ui
