// The reach map's slice through the best position as a picture, with its colour bar (docs/robot-cell.md, "Reach
// map"). Pixels only: the command encodes them as PNG.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "multidir/robot/reach_map.h"

namespace multidir::robot {
namespace {

constexpr std::array<std::uint8_t, 3> kUnsampled = {225, 225, 225};
constexpr std::array<std::uint8_t, 3> kBlack = {0, 0, 0};
constexpr int kBarWidth = 16;
constexpr int kBarGap = 16;
constexpr int kTextScale = 2;  // the legend's 3x5 glyphs drawn with squares of this many pixels

// 3x5 glyphs of the legend's marks, rows from the top, bit 2 the left column.
struct Glyph {
  char c;
  std::array<std::uint8_t, 5> rows;
};
constexpr Glyph kGlyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'5', {7, 4, 7, 1, 7}}, {'%', {5, 1, 2, 4, 5}},
};

struct Canvas {
  ReachSlice& slice;
  void set(int x, int y, const std::array<std::uint8_t, 3>& c) {
    if (x < 0 || y < 0 || x >= slice.width || y >= slice.height) return;
    const std::size_t at = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(slice.width) + static_cast<std::size_t>(x));
    slice.rgb[at] = c[0];
    slice.rgb[at + 1] = c[1];
    slice.rgb[at + 2] = c[2];
  }
  void fill(int x0, int y0, int w, int h, const std::array<std::uint8_t, 3>& c) {
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) set(x, y, c);
  }
  void frame(int x0, int y0, int w, int h, const std::array<std::uint8_t, 3>& c) {
    for (int x = x0; x < x0 + w; ++x) {
      set(x, y0, c);
      set(x, y0 + h - 1, c);
    }
    for (int y = y0; y < y0 + h; ++y) {
      set(x0, y, c);
      set(x0 + w - 1, y, c);
    }
  }
  // Text with its top-left corner at (x0, y0).
  void text(int x0, int y0, const std::string& s) {
    for (std::size_t i = 0; i < s.size(); ++i)
      for (const Glyph& g : kGlyphs) {
        if (g.c != s[i]) continue;
        for (int r = 0; r < 5; ++r)
          for (int col = 0; col < 3; ++col)
            if (g.rows[static_cast<std::size_t>(r)] & (4 >> col))
              fill(x0 + static_cast<int>(i) * 4 * kTextScale + col * kTextScale, y0 + r * kTextScale, kTextScale,
                   kTextScale, kBlack);
      }
  }
};

}  // namespace

std::array<std::uint8_t, 3> reachColour(double score) {
  const double s = std::clamp(score, 0.0, 1.0);
  return {static_cast<std::uint8_t>(std::lround(255 * (1.0 - s))), 0, static_cast<std::uint8_t>(std::lround(255 * s))};
}

std::array<int, 2> ReachSlice::pixelOf(double xMm, double yMm) const {
  const int column = static_cast<int>(std::lround((xMm - leftXMm) / gridMm));
  const int row = static_cast<int>(std::lround((topYMm - yMm) / gridMm));
  return {kMarginPixels + column * kPixelsPerCell + kPixelsPerCell / 2,
          kMarginPixels + row * kPixelsPerCell + kPixelsPerCell / 2};
}

ReachSlice reachSlice(const ReachMap& map, double gridMm) {
  ReachSlice slice;
  slice.gridMm = gridMm;
  slice.zMm = map.best.nozzleTipMm.z();
  double minX = std::numeric_limits<double>::infinity(), maxX = -minX, minY = minX, maxY = -minX;
  for (const auto& p : map.points) {
    minX = std::min(minX, p.nozzleTipMm.x());
    maxX = std::max(maxX, p.nozzleTipMm.x());
    minY = std::min(minY, p.nozzleTipMm.y());
    maxY = std::max(maxY, p.nozzleTipMm.y());
  }
  if (map.points.empty()) minX = maxX = minY = maxY = 0.0;
  slice.leftXMm = minX;
  slice.topYMm = maxY;
  slice.columns = static_cast<int>(std::lround((maxX - minX) / gridMm)) + 1;
  slice.rows = static_cast<int>(std::lround((maxY - minY) / gridMm)) + 1;
  const int mapWidth = slice.columns * ReachSlice::kPixelsPerCell;
  const int mapHeight = slice.rows * ReachSlice::kPixelsPerCell;
  const int legendWidth = kBarGap + kBarWidth + 4 + 4 * 4 * kTextScale;  // bar, gap and "100%"
  slice.width = 2 * ReachSlice::kMarginPixels + mapWidth + legendWidth;
  slice.height = 2 * ReachSlice::kMarginPixels + std::max(mapHeight, 5 * kTextScale * 3);
  slice.rgb.assign(3 * static_cast<std::size_t>(slice.width) * static_cast<std::size_t>(slice.height), 255);
  Canvas canvas{slice};
  const int m = ReachSlice::kMarginPixels, cell = ReachSlice::kPixelsPerCell;
  canvas.fill(m, m, mapWidth, mapHeight, kUnsampled);
  for (const auto& p : map.points) {
    if (std::abs(p.nozzleTipMm.z() - slice.zMm) > 0.5 * gridMm) continue;
    const auto centre = slice.pixelOf(p.nozzleTipMm.x(), p.nozzleTipMm.y());
    canvas.fill(centre[0] - cell / 2, centre[1] - cell / 2, cell, cell, reachColour(p.score));
  }
  if (!map.points.empty()) {
    const auto best = slice.pixelOf(map.best.nozzleTipMm.x(), map.best.nozzleTipMm.y());
    canvas.frame(best[0] - cell / 2, best[1] - cell / 2, cell, cell, kBlack);
  }
  // The colour bar: 100 % at the top, 0 at the bottom, marks beside it.
  const int barX = m + mapWidth + kBarGap;
  const int barHeight = std::max(mapHeight, 5 * kTextScale * 3);
  for (int y = 0; y < barHeight; ++y)
    canvas.fill(barX, m + y, kBarWidth, 1, reachColour(1.0 - static_cast<double>(y) / std::max(1, barHeight - 1)));
  canvas.frame(barX - 1, m - 1, kBarWidth + 2, barHeight + 2, kBlack);
  const int textX = barX + kBarWidth + 4;
  canvas.text(textX, m, "100%");
  canvas.text(textX, m + barHeight / 2 - 5 * kTextScale / 2, "50");
  canvas.text(textX, m + barHeight - 5 * kTextScale, "0");
  return slice;
}

}  // namespace multidir::robot
