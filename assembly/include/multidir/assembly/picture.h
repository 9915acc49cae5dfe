#pragma once
// Pictures for the assembly sheet without a GUI library (docs/apart.md, "Assembly sheet"): an orthographic view
// of coloured meshes, rasterized in software with a depth buffer and flat shading, and written as PNG (zlib).
#include <cstdint>
#include <string>
#include <vector>

#include "multidir/core/common/result.h"
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::assembly {

using Colour = Eigen::Vector3d;  // red, green, blue in [0, 1]

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // row by row from the top, three bytes a pixel
  Colour at(int x, int y) const;
};

struct ColouredMesh {
  const core::TriangleMesh* mesh = nullptr;
  Colour colour;
  core::Vec3 shift = core::Vec3::Zero();  // moved by this before drawing (an exploded view)
};

// A text drawn over the picture at a point of the model, in the seven-segment digits of the part numbers.
struct Caption {
  std::string text;
  core::Vec3 at;
};

struct View {
  core::Vec3 looking = -core::Vec3::UnitZ();  // the direction the eye looks in (unit)
  core::Vec3 up = core::Vec3::UnitY();        // what points up in the picture (not along `looking`)
  int width = 480;
  int height = 360;
  double marginShare = 0.06;                  // empty border, per unit of the picture's size
};

// The meshes seen along `view.looking`, fitted to the picture; a face lit by its angle to the eye (flat
// shading), hidden faces removed by a depth buffer; white where nothing is.
Image render(const std::vector<ColouredMesh>& meshes, const std::vector<Caption>& captions, const View& view);

// The image as a PNG file's bytes (8-bit RGB, zlib-compressed rows, every chunk with its CRC).
std::vector<std::uint8_t> encodePng(const Image& image);

}  // namespace multidir::assembly
