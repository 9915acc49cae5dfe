#include "ui/viewer/gcode_toolpaths.h"

#include <algorithm>

namespace multidir::ui {
namespace {

// A layer is higher than the one in progress when its z is at least this much above (slicers round z to
// 1e-3 mm; a layer is at least 0.05 mm thick).
constexpr double kLayerRiseMm = 0.01;

std::size_t prefixUpTo(const std::vector<ToolpathSegment>& segments, int layers) {
  const auto end = std::upper_bound(segments.begin(), segments.end(), layers,
                                    [](int limit, const ToolpathSegment& s) { return limit < s.layer; });
  return static_cast<std::size_t>(end - segments.begin());
}

}  // namespace

std::size_t GcodePreview::extrusionsUpTo(int layers) const { return prefixUpTo(extrusions, layers); }

std::size_t GcodePreview::travelsUpTo(int layers) const { return prefixUpTo(travels, layers); }

GcodePreview buildGcodePreview(const std::vector<StepProgram>& steps) {
  GcodePreview preview;
  preview.stepCount = static_cast<int>(steps.size());
  for (const StepProgram& step : steps) {
    const Eigen::Isometry3d toModel = step.modelToPrinter.inverse();
    const int firstLayer = preview.layerCount() + 1;  // this step's first layer, over the job
    int layerInStep = 0;                              // none yet
    double layerZ = 0.0;
    for (const slicing::GcodeMove& move : step.program.moves) {
      if (move.step != step.step || move.inTransition) continue;
      if (move.extrudes()) {
        const double z = std::max(move.from.z(), move.to.z());
        if (layerInStep == 0 || z > layerZ + kLayerRiseMm) {
          ++layerInStep;
          layerZ = z;
          preview.layers.push_back({step.step, layerInStep, z});
        }
        preview.extrusions.push_back(
            {toModel * move.from, toModel * move.to, step.step, firstLayer + layerInStep - 1, move.line});
      } else if (layerInStep > 0 && (move.movesXy() || move.movesZ())) {
        preview.travels.push_back(
            {toModel * move.from, toModel * move.to, step.step, firstLayer + layerInStep - 1, move.line});
      }
    }
  }
  return preview;
}

std::size_t markUnsupported(GcodePreview& preview, int step, const std::vector<int>& lines) {
  std::size_t marked = 0;
  for (ToolpathSegment& s : preview.extrusions) {
    if (s.step != step || !std::binary_search(lines.begin(), lines.end(), s.line)) continue;
    s.unsupported = true;
    ++marked;
  }
  return marked;
}

}  // namespace multidir::ui
