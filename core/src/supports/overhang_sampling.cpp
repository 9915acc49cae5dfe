#include "multidir/core/supports/overhang_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "multidir/core/analysis/overhang.h"
#include "mesh/edge_groups.h"
#include "supports/direction_frame.h"

namespace multidir::core {
namespace {

using detail::DirectionFrame;

// Connected patches of risky faces (through shared edges).
std::vector<std::int32_t> riskyPatches(const TriangleMesh& mesh, const std::vector<char>& risky,
                                       const detail::EdgeGroups& edges, int& count) {
  std::vector<std::int32_t> parent(mesh.triangles.size());
  for (std::size_t f = 0; f < parent.size(); ++f) parent[f] = static_cast<std::int32_t>(f);
  auto find = [&](std::int32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  for (std::uint32_t g = 0; g < edges.groupCount(); ++g) {
    const auto first = static_cast<std::int32_t>(edges.halfEdges[edges.groupStart[g]] / 3);
    for (std::uint32_t i = edges.groupStart[g] + 1; i < edges.groupStart[g + 1]; ++i) {
      const auto other = static_cast<std::int32_t>(edges.halfEdges[i] / 3);
      if (risky[first] && risky[other]) parent[find(first)] = find(other);
    }
  }
  std::vector<std::int32_t> patch(mesh.triangles.size(), -1);
  std::unordered_map<std::int32_t, std::int32_t> ids;
  for (std::size_t f = 0; f < patch.size(); ++f) {
    if (!risky[f]) continue;
    const auto [it, inserted] = ids.emplace(find(static_cast<std::int32_t>(f)), static_cast<std::int32_t>(ids.size()));
    patch[f] = it->second;
  }
  count = static_cast<int>(ids.size());
  return patch;
}

// Grid points of spacing R inside the triangle's projection, lifted onto the triangle, above `minHeight`.
void sampleFace(const TriangleMesh& mesh, std::size_t f, const DirectionFrame& frame, double spacing,
                double minHeight, std::vector<OverhangSample>& out) {
  std::array<Eigen::Vector2d, 3> p;
  std::array<double, 3> h;
  for (int k = 0; k < 3; ++k) {
    p[k] = frame.planar(mesh.corner(f, k));
    h[k] = frame.height(mesh.corner(f, k));
  }
  const double area2 = (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
  if (std::abs(area2) < 1e-12) return;
  const Eigen::Vector2d lo = p[0].cwiseMin(p[1]).cwiseMin(p[2]), hi = p[0].cwiseMax(p[1]).cwiseMax(p[2]);
  const long long i0 = static_cast<long long>(std::ceil(lo.x() / spacing)), i1 = static_cast<long long>(std::floor(hi.x() / spacing));
  const long long j0 = static_cast<long long>(std::ceil(lo.y() / spacing)), j1 = static_cast<long long>(std::floor(hi.y() / spacing));
  if ((i1 - i0 + 1) * (j1 - j0 + 1) > 10'000'000) return;  // a face larger than any printer bed
  for (long long i = i0; i <= i1; ++i)
    for (long long j = j0; j <= j1; ++j) {
      const Eigen::Vector2d q(static_cast<double>(i) * spacing, static_cast<double>(j) * spacing);
      // Barycentric coordinates; points on an edge belong to both faces and are merged later.
      const double w1 = ((q - p[0]).x() * (p[2] - p[0]).y() - (q - p[0]).y() * (p[2] - p[0]).x()) / area2;
      const double w2 = ((p[1] - p[0]).x() * (q - p[0]).y() - (p[1] - p[0]).y() * (q - p[0]).x()) / area2;
      const double w0 = 1.0 - w1 - w2;
      constexpr double kEdge = -1e-12;
      if (w0 < kEdge || w1 < kEdge || w2 < kEdge) continue;
      const double height = w0 * h[0] + w1 * h[1] + w2 * h[2];
      if (height <= minHeight) continue;
      const Vec3 position = w0 * mesh.corner(f, 0) + w1 * mesh.corner(f, 1) + w2 * mesh.corner(f, 2);
      out.push_back({position, OverhangKind::Face, static_cast<std::int32_t>(f), 0.0});
    }
}

// One sample per point: grid points on an edge shared by two risky faces come out twice.
void removeDuplicates(std::vector<OverhangSample>& samples, double tolerance) {
  std::vector<OverhangSample> kept;
  std::map<std::array<long long, 3>, std::vector<std::size_t>> cells;
  for (const OverhangSample& s : samples) {
    const std::array<long long, 3> key = {static_cast<long long>(std::floor(s.position.x() / tolerance)),
                                          static_cast<long long>(std::floor(s.position.y() / tolerance)),
                                          static_cast<long long>(std::floor(s.position.z() / tolerance))};
    bool duplicate = false;
    for (long long dx = -1; dx <= 1 && !duplicate; ++dx)
      for (long long dy = -1; dy <= 1 && !duplicate; ++dy)
        for (long long dz = -1; dz <= 1 && !duplicate; ++dz) {
          const auto it = cells.find({key[0] + dx, key[1] + dy, key[2] + dz});
          if (it == cells.end()) continue;
          for (std::size_t k : it->second)
            if ((kept[k].position - s.position).norm() <= tolerance) duplicate = true;
        }
    if (duplicate) continue;
    cells[key].push_back(kept.size());
    kept.push_back(s);
  }
  samples = std::move(kept);
}

bool nearAny(const std::vector<OverhangSample>& samples, const Vec3& p, double distance) {
  return std::any_of(samples.begin(), samples.end(),
                     [&](const OverhangSample& s) { return (s.position - p).squaredNorm() < distance * distance; });
}

}  // namespace

Result<std::vector<OverhangSample>> sampleOverhangs(const TriangleMesh& mesh, const Vec3& printingDirection,
                                                    const SupportOptions& options, RegionBase base) {
  if (Status s = validate(options); !s) return s.error();
  OverhangOptions overhang;
  overhang.alphaMaxDegrees = options.alphaMaxDegrees;
  overhang.supportedBandMm = options.supportedBandMm;
  overhang.base = base;
  const Result<OverhangAnalysis> analysis = analyzeOverhang(mesh, printingDirection, overhang);
  if (!analysis) return analysis.error();
  const DirectionFrame frame(printingDirection.normalized());
  const double minHeight =
      analysis->platformHeightMm + (base == RegionBase::Platform ? options.supportedBandMm : 0.0);
  const double spacing = options.samplingSpacingMm;

  std::vector<OverhangSample> samples;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (analysis->risky[f]) sampleFace(mesh, f, frame, spacing, minHeight, samples);
  removeDuplicates(samples, 1e-6 * spacing);

  // Risky patches smaller than a grid cell still need one contact.
  const detail::EdgeGroups edges = detail::edgeGroups(mesh);
  int patchCount = 0;
  const std::vector<std::int32_t> patch = riskyPatches(mesh, analysis->risky, edges, patchCount);
  std::vector<char> patchSampled(static_cast<std::size_t>(patchCount), 0);
  for (const OverhangSample& s : samples) patchSampled[static_cast<std::size_t>(patch[s.face])] = 1;
  std::vector<std::int32_t> largest(static_cast<std::size_t>(patchCount), -1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (patch[f] < 0 || patchSampled[patch[f]]) continue;
    std::int32_t& best = largest[patch[f]];
    if (best < 0 || analysis->riskyFaceAreaMm2[f] > analysis->riskyFaceAreaMm2[best]) best = static_cast<std::int32_t>(f);
  }
  for (std::int32_t f : largest) {
    if (f < 0) continue;
    const Vec3 centroid = (mesh.corner(f, 0) + mesh.corner(f, 1) + mesh.corner(f, 2)) / 3.0;
    if (frame.height(centroid) > minHeight) samples.push_back({centroid, OverhangKind::Face, f, 0.0});
  }

  // Edge overhangs: a downward ridge between two faces that are each printable on their own.
  const double sinAlpha = std::sin(degToRad(options.alphaMaxDegrees));
  const double cosAlpha = std::cos(degToRad(options.alphaMaxDegrees));
  const Vec3 d = frame.up();
  for (std::uint32_t g = 0; g < edges.groupCount(); ++g) {
    if (edges.useCount(g) != 2) continue;
    const std::uint32_t h = edges.halfEdges[edges.groupStart[g]];
    const std::array<std::int32_t, 2> faces{static_cast<std::int32_t>(h / 3),
                                            static_cast<std::int32_t>(edges.halfEdges[edges.groupStart[g] + 1] / 3)};
    const std::pair<std::int32_t, std::int32_t> edge = std::minmax(detail::halfEdgeFrom(mesh, h), detail::halfEdgeTo(mesh, h));
    if (analysis->risky[faces[0]] || analysis->risky[faces[1]]) continue;
    // A cap is a cut where a later region is printed on this one: what hangs at its rim lies in the later
    // region's sub-space, where this region's supports cannot go.
    if (!mesh.origins.empty() && (mesh.origins[faces[0]].isCap() || mesh.origins[faces[1]].isCap())) continue;
    const Vec3& a = mesh.vertices[edge.first];
    const Vec3& b = mesh.vertices[edge.second];
    const double length = (b - a).norm();
    if (!(length > 0)) continue;
    if (std::abs((b - a).dot(d)) / length >= cosAlpha) continue;
    bool ridge = true;
    for (std::int32_t f : faces) {
      const Vec3 n = mesh.faceNormal(static_cast<std::size_t>(f));
      if (!(n.dot(d) < 0.0) || n.dot(d) + sinAlpha < 0.0) ridge = false;
      for (int k = 0; k < 3; ++k) {
        const std::int32_t v = mesh.triangles[f][k];
        if (v == edge.first || v == edge.second) continue;
        const Vec3& c = mesh.vertices[v];
        // The opposite corner must lie above the edge's line at its foot.
        const double t = std::clamp((c - a).dot(b - a) / (length * length), 0.0, 1.0);
        if (frame.height(c) <= frame.height(a + t * (b - a)) + 1e-9) ridge = false;
      }
    }
    if (!ridge) continue;
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / spacing)));
    for (int i = 0; i < pieces; ++i) {
      const Vec3 p = a + (b - a) * ((i + 0.5) / pieces);
      if (frame.height(p) > minHeight && !nearAny(samples, p, 0.5 * spacing))
        samples.push_back({p, OverhangKind::Edge, faces[0], length / pieces});
    }
  }

  // Point overhangs: a vertex below all of its neighbours, where the surface faces down. A vertex below its
  // neighbours where the surface faces up is the bottom of a pit in a top surface: the solid lies under it, so
  // it rests on material printed before it (issue 29: the bunny's pits got struts grown inside the model).
  std::vector<double> lowestNeighbour(mesh.vertices.size(), std::numeric_limits<double>::infinity());
  std::vector<std::int32_t> someFace(mesh.vertices.size(), -1);
  std::vector<Vec3> areaNormal(mesh.vertices.size(), Vec3::Zero());  // sum of the faces' area vectors around it
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = mesh.triangles[f][k];
      someFace[v] = static_cast<std::int32_t>(f);
      areaNormal[v] += (mesh.corner(f, 1) - mesh.corner(f, 0)).cross(mesh.corner(f, 2) - mesh.corner(f, 0));
      for (int m = 1; m < 3; ++m)
        lowestNeighbour[v] = std::min(lowestNeighbour[v], frame.height(mesh.vertices[mesh.triangles[f][(k + m) % 3]]));
    }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (someFace[v] < 0) continue;
    const double h = frame.height(mesh.vertices[v]);
    if (h > minHeight && h < lowestNeighbour[v] - 1e-9 && areaNormal[v].dot(d) < 0.0 &&
        !nearAny(samples, mesh.vertices[v], 0.5 * spacing))
      samples.push_back({mesh.vertices[v], OverhangKind::Point, someFace[v], 0.0});
  }
  return samples;
}

}  // namespace multidir::core
