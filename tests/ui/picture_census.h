#pragma once
// Tells, pixel by pixel, what a viewer picture shows: background, the model's shade, or something else
// (platform, grid, axes). The viewer's colours are chosen so that these classes can be told apart.
#include <QColor>
#include <QImage>
#include <QRect>
#include <algorithm>
#include <cmath>
#include <vector>

#include "ui/common/region_palette.h"
#include "ui/viewer/mesh_viewer_widget.h"

namespace multidir::test {

struct PictureCensus {
  double modelFraction = 0.0;       // pixels in the model's shade range, over all pixels
  double backgroundFraction = 0.0;  // pixels matching the background gradient at their row
};

// The gradient's colour at `row` of a picture `height` pixels high (top row first).
inline QColor expectedBackground(int row, int height) {
  const QColor top = ui::MeshViewerWidget::backgroundTopColor();
  const QColor bottom = ui::MeshViewerWidget::backgroundBottomColor();
  const double t = height > 1 ? static_cast<double>(row) / (height - 1) : 0.0;
  return QColor::fromRgbF(float(top.redF() + t * (bottom.redF() - top.redF())),
                          float(top.greenF() + t * (bottom.greenF() - top.greenF())),
                          float(top.blueF() + t * (bottom.blueF() - top.blueF())));
}

inline bool isBackground(QRgb pixel, int row, int height) {
  const QColor expected = expectedBackground(row, height);
  return std::abs(qRed(pixel) - expected.red()) <= 10 && std::abs(qGreen(pixel) - expected.green()) <= 10 &&
         std::abs(qBlue(pixel) - expected.blue()) <= 10;
}

// Flat shading under white light scales the model's colour: a model pixel points the same way as the
// model colour in RGB space (the grey platform and the near-grey background do not).
inline bool isModelShade(QRgb pixel, int row, int height) {
  const double r = qRed(pixel), g = qGreen(pixel), b = qBlue(pixel);
  if (r + g + b < 120.0 || isBackground(pixel, row, height)) return false;
  const QColor model = ui::MeshViewerWidget::modelColor();
  const double mr = model.redF(), mg = model.greenF(), mb = model.blueF();
  const double cosine = (r * mr + g * mg + b * mb) /
                        (std::sqrt(r * r + g * g + b * b) * std::sqrt(mr * mr + mg * mg + mb * mb));
  return cosine > 0.998;
}

inline PictureCensus census(const QImage& picture, const QRect& region) {
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  const QRect area = region.intersected(image.rect());
  PictureCensus result;
  if (area.isEmpty()) return result;
  long long model = 0, background = 0;
  for (int y = area.top(); y <= area.bottom(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = area.left(); x <= area.right(); ++x) {
      if (isModelShade(line[x], y, image.height())) ++model;
      if (isBackground(line[x], y, image.height())) ++background;
    }
  }
  const double total = static_cast<double>(area.width()) * area.height();
  result.modelFraction = model / total;
  result.backgroundFraction = background / total;
  return result;
}

inline PictureCensus census(const QImage& picture) { return census(picture, picture.rect()); }

// The middle tenth of the picture in each direction.
inline QRect centreOf(const QImage& picture) {
  const int w = std::max(1, picture.width() / 10), h = std::max(1, picture.height() / 10);
  return {picture.width() / 2 - w / 2, picture.height() / 2 - h / 2, w, h};
}

}  // namespace multidir::test

namespace multidir::test {

// How many of the first `regionCount` palette colours cover at least `minFraction` of `picture`. A pixel
// shows region i when it points the same way as the region's colour in RGB space (flat shading under
// white light only scales a colour).
inline int regionColoursSeen(const QImage& picture, int regionCount, double minFraction) {
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  std::vector<long long> counts(static_cast<std::size_t>(std::max(0, regionCount)), 0);
  for (int y = 0; y < image.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = 0; x < image.width(); ++x) {
      const double r = qRed(line[x]), g = qGreen(line[x]), b = qBlue(line[x]);
      const double length = std::sqrt(r * r + g * g + b * b);
      if (length < 60.0 || isBackground(line[x], y, image.height())) continue;
      for (int i = 0; i < regionCount; ++i) {
        const QColor c = ui::regionColor(i);
        const double cr = c.red(), cg = c.green(), cb = c.blue();
        const double cosine = (r * cr + g * cg + b * cb) / (length * std::sqrt(cr * cr + cg * cg + cb * cb));
        if (cosine > 0.997) {
          ++counts[static_cast<std::size_t>(i)];
          break;
        }
      }
    }
  }
  const double total = static_cast<double>(image.width()) * image.height();
  int seen = 0;
  for (const long long count : counts) {
    if (count / total >= minFraction) ++seen;
  }
  return seen;
}

// The fraction of `picture`'s pixels that show `colour` under flat shading: bright enough and pointing the
// same way in RGB space (within `minCosine`).
inline double colourFraction(const QImage& picture, const QColor& colour, double minCosine = 0.997) {
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  const double cr = colour.red(), cg = colour.green(), cb = colour.blue();
  const double colourLength = std::sqrt(cr * cr + cg * cg + cb * cb);
  if (image.isNull() || colourLength == 0.0) return 0.0;
  long long count = 0;
  for (int y = 0; y < image.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = 0; x < image.width(); ++x) {
      const double r = qRed(line[x]), g = qGreen(line[x]), b = qBlue(line[x]);
      const double length = std::sqrt(r * r + g * g + b * b);
      if (length < 60.0) continue;
      if ((r * cr + g * cg + b * cb) / (length * colourLength) > minCosine) ++count;
    }
  }
  return static_cast<double>(count) / (static_cast<double>(image.width()) * image.height());
}

}  // namespace multidir::test
