// A software rasterizer and a PNG writer for the assembly sheet's pictures (docs/apart.md, "Assembly sheet").
#include "multidir/assembly/picture.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "multidir/assembly/part_labels.h"

namespace multidir::assembly {

using core::Vec3;

namespace {

void putBig32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  putBig32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  const uLong crc = crc32(0L, out.data() + start, static_cast<uInt>(out.size() - start));
  putBig32(out, static_cast<std::uint32_t>(crc));
}

std::uint8_t channel(double value) { return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(value, 0.0, 1.0))); }

}  // namespace

Colour Image::at(int x, int y) const {
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
  return Colour(rgb[i], rgb[i + 1], rgb[i + 2]) / 255.0;
}

Image render(const std::vector<ColouredMesh>& meshes, const std::vector<Caption>& captions, const View& view) {
  Image image;
  image.width = view.width;
  image.height = view.height;
  image.rgb.assign(3 * static_cast<std::size_t>(view.width) * static_cast<std::size_t>(view.height), 255);
  // The eye's frame: x to the right, y up, depth along `looking`.
  const Vec3 w = view.looking.normalized();
  const Vec3 right = w.cross(view.up).normalized();
  const Vec3 up = right.cross(w);
  Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY), high = Eigen::Vector2d::Constant(-INFINITY);
  for (const ColouredMesh& m : meshes)
    for (const Vec3& v : m.mesh->vertices) {
      const Vec3 p = v + m.shift;
      const Eigen::Vector2d q(p.dot(right), p.dot(up));
      low = low.cwiseMin(q);
      high = high.cwiseMax(q);
    }
  if (!(low.x() <= high.x())) return image;
  const double usableW = view.width * (1.0 - 2.0 * view.marginShare), usableH = view.height * (1.0 - 2.0 * view.marginShare);
  const Eigen::Vector2d extent = (high - low).cwiseMax(Eigen::Vector2d::Constant(1e-9));
  const double scale = std::min(usableW / extent.x(), usableH / extent.y());
  const Eigen::Vector2d middle = 0.5 * (low + high);
  auto toPixel = [&](const Vec3& p) {
    return Vec3(0.5 * view.width + (p.dot(right) - middle.x()) * scale,
                0.5 * view.height - (p.dot(up) - middle.y()) * scale, p.dot(w));
  };
  std::vector<double> depth(static_cast<std::size_t>(view.width) * static_cast<std::size_t>(view.height),
                            std::numeric_limits<double>::infinity());
  for (const ColouredMesh& m : meshes) {
    const core::TriangleMesh& mesh = *m.mesh;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const Vec3 n = mesh.areaNormal(f);
      if (n.norm() <= 0) continue;
      const double facing = -n.normalized().dot(w);
      if (facing <= 0) continue;  // a back face: the solid's front hides it
      const Colour shade = m.colour * (0.35 + 0.65 * facing);
      const Vec3 a = toPixel(mesh.corner(f, 0) + m.shift), b = toPixel(mesh.corner(f, 1) + m.shift),
                 c = toPixel(mesh.corner(f, 2) + m.shift);
      const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
      if (std::abs(area) < 1e-12) continue;
      const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
      const int x1 = std::min(view.width - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
      const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
      const int y1 = std::min(view.height - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double px = x + 0.5, py = y + 0.5;
          const double l0 = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
          const double l1 = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
          const double l2 = 1.0 - l0 - l1;
          if (l0 < 0 || l1 < 0 || l2 < 0) continue;
          const double z = l0 * a.z() + l1 * b.z() + l2 * c.z();
          const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(view.width) + static_cast<std::size_t>(x);
          if (z >= depth[i]) continue;
          depth[i] = z;
          image.rgb[3 * i] = channel(shade.x());
          image.rgb[3 * i + 1] = channel(shade.y());
          image.rgb[3 * i + 2] = channel(shade.z());
        }
    }
  }
  // Captions: black seven-segment digits on a white box, over everything.
  const double textHeight = std::max(12.0, 0.06 * view.height);
  LabelOptions font;  // the parts' digits, their strokes and gaps in pixels at this height
  font.minStrokeMm = 0.12 * textHeight;
  font.gapMm = 0.05 * textHeight;
  for (const Caption& caption : captions) {
    const Vec3 at = toPixel(caption.at);
    const Eigen::Vector2d size = textSize(caption.text, textHeight, font);
    const double left = at.x() - 0.5 * size.x(), bottom = at.y() + 0.5 * size.y();
    auto fill = [&](double xa, double ya, double xb, double yb, std::uint8_t value) {
      for (int y = std::max(0, static_cast<int>(std::floor(ya))); y < std::min(view.height, static_cast<int>(std::ceil(yb))); ++y)
        for (int x = std::max(0, static_cast<int>(std::floor(xa))); x < std::min(view.width, static_cast<int>(std::ceil(xb))); ++x)
          for (int k = 0; k < 3; ++k)
            image.rgb[3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(view.width) + static_cast<std::size_t>(x)) +
                      static_cast<std::size_t>(k)] = value;
    };
    const double pad = 0.2 * textHeight;
    fill(left - pad, bottom - size.y() - pad, left + size.x() + pad, bottom + pad, 255);
    for (const Stroke& s : textStrokes(caption.text, textHeight, font))
      fill(left + s.low.x(), bottom - s.high.y(), left + s.high.x(), bottom - s.low.y(), 0);
  }
  return image;
}

std::vector<std::uint8_t> encodePng(const Image& image) {
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  putBig32(header, static_cast<std::uint32_t>(image.width));
  putBig32(header, static_cast<std::uint32_t>(image.height));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, no filter method beyond 0, no interlace
  chunk(out, "IHDR", header);
  // Each row: filter type 0 (none), then its pixels.
  std::vector<std::uint8_t> raw;
  const std::size_t row = 3 * static_cast<std::size_t>(image.width);
  for (int y = 0; y < image.height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), image.rgb.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)),
               image.rgb.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y + 1)));
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::uint8_t> packed(size);
  compress2(packed.data(), &size, raw.data(), static_cast<uLong>(raw.size()), 9);
  packed.resize(size);
  chunk(out, "IDAT", packed);
  chunk(out, "IEND", {});
  return out;
}

}  // namespace multidir::assembly
