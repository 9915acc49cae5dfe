// Checks and safe repairs of a polygon soup (see checkAndRepair in mesh_io.h). The order matters: welding
// first (an STL has three copies of each corner), then faces that welding made degenerate or duplicate,
// then topology (which only means something once corners are shared), then orientation and inside-out.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include "detail/huge_pages.h"
#include "detail/parallel.h"
#include "detail/union_find.h"
#include "detail/edge_key.h"
#include "mesh/edge_groups.h"
#include "mesh/mesh_formats.h"
#include "mesh/mesh_shells.h"
#include "mesh/vertex_weld.h"
#include "multidir/core/mesh/mesh_io.h"

namespace multidir::core {
namespace {

using detail::joinIndices;
using detail::withThousands;

constexpr std::size_t kFirstFew = 5;
// Beyond this many shells the nesting test (shells x faces winding numbers) would cost too much; every
// shell is then taken as an outer one.
constexpr std::int32_t kMaxShellsForNesting = 64;
// A shell whose volume is below this times its area^(3/2) is flat (a sphere has about 0.09, a 100 mm
// square sheet 0.01 mm thick 4e-5): rounding leaves a flat shell at 1e-17 or so.
constexpr double kFlatShellRatio = 1e-9;

std::string edgeName(std::uint64_t key) {
  return std::to_string(key >> 32) + "-" + std::to_string(key & 0xffffffffu);
}

// Collects the defects and repairs of one check and turns an unrepairable one into an Error.
class Checker {
 public:
  Checker(const LoadOptions& options, std::string source) : m_options(options), m_source(std::move(source)) {}

  void info(const std::string& kind, std::size_t count, std::vector<std::int64_t> first, const std::string& text) {
    MeshDefect d{kind, count, std::move(first), text, false, false};
    m_report.defects.push_back(std::move(d));
  }
  // A defect loading can repair: recorded as repaired, or with repair off an error of code `code`.
  std::optional<Error> repairable(const std::string& kind, std::size_t count, std::vector<std::int64_t> first,
                                  const std::string& text, const std::string& repairSentence, ErrorCode code) {
    if (!m_options.repair)
      return Error{code, text + ". Loading with repairs switched on would fix this: " + repairSentence + ".", m_source};
    MeshDefect d{kind, count, std::move(first), text, true, true};
    m_report.defects.push_back(std::move(d));
    m_report.repairs.push_back(repairSentence);
    return std::nullopt;
  }
  Error fatal(ErrorCode code, const std::string& text) const { return Error{code, text, m_source}; }
  MeshReport& report() { return m_report; }

 private:
  const LoadOptions& m_options;
  std::string m_source;
  MeshReport m_report;
};

std::string firstList(const std::string& what, const std::vector<std::int64_t>& first, std::size_t count) {
  if (first.empty()) return "";
  return " (first: " + what + " " + joinIndices(first) + (count > first.size() ? ", ..." : "") + ")";
}

// Vertices whose faces form more than one fan (the first few), for the message; edgeCensus gives the count.
// Linear in the faces: the faces around a vertex are grouped through the other corner they share (a
// union-find per vertex), so a vertex with 100,000 faces costs 100,000 steps, not their square.
std::vector<std::int64_t> firstNonManifoldVertices(const TriangleMesh& mesh) {
  std::vector<std::vector<std::int32_t>> facesOfVertex(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f]) facesOfVertex[static_cast<std::size_t>(v)].push_back(static_cast<std::int32_t>(f));
  std::vector<std::int64_t> out;
  std::unordered_map<std::int32_t, std::int32_t> firstFaceWithCorner;
  for (std::size_t v = 0; v < facesOfVertex.size() && out.size() < kFirstFew; ++v) {
    const auto& faces = facesOfVertex[v];
    if (faces.size() < 2) continue;
    detail::UnionFind fans(faces.size());
    firstFaceWithCorner.clear();
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::int32_t w : mesh.triangles[static_cast<std::size_t>(faces[i])]) {
        if (w == static_cast<std::int32_t>(v)) continue;
        auto [it, inserted] = firstFaceWithCorner.emplace(w, static_cast<std::int32_t>(i));
        if (!inserted) fans.unite(it->second, static_cast<std::int32_t>(i));
      }
    const std::int32_t root = fans.find(0);
    for (std::size_t i = 1; i < faces.size(); ++i)
      if (fans.find(static_cast<std::int32_t>(i)) != root) {
        out.push_back(static_cast<std::int64_t>(v));
        break;
      }
  }
  return out;
}

// Edges of faces, in face order, whose use count satisfies `pick`: the first few, for messages.
template <typename Pick>
std::vector<std::string> firstEdges(const TriangleMesh& mesh, const detail::EdgeGroups& groups, Pick pick) {
  std::vector<std::string> out;
  std::unordered_set<std::uint32_t> seen;
  for (std::uint32_t h = 0; h < mesh.triangles.size() * 3 && out.size() < kFirstFew; ++h) {
    const std::uint32_t g = groups.groupOfHalfEdge[h];
    if (pick(groups.useCount(g)) && seen.insert(g).second)
      out.push_back(edgeName(detail::undirectedEdgeKey(detail::halfEdgeFrom(mesh, h), detail::halfEdgeTo(mesh, h))));
  }
  return out;
}

std::string edgeList(const std::vector<std::string>& edges, std::size_t count) {
  std::string s;
  for (std::size_t i = 0; i < edges.size(); ++i) s += (i ? ", " : "") + edges[i];
  return " (first: edges " + s + (count > edges.size() ? ", ..." : "") + ")";
}

void flip(Triangle& t) { std::swap(t[1], t[2]); }

}  // namespace

Result<LoadedMesh> checkAndRepair(const RawSoup& soup, const LoadOptions& options, const std::string& sourceName) {
  if (!(options.weldToleranceMm >= 0.0 && std::isfinite(options.weldToleranceMm)))
    return Error{ErrorCode::InvalidParameter, "the weld tolerance must be a finite length >= 0 mm", "weld tolerance"};
  if (!(options.degenerateAreaMm2 >= 0.0 && std::isfinite(options.degenerateAreaMm2)))
    return Error{ErrorCode::InvalidParameter, "the degenerate-face area must be a finite area >= 0 mm^2",
                 "degenerate area"};
  Checker check(options, sourceName);

  // Empty, too large, indices out of range, coordinates that are not numbers.
  if (soup.triangles.empty())
    return check.fatal(ErrorCode::EmptyMesh,
                       soup.droppedByReader > 0
                           ? "every one of its " + withThousands(soup.droppedByReader) +
                                 " faces is degenerate (fewer than three distinct corners): there is no surface"
                           : "the mesh has no faces: there is no surface to print");
  if (soup.triangles.size() > options.maxTriangles)
    return check.fatal(ErrorCode::TooLarge, withThousands(soup.triangles.size()) + " triangles, more than the limit of " +
                                                withThousands(options.maxTriangles) + "; simplify the model first");
  const std::size_t vertexCount = soup.vertices.size();
  std::vector<char> used(vertexCount, 0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (std::int32_t v : soup.triangles[f]) {
      if (v < 0 || static_cast<std::size_t>(v) >= vertexCount)
        return check.fatal(ErrorCode::MalformedFile, "face " + std::to_string(f) + " refers to vertex " +
                                                         std::to_string(v) + ", but there are " +
                                                         withThousands(vertexCount) + " vertices");
      used[static_cast<std::size_t>(v)] = 1;
    }
  {
    std::size_t bad = 0;
    std::vector<std::int64_t> first;
    for (std::size_t v = 0; v < vertexCount; ++v)
      if (used[v] && !soup.vertices[v].allFinite() && bad++ < kFirstFew) first.push_back(static_cast<std::int64_t>(v));
    if (bad > 0)
      return check.fatal(ErrorCode::NonFiniteVertex,
                         withThousands(bad) + " vertices have coordinates that are not finite numbers (NaN or "
                                              "infinite)" + firstList("vertices", first, bad) +
                             ". Fix or remove them in a mesh editor and export the model again.");
  }

  // Weld duplicate vertices.
  TriangleMesh mesh;
  std::size_t merged = 0;
  std::vector<std::int64_t> firstMerged;
  const std::vector<std::int32_t> newIndex = detail::weldVertices(soup.vertices, used, options.weldToleranceMm, 0,
                                                                  mesh.vertices, merged, firstMerged, kFirstFew);
  const auto unused = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
  if (unused > 0)
    check.info("unused-vertices", unused, {},
               withThousands(unused) + " vertices are used by no face; they were left out");
  if (merged > 0)
    if (auto e = check.repairable(
            "duplicate-vertices", merged, firstMerged,
            withThousands(merged) + " vertices repeat another within " + std::to_string(options.weldToleranceMm) +
                " mm" + firstList("vertices", firstMerged, merged),
            "merged " + withThousands(merged) + " duplicate vertices", ErrorCode::OpenBoundary))
      return *e;

  // Degenerate faces: repeated corners after welding, or an area below the threshold.
  std::size_t degenerate = soup.droppedByReader;
  std::vector<std::int64_t> firstDegenerate;
  std::vector<std::int64_t> sourceFace;  // soup face index of each kept face
  detail::reserveInHugePages(mesh.triangles, soup.triangles.size());
  detail::reserveInHugePages(sourceFace, soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    Triangle t;
    for (int k = 0; k < 3; ++k) t[static_cast<std::size_t>(k)] = newIndex[static_cast<std::size_t>(soup.triangles[f][static_cast<std::size_t>(k)])];
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const double area = 0.5 * (mesh.vertices[static_cast<std::size_t>(t[1])] - a)
                                  .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - a)
                                  .norm();
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(area >= options.degenerateAreaMm2) ||
        (area == 0.0 && options.degenerateAreaMm2 == 0.0)) {
      ++degenerate;
      if (firstDegenerate.size() < kFirstFew) firstDegenerate.push_back(static_cast<std::int64_t>(f));
      continue;
    }
    mesh.triangles.push_back(t);
    sourceFace.push_back(static_cast<std::int64_t>(f));
  }
  if (degenerate > 0)
    if (auto e = check.repairable(
            "degenerate-faces", degenerate, firstDegenerate,
            withThousands(degenerate) + " faces are degenerate (repeated corners or an area below " +
                std::to_string(options.degenerateAreaMm2) + " mm^2)" + firstList("faces", firstDegenerate, degenerate),
            "dropped " + withThousands(degenerate) + " degenerate faces", ErrorCode::NotManifold))
      return *e;
  if (mesh.triangles.empty())
    return check.fatal(ErrorCode::EmptyMesh, "every face is degenerate: there is no surface to print");

  // Duplicate faces: the same three corners, in any order.
  {
    // Sorted by corners, then by face: in each run of equal corners every face but the first repeats it.
    std::vector<std::pair<std::array<std::int32_t, 3>, std::uint32_t>> byCorners;
    detail::reserveInHugePages(byCorners, mesh.triangles.size());
    byCorners.resize(mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      byCorners[f] = {mesh.triangles[f], static_cast<std::uint32_t>(f)};
      std::sort(byCorners[f].first.begin(), byCorners[f].first.end());
    }
    // (corners, face) pairs are all different: the one sorted order, on threads.
    detail::parallelSort(byCorners.begin(), byCorners.end(), std::less<>(), detail::resolveThreadCount(0));
    std::vector<char> repeats(mesh.triangles.size(), 0);
    for (std::size_t i = 1; i < byCorners.size(); ++i)
      if (byCorners[i].first == byCorners[i - 1].first) repeats[byCorners[i].second] = 1;
    std::size_t duplicates = 0;
    std::vector<std::int64_t> first;
    std::vector<Triangle> kept;
    std::vector<std::int64_t> keptSource;
    detail::reserveInHugePages(kept, mesh.triangles.size());
    detail::reserveInHugePages(keptSource, mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      if (repeats[f]) {
        if (duplicates++ < kFirstFew) first.push_back(sourceFace[f]);
        continue;
      }
      kept.push_back(mesh.triangles[f]);
      keptSource.push_back(sourceFace[f]);
    }
    if (duplicates > 0)
      if (auto e = check.repairable("duplicate-faces", duplicates, first,
                                    withThousands(duplicates) + " faces repeat another face's corners" +
                                        firstList("faces", first, duplicates),
                                    "dropped " + withThousands(duplicates) + " duplicate faces", ErrorCode::NotManifold))
        return *e;
    mesh.triangles = std::move(kept);
    sourceFace = std::move(keptSource);
  }

  // Topology: every edge on exactly two faces, every vertex one fan. Not repairable automatically.
  const detail::EdgeGroups groups = detail::edgeGroups(mesh);
  const EdgeCensus census = detail::edgeCensus(mesh, groups);
  std::vector<std::string> problems;
  ErrorCode firstCode = ErrorCode::NotManifold;
  if (census.nonManifold > 0)
    problems.push_back("not a 2-manifold: " + withThousands(census.nonManifold) +
                       " edges are shared by more than two faces" +
                       edgeList(firstEdges(mesh, groups, [](std::uint32_t c) { return c > 2; }), census.nonManifold) +
                       ". Separate the touching parts in a mesh editor (e.g. MeshLab's 'Repair non Manifold Edges')");
  if (census.nonManifoldVertices > 0)
    problems.push_back("not a 2-manifold: " + withThousands(census.nonManifoldVertices) +
                       " vertices join surface parts that share no edge" +
                       firstList("vertices", firstNonManifoldVertices(mesh), census.nonManifoldVertices) +
                       ". Move the parts apart or merge them in a mesh editor (e.g. MeshLab's 'Split Vertices')");
  if (census.boundary > 0) {
    if (problems.empty()) firstCode = ErrorCode::OpenBoundary;
    problems.push_back("not a solid: " + withThousands(census.boundary) + " open boundary edges" +
                       edgeList(firstEdges(mesh, groups, [](std::uint32_t c) { return c == 1; }), census.boundary) +
                       ". Close the holes in a mesh editor (e.g. MeshLab's 'Close Holes') and load it again");
  }
  if (!problems.empty()) {
    std::string text;
    for (std::size_t i = 0; i < problems.size(); ++i) text += (i ? "; also " : "") + problems[i];
    return check.fatal(firstCode, text + ".");
  }

  // Orientation: walk each shell across its edges so that neighbours traverse their shared edge in
  // opposite directions; flip the smaller part of each shell.
  const std::size_t faceCount = mesh.triangles.size();
  std::vector<std::array<std::int32_t, 3>> neighbour;
  detail::reserveInHugePages(neighbour, faceCount);
  neighbour.resize(faceCount);
  std::vector<std::array<bool, 3>> sameDirection;
  detail::reserveInHugePages(sameDirection, faceCount);
  sameDirection.resize(faceCount);
  for (std::uint32_t h = 0; h < faceCount * 3; ++h) {
    // Every edge has two faces here (checked above): the other half-edge of its group.
    const std::uint32_t first = groups.groupStart[groups.groupOfHalfEdge[h]];
    const std::uint32_t other = groups.halfEdges[first] == h ? groups.halfEdges[first + 1] : groups.halfEdges[first];
    neighbour[h / 3][h % 3] = static_cast<std::int32_t>(other / 3);
    sameDirection[h / 3][h % 3] = detail::halfEdgeFrom(mesh, h) == detail::halfEdgeFrom(mesh, other);
  }
  const FaceComponents components = faceComponents(mesh);
  std::vector<char> flipped(faceCount, 0), visited(faceCount, 0);
  std::size_t flips = 0;
  std::vector<std::int64_t> firstFlipped;
  for (std::size_t seed = 0; seed < faceCount; ++seed) {
    if (visited[seed]) continue;
    std::vector<std::int32_t> shell{static_cast<std::int32_t>(seed)};
    visited[seed] = 1;
    for (std::size_t i = 0; i < shell.size(); ++i) {
      const auto f = static_cast<std::size_t>(shell[i]);
      for (int k = 0; k < 3; ++k) {
        const auto g = static_cast<std::size_t>(neighbour[f][static_cast<std::size_t>(k)]);
        const char want = static_cast<char>(flipped[f] ^ (sameDirection[f][static_cast<std::size_t>(k)] ? 1 : 0));
        if (!visited[g]) {
          visited[g] = 1;
          flipped[g] = want;
          shell.push_back(static_cast<std::int32_t>(g));
        } else if (flipped[g] != want) {
          return check.fatal(ErrorCode::InconsistentOrientation,
                             "the shell containing face " + std::to_string(sourceFace[seed]) +
                                 " cannot be oriented (it is one-sided, like a Moebius strip). Rebuild that part in a "
                                 "mesh editor.");
        }
      }
    }
    const auto shellFlips = static_cast<std::size_t>(
        std::count_if(shell.begin(), shell.end(), [&](std::int32_t f) { return flipped[static_cast<std::size_t>(f)] != 0; }));
    const bool invert = 2 * shellFlips > shell.size();
    for (std::int32_t f : shell) {
      auto& flag = flipped[static_cast<std::size_t>(f)];
      if (invert) flag = static_cast<char>(!flag);
    }
  }
  for (std::size_t f = 0; f < faceCount; ++f)
    if (flipped[f]) {
      flip(mesh.triangles[f]);
      if (flips++ < kFirstFew) firstFlipped.push_back(sourceFace[f]);
    }
  if (flips > 0)
    if (auto e = check.repairable("inconsistent-orientation", flips, firstFlipped,
                                  withThousands(flips) + " faces are oriented against their neighbours" +
                                      firstList("faces", firstFlipped, flips),
                                  "turned " + withThousands(flips) + " faces to agree with their neighbours",
                                  ErrorCode::InconsistentOrientation))
      return *e;

  // Inside-out shells: an outer shell must enclose positive volume, a cavity (inside an odd number of
  // other shells) negative.
  {
    const auto shellFaces = detail::facesOfComponents(components);
    // One shell (the usual model) is the mesh itself: no copy of a million faces to measure it.
    const std::size_t shellCount = shellFaces.size();
    std::vector<TriangleMesh> shells;
    if (shellCount > 1) {
      shells.reserve(shellCount);
      for (const auto& faces : shellFaces) shells.push_back(detail::extractFaces(mesh, faces));
    }
    auto shellMesh = [&](std::size_t s) -> const TriangleMesh& { return shellCount > 1 ? shells[s] : mesh; };
    // Nesting: shell s lies inside shell o when its probes say so; shells whose surfaces cross are two
    // overlapping parts, and neither a part nor a cavity can be told apart there, so they are refused
    // rather than one of them turned inside out on the word of a single vertex.
    std::vector<int> depth(shellCount, 0);
    if (components.count <= kMaxShellsForNesting && shellCount > 1) {
      std::vector<BoundingBox> boxes;
      boxes.reserve(shells.size());
      for (const TriangleMesh& shell : shells) boxes.push_back(boundingBox(shell));
      for (std::size_t s = 0; s < shells.size(); ++s)
        for (std::size_t other = 0; other < shells.size(); ++other) {
          if (other == s) continue;
          const detail::Containment where = detail::containment(shells[s], shells[other], boxes[other]);
          if (where == detail::Containment::Crossing)
            return check.fatal(
                ErrorCode::NotManifold,
                "shells " + std::to_string(std::min(s, other)) + " and " + std::to_string(std::max(s, other)) +
                    " (with faces " + std::to_string(sourceFace[static_cast<std::size_t>(shellFaces[s].front())]) +
                    " and " + std::to_string(sourceFace[static_cast<std::size_t>(shellFaces[other].front())]) +
                    ") cross each other: part of one lies inside the other and part outside, so neither is a "
                    "cavity and the solid they make is not defined. Join them with a boolean union in a mesh "
                    "editor (e.g. MeshLab's 'Mesh Boolean: Union') and load the model again");
          if (where == detail::Containment::Inside) ++depth[s];
        }
    }
    std::size_t inverted = 0;
    std::vector<std::int64_t> first;
    for (std::size_t s = 0; s < shellCount; ++s) {
      const double volume = signedVolume(shellMesh(s));
      // A closed shell that encloses no volume (a flat tetrahedron, a surface folded onto itself) is no
      // solid. Relative to the shell's area, so that the test does not depend on the model's units.
      const double area = surfaceArea(shellMesh(s));
      if (!(std::abs(volume) > kFlatShellRatio * area * std::sqrt(area)))
        return check.fatal(ErrorCode::EmptyMesh,
                           "shell " + std::to_string(s) + " (with face " +
                               std::to_string(sourceFace[static_cast<std::size_t>(shellFaces[s].front())]) +
                               ") encloses no volume (" + std::to_string(volume) + " mm^3 for " +
                               std::to_string(area) + " mm^2 of surface): it is flat, not a solid. Remove it or "
                               "give it thickness in a mesh editor");
      const bool wantPositive = depth[s] % 2 == 0;
      if ((volume > 0.0) != wantPositive) {
        for (std::int32_t f : shellFaces[s]) flip(mesh.triangles[static_cast<std::size_t>(f)]);
        if (inverted++ < kFirstFew) first.push_back(static_cast<std::int64_t>(s));
      }
    }
    if (inverted > 0)
      if (auto e = check.repairable("inverted-shells", inverted, first,
                                    withThousands(inverted) + " of " + withThousands(shellCount) +
                                        " shells face inward (inside out)" + firstList("shells", first, inverted),
                                    "turned " + withThousands(inverted) + " inside-out shells the right way out",
                                    ErrorCode::InconsistentOrientation))
        return *e;
    if (shellCount > 1)
      check.info("several-shells", shellCount, {},
                 "the model is made of " + withThousands(shellCount) +
                     " separate shells (parts or cavities); each is kept");
  }

  // Vertices that only dropped faces used are left out (keeping the order of the rest), so every vertex
  // of the result belongs to a face.
  {
    std::vector<std::int32_t> compact(mesh.vertices.size(), -1);
    for (const Triangle& t : mesh.triangles)
      for (std::int32_t v : t) compact[static_cast<std::size_t>(v)] = 0;
    std::vector<Vec3> kept;
    kept.reserve(mesh.vertices.size());
    for (std::size_t v = 0; v < compact.size(); ++v)
      if (compact[v] == 0) {
        compact[v] = static_cast<std::int32_t>(kept.size());
        kept.push_back(mesh.vertices[v]);
      }
    if (kept.size() != mesh.vertices.size()) {
      for (Triangle& t : mesh.triangles)
        for (std::int32_t& v : t) v = compact[static_cast<std::size_t>(v)];
      mesh.vertices = std::move(kept);
    }
  }

  LoadedMesh out;
  out.mesh = std::move(mesh);
  out.mesh.resetOrigins();
  out.report = std::move(check.report());
  out.report.statistics = detail::computeStatistics(out.mesh, true);  // closed and oriented: checked above
  return out;
}

}  // namespace multidir::core
