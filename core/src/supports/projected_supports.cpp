#include "multidir/core/supports/projected_supports.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "multidir/core/mesh/mesh_measure.h"
#include "supports/direction_frame.h"
#include "supports/mesh_ray_index.h"

namespace multidir::core {
namespace {

using detail::MeshRayIndex;

// A point this close to a plane lies on it (nodes on base planes and walls are computed to ~1e-12 mm).
constexpr double kOnPlaneMm = 1e-9;
// How far above its sample a tip's clearance test starts, so the face it stands on is not hit.
constexpr double kSurfaceClearanceMm = 1e-4;
constexpr double kTiny = 1e-12;

// One sub-space Omega_k with the region printed in it.
struct Cell {
  int region = 0;                // printing position
  Vec3 up = Vec3::UnitZ();       // printing direction
  std::optional<Plane> base;     // inside: signedDistance >= 0
  std::vector<Plane> walls;      // inside: signedDistance <= 0 (planes of regions printed later)
  const TriangleMesh* mesh = nullptr;
};

struct Layout {
  std::vector<Cell> cells;       // clipping order: cell k belongs to plane k; the last is the first region's
  std::vector<Plane> planes;
  Vec3 platformUp = Vec3::UnitZ();
  double platformHeight = 0.0;
  int regionCount = 1;
};

enum class Event { Model, Base, Platform, Wall, None };

class Grower {
 public:
  Grower(const TriangleMesh& model, const Layout& layout, const SupportOptions& options, JobContext& job)
      : m_layout(layout), m_options(options), m_job(job), m_index(model) {
    m_tanAngle = std::tan(degToRad(options.strutAngleDegrees));
    m_cosWall = std::cos(degToRad(options.maxWallSlideDegrees));
    m_baseRadius = options.samplingSpacingMm / 4.0;
    const BoundingBox box = boundingBox(model);
    m_reach = 4.0 * box.size().norm() + 10.0;
  }

  // Grows every cell in clipping order; false when cancelled.
  bool run(SupportStatistics& stats) {
    m_pending.assign(m_layout.cells.size(), {});
    for (std::size_t c = 0; c < m_layout.cells.size(); ++c) {
      if (m_job.isCancelled()) return false;
      const Cell& cell = m_layout.cells[c];
      if (cell.mesh) {
        const Result<std::vector<OverhangSample>> samples = sampleOverhangs(
            *cell.mesh, cell.up, m_options, cell.base ? RegionBase::CutPlane : RegionBase::Platform);
        if (samples)
          for (const OverhangSample& s : *samples) addTip(static_cast<int>(c), s, stats);
      }
      if (!growCell(static_cast<int>(c), stats)) return false;
    }
    return true;
  }

  std::vector<SupportNode> nodes;
  std::vector<SupportStrut> struts;
  std::vector<int> strutCell;
  std::vector<char> strutIsTip;   // contact tip (narrow at the top)
  std::vector<char> strutIsFoot;  // foot (narrow at the bottom)
  // Per node: the overhang a contact node holds up, and for an edge contact the length it stands for.
  std::vector<OverhangKind> nodeCause;
  std::vector<double> nodeEdgeLengthMm;

 private:
  int addNode(const Vec3& p, SupportNodeKind kind) {
    nodes.push_back({p, kind});
    nodeCause.push_back(OverhangKind::Face);
    nodeEdgeLengthMm.push_back(0.0);
    return static_cast<int>(nodes.size()) - 1;
  }
  void addStrut(int upper, int lower, int cell, bool tip = false, bool foot = false) {
    struts.push_back({upper, lower, 0.0, 0.0});
    strutCell.push_back(cell);
    strutIsTip.push_back(tip ? 1 : 0);
    strutIsFoot.push_back(foot ? 1 : 0);
  }

  bool contains(int c, const Vec3& p, double tolerance) const {
    const Cell& cell = m_layout.cells[static_cast<std::size_t>(c)];
    if (cell.base && cell.base->signedDistance(p) < -tolerance) return false;
    for (const Plane& wall : cell.walls)
      if (wall.signedDistance(p) > tolerance) return false;
    return m_layout.platformUp.dot(p) >= m_layout.platformHeight - tolerance;
  }

  // The cell a point belongs to: the first plane it lies above, else the first region's.
  int locate(const Vec3& p) const {
    for (std::size_t k = 0; k < m_layout.planes.size(); ++k)
      if (m_layout.planes[k].signedDistance(p) > kOnPlaneMm) return static_cast<int>(k);
    return static_cast<int>(m_layout.cells.size()) - 1;
  }

  bool clear(const Vec3& from, const Vec3& to) const { return !m_index.firstHit(from, to); }

  void addTip(int c, const OverhangSample& sample, SupportStatistics& stats) {
    const Cell& cell = m_layout.cells[static_cast<std::size_t>(c)];
    switch (sample.kind) {
      case OverhangKind::Face: ++stats.faceSamples; break;
      case OverhangKind::Edge: ++stats.edgeSamples; break;
      case OverhangKind::Point: ++stats.pointSamples; break;
    }
    const Vec3 tip = sample.position - m_options.tipLengthMm * cell.up;
    if (!contains(c, tip, kOnPlaneMm) || !clear(sample.position - kSurfaceClearanceMm * cell.up, tip)) {
      ++stats.droppedSamples;
      return;
    }
    const int contact = addNode(sample.position, SupportNodeKind::Contact);
    nodeCause[static_cast<std::size_t>(contact)] = sample.kind;
    nodeEdgeLengthMm[static_cast<std::size_t>(contact)] = sample.edgeLengthMm;
    const int bottom = addNode(tip, SupportNodeKind::Tip);
    addStrut(contact, bottom, c, true);
    m_pending[static_cast<std::size_t>(c)].push_back(bottom);
  }

  struct Descent {
    Event event = Event::None;
    double length = std::numeric_limits<double>::infinity();
    int wall = -1;
  };

  // The first thing met going from p along v (unit) inside cell c.
  Descent firstEvent(int c, const Vec3& p, const Vec3& v) const {
    const Cell& cell = m_layout.cells[static_cast<std::size_t>(c)];
    Descent d;
    auto consider = [&](double t, Event e, int wall) {
      if (t < d.length) {
        d.length = std::max(0.0, t);
        d.event = e;
        d.wall = wall;
      }
    };
    if (cell.base) {
      const double rate = cell.base->normal.dot(v);
      if (rate < -kTiny) consider(cell.base->signedDistance(p) / -rate, Event::Base, -1);
    }
    const double platformRate = m_layout.platformUp.dot(v);
    if (platformRate < -kTiny)
      consider((m_layout.platformUp.dot(p) - m_layout.platformHeight) / -platformRate, Event::Platform, -1);
    for (std::size_t j = 0; j < cell.walls.size(); ++j) {
      const double rate = cell.walls[j].normal.dot(v);
      if (rate > kTiny) consider(-cell.walls[j].signedDistance(p) / rate, Event::Wall, static_cast<int>(j));
    }
    const double reach = std::isfinite(d.length) ? d.length : m_reach;
    if (const auto hit = m_index.firstHit(p, p + reach * v)) {
      d.length = *hit * reach;
      d.event = Event::Model;
      d.wall = -1;
    }
    return d;
  }

  // Slides v along the walls p lies on that it would cross; empty when it cannot go on downward.
  std::optional<Vec3> slide(int c, const Vec3& p, Vec3 v) const {
    const Cell& cell = m_layout.cells[static_cast<std::size_t>(c)];
    for (int round = 0; round < 4; ++round) {
      bool changed = false;
      for (const Plane& wall : cell.walls) {
        if (std::abs(wall.signedDistance(p)) > 1e-7) continue;
        const double rate = wall.normal.dot(v);
        if (rate <= kTiny) continue;
        v -= rate * wall.normal;
        changed = true;
      }
      if (v.norm() < 1e-9) return std::nullopt;
      v.normalize();
      if (!changed) break;
    }
    for (const Plane& wall : cell.walls)
      if (std::abs(wall.signedDistance(p)) <= 1e-7 && wall.normal.dot(v) > 1e-9) return std::nullopt;
    if (v.dot(-cell.up) < m_cosWall) return std::nullopt;
    return v;
  }

  // Grows node p straight down its cell (sliding along walls), to the model, the platform or the base plane.
  void descend(int c, int p, SupportStatistics& stats) {
    const Cell& cell = m_layout.cells[static_cast<std::size_t>(c)];
    Vec3 v = -cell.up;
    int current = p;
    for (int bend = 0; bend < 8; ++bend) {
      const Vec3 from = nodes[static_cast<std::size_t>(current)].position;
      const Descent d = firstEvent(c, from, v);
      if (d.event == Event::Model) {
        const Vec3 touch = from + d.length * v;
        int top = current;
        if (d.length > m_options.tipLengthMm) {
          top = addNode(from + (d.length - m_options.tipLengthMm) * v, SupportNodeKind::Foot);
          addStrut(current, top, c);
        }
        addStrut(top, addNode(touch, SupportNodeKind::Model), c, false, true);
        ++stats.onModel;
        return;
      }
      if (d.event == Event::Platform) {
        Vec3 foot = from + d.length * v;
        foot -= (m_layout.platformUp.dot(foot) - m_layout.platformHeight) * m_layout.platformUp;
        addStrut(current, addNode(foot, SupportNodeKind::Platform), c);
        ++stats.onPlatform;
        return;
      }
      if (d.event == Event::Base) {
        const Vec3 onPlane = cell.base->project(from + d.length * v);
        const int node = addNode(onPlane, SupportNodeKind::Plane);
        addStrut(current, node, c);
        ++stats.projections;
        m_pending[static_cast<std::size_t>(locate(onPlane))].push_back(node);
        return;
      }
      if (d.event == Event::Wall) {
        Vec3 onWall = from + d.length * v;
        const Plane& wall = cell.walls[static_cast<std::size_t>(d.wall)];
        onWall -= std::max(0.0, wall.signedDistance(onWall)) * wall.normal;
        if (d.length > 1e-9) {
          const int node = addNode(onWall, SupportNodeKind::Bend);
          addStrut(current, node, c);
          current = node;
        }
        if (const auto next = slide(c, nodes[static_cast<std::size_t>(current)].position, v)) {
          v = *next;
          continue;
        }
      }
      break;  // no event ahead, or a wall it cannot slide along
    }
    nodes[static_cast<std::size_t>(current)].kind = SupportNodeKind::Stuck;
    ++stats.stuck;
  }

  struct Merge {
    int other = -1;       // index into the active list
    Vec3 point;
    bool atOther = false;  // the merge point is the other node itself
    double cost = std::numeric_limits<double>::infinity();
  };

  // Vanek et al.: the point below both nodes that both reach inside their cones, closest to p.
  std::optional<Merge> bestMerge(int c, int p, const std::vector<int>& active, double limit) const {
    const Cell& cell = m_layout.cells[static_cast<std::size_t>(c)];
    const detail::DirectionFrame frame(cell.up);
    const Vec3& pp = nodes[static_cast<std::size_t>(p)].position;
    const double hp = frame.height(pp);
    std::vector<Merge> candidates;
    for (std::size_t i = 0; i < active.size(); ++i) {
      const Vec3& qq = nodes[static_cast<std::size_t>(active[i])].position;
      const double hq = frame.height(qq);
      const Vec3 offset = frame.horizontal(qq - pp);
      const double distance = offset.norm();
      Merge m;
      m.other = static_cast<int>(i);
      if (distance <= (hp - hq) * m_tanAngle + 1e-12) {
        m.point = qq;
        m.atOther = true;
      } else {
        if (m_tanAngle < 1e-9) continue;
        const double z = 0.5 * (hp + hq - distance / m_tanAngle);
        const double fromP = (hp - z) * m_tanAngle;
        m.point = pp + offset * (fromP / distance) - (hp - z) * cell.up;
      }
      m.cost = (m.point - pp).norm();
      if (m.cost < limit) candidates.push_back(m);
    }
    std::sort(candidates.begin(), candidates.end(), [](const Merge& a, const Merge& b) {
      return a.cost < b.cost || (a.cost == b.cost && a.other < b.other);
    });
    for (const Merge& m : candidates) {
      const Vec3& qq = nodes[static_cast<std::size_t>(active[static_cast<std::size_t>(m.other)])].position;
      if (!contains(c, m.point, kOnPlaneMm)) continue;
      if (!clear(pp, m.point)) continue;
      if (!m.atOther && !clear(qq, m.point)) continue;
      return m;
    }
    return std::nullopt;
  }

  bool growCell(int c, SupportStatistics& stats) {
    const Cell& cell = m_layout.cells[static_cast<std::size_t>(c)];
    std::vector<int> active = std::move(m_pending[static_cast<std::size_t>(c)]);
    m_pending[static_cast<std::size_t>(c)].clear();
    int picks = 0;
    while (!active.empty()) {
      if (++picks % 64 == 0 && m_job.isCancelled()) return false;
      // The highest node first; ties by creation order keep the result deterministic.
      std::size_t top = 0;
      for (std::size_t i = 1; i < active.size(); ++i) {
        const double hi = cell.up.dot(nodes[static_cast<std::size_t>(active[i])].position);
        const double ht = cell.up.dot(nodes[static_cast<std::size_t>(active[top])].position);
        if (hi > ht || (hi == ht && active[i] < active[top])) top = i;
      }
      const int p = active[top];
      active.erase(active.begin() + static_cast<std::ptrdiff_t>(top));
      if (m_options.mergeStruts && !active.empty()) {
        const Descent straight = firstEvent(c, nodes[static_cast<std::size_t>(p)].position, -cell.up);
        if (const auto merge = bestMerge(c, p, active, straight.length)) {
          const int q = active[static_cast<std::size_t>(merge->other)];
          if (merge->atOther) {
            addStrut(p, q, c);
          } else {
            const int m = addNode(merge->point, SupportNodeKind::Merge);
            addStrut(p, m, c);
            addStrut(q, m, c);
            active[static_cast<std::size_t>(merge->other)] = m;
          }
          ++stats.merges;
          continue;
        }
      }
      descend(c, p, stats);
    }
    return true;
  }

  const Layout& m_layout;
  const SupportOptions& m_options;
  JobContext& m_job;
  MeshRayIndex m_index;
  double m_tanAngle = 0.0;
  double m_cosWall = 0.0;
  double m_baseRadius = 0.5;
  double m_reach = 1000.0;
  std::vector<std::vector<int>> m_pending;
};

// Distance of a frustum's centroid from its r1 end, along its length.
double frustumCentroidFromFirst(double length, double r1, double r2) {
  const double denominator = 4.0 * (r1 * r1 + r1 * r2 + r2 * r2);
  return denominator > 0 ? length * (r1 * r1 + 2 * r1 * r2 + 3 * r2 * r2) / denominator : 0.5 * length;
}

// Eq. 14 for every strut, top down (struts are created after every strut above them).
void assignRadii(Grower& g, const Layout& layout, const SupportOptions& options) {
  const std::size_t n = g.nodes.size();
  std::vector<double> volumeAbove(n, 0.0);
  std::vector<Vec3> momentAbove(n, Vec3::Zero());  // sum V_i c_i
  std::vector<int> lastRegionAbove(n, -1);
  const double base = options.samplingSpacingMm / 4.0;
  for (std::size_t s = 0; s < g.struts.size(); ++s) {
    SupportStrut& strut = g.struts[s];
    const auto upper = static_cast<std::size_t>(strut.upper), lower = static_cast<std::size_t>(strut.lower);
    const Vec3& a = g.nodes[upper].position;
    const int region = layout.cells[static_cast<std::size_t>(g.strutCell[s])].region;
    double torque = 0.0;
    if (volumeAbove[upper] > 0) {
      const Vec3 arm = momentAbove[upper] - a * volumeAbove[upper];
      // Gravity of each printing direction under which the pieces above stand on this strut.
      for (const Cell& cell : layout.cells)
        if (cell.region >= region && cell.region <= std::max(region, lastRegionAbove[upper]))
          torque = std::max(torque, arm.cross(-cell.up).norm());
    }
    const double radius = strutRadiusMm(options.samplingSpacingMm, options.torqueLambda, torque);
    strut.upperRadiusMm = g.strutIsTip[s] ? options.contactRadiusMm : radius;
    strut.lowerRadiusMm = g.strutIsFoot[s] ? options.contactRadiusMm : (g.strutIsTip[s] ? base : radius);
    const Vec3& b = g.nodes[lower].position;
    const double length = (a - b).norm();
    const double volume = frustumVolume(length, strut.lowerRadiusMm, strut.upperRadiusMm);
    const Vec3 centroid =
        length > 0 ? Vec3(b + (a - b) * (frustumCentroidFromFirst(length, strut.lowerRadiusMm, strut.upperRadiusMm) / length)) : a;
    volumeAbove[lower] += volumeAbove[upper] + volume;
    momentAbove[lower] += momentAbove[upper] + volume * centroid;
    lastRegionAbove[lower] = std::max({lastRegionAbove[lower], lastRegionAbove[upper], region});
  }
}

// What each region's supports hold up: its contacts by overhang kind, and the volume of its struts that hold up
// only struts carried across a base plane from a region printed later. Struts come after every strut above
// them, so one pass top-down sees each strut's upper node complete: a strut holds up its own region's
// overhangs when it starts at a contact or below such a strut of the same cell.
void tallyCauses(const Grower& g, const Layout& layout, ProjectedSupports& out) {
  std::vector<std::vector<int>> ownCells(g.nodes.size());  // cells in which a strut into the node holds up own contacts
  for (std::size_t s = 0; s < g.struts.size(); ++s) {
    const SupportStrut& strut = g.struts[s];
    const auto upper = static_cast<std::size_t>(strut.upper), lower = static_cast<std::size_t>(strut.lower);
    const int cell = g.strutCell[s];
    SupportCause& cause = out.regions[static_cast<std::size_t>(layout.cells[static_cast<std::size_t>(cell)].region)].cause;
    const bool contact = g.nodes[upper].kind == SupportNodeKind::Contact;
    if (contact) {
      switch (g.nodeCause[upper]) {
        case OverhangKind::Face: ++cause.faceContacts; break;
        case OverhangKind::Point: ++cause.pointContacts; break;
        case OverhangKind::Edge:
          ++cause.edgeContacts;
          cause.edgeLengthMm += g.nodeEdgeLengthMm[upper];
          break;
      }
    }
    const std::vector<int>& above = ownCells[upper];
    if (contact || std::find(above.begin(), above.end(), cell) != above.end()) {
      if (std::find(ownCells[lower].begin(), ownCells[lower].end(), cell) == ownCells[lower].end())
        ownCells[lower].push_back(cell);
    } else {
      cause.carriedVolumeMm3 +=
          frustumVolume((g.nodes[upper].position - g.nodes[lower].position).norm(), strut.lowerRadiusMm, strut.upperRadiusMm);
    }
  }
}

// Splits the structure by region and builds each region's solids.
ProjectedSupports package(Grower& g, const Layout& layout, const SupportOptions& options) {
  ProjectedSupports out;
  out.regions.resize(static_cast<std::size_t>(layout.regionCount));
  for (int r = 0; r < layout.regionCount; ++r) out.regions[static_cast<std::size_t>(r)].regionIndex = r;
  tallyCauses(g, layout, out);
  std::vector<std::vector<int>> localIndex(out.regions.size(), std::vector<int>(g.nodes.size(), -1));
  for (std::size_t s = 0; s < g.struts.size(); ++s) {
    const int region = layout.cells[static_cast<std::size_t>(g.strutCell[s])].region;
    out.strutRegion.push_back(region);
    SupportSet& set = out.regions[static_cast<std::size_t>(region)];
    std::vector<int>& local = localIndex[static_cast<std::size_t>(region)];
    SupportStrut piece = g.struts[s];
    for (std::int32_t* end : {&piece.upper, &piece.lower}) {
      int& index = local[static_cast<std::size_t>(*end)];
      if (index < 0) {
        index = static_cast<int>(set.nodes.size());
        set.nodes.push_back(g.nodes[static_cast<std::size_t>(*end)]);
      }
      *end = index;
    }
    set.struts.push_back(piece);
  }
  const double contactArea = kPi * options.contactRadiusMm * options.contactRadiusMm;
  for (SupportSet& set : out.regions) {
    set.strutSides = options.strutSides;
    set.mesh = supportSolids(set.nodes, set.struts, options.strutSides);
    set.volumeMm3 = set.mesh.empty() ? 0.0 : signedVolume(set.mesh);
    for (const SupportNode& node : set.nodes)
      if (node.kind == SupportNodeKind::Contact || node.kind == SupportNodeKind::Model) ++set.contacts;
    set.contactAreaMm2 = set.contacts * contactArea;
    out.volumeMm3 += set.volumeMm3;
    out.contactAreaMm2 += set.contactAreaMm2;
    out.contacts += set.contacts;
  }
  out.nodes = std::move(g.nodes);
  out.struts = std::move(g.struts);
  return out;
}

Result<ProjectedSupports> grow(const TriangleMesh& model, const Layout& layout, const SupportOptions& options,
                               JobContext& job) {
  const auto start = std::chrono::steady_clock::now();
  Grower grower(model, layout, options, job);
  SupportStatistics stats;
  if (!grower.run(stats)) return Error{ErrorCode::Cancelled, "support generation was cancelled", "supports"};
  assignRadii(grower, layout, options);
  ProjectedSupports out = package(grower, layout, options);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.statistics = stats;
  return out;
}

double lowestAlong(const TriangleMesh& mesh, const Vec3& up) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t) lowest = std::min(lowest, up.dot(mesh.vertices[static_cast<std::size_t>(v)]));
  return lowest;
}

Status checkModel(const TriangleMesh& model, const SupportOptions& options) {
  if (Status s = validate(options); !s) return s;
  if (model.empty()) return Error{ErrorCode::EmptyMesh, "the model has no faces: load a closed mesh first", "model"};
  return Done{};
}

}  // namespace

double strutRadiusMm(double samplingSpacingMm, double torqueLambda, double torqueMm4) {
  return (1.0 + torqueLambda * std::abs(torqueMm4)) * samplingSpacingMm / 4.0;
}

Vec3 gravityTorque(const std::vector<double>& volumesMm3, const std::vector<Vec3>& centroids, const Vec3& pivot,
                   const Vec3& gravity) {
  Vec3 torque = Vec3::Zero();
  for (std::size_t i = 0; i < volumesMm3.size() && i < centroids.size(); ++i)
    torque += volumesMm3[i] * (centroids[i] - pivot).cross(gravity);
  return torque;
}

Result<ProjectedSupports> generateSupports(const TriangleMesh& model, const Decomposition& plan,
                                           const MachineSpec& machine, const SupportOptions& options,
                                           JobContext& job) {
  if (Status s = checkModel(model, options); !s) return s.error();
  const std::size_t planeCount = plan.clippingPlanes.size();
  if (plan.regions.size() != planeCount + 1)
    return Error{ErrorCode::InvalidParameter,
                 "the plan has " + std::to_string(plan.regions.size()) + " regions for " + std::to_string(planeCount) +
                     " clipping planes; a plan has one region more than planes",
                 "plan"};
  for (std::size_t i = 1; i < plan.regions.size(); ++i)
    if (plan.regions[i].clippingIndex != static_cast<std::int32_t>(planeCount - i))
      return Error{ErrorCode::InvalidParameter,
                   "region " + std::to_string(i) + " names clipping plane " +
                       std::to_string(plan.regions[i].clippingIndex) + " but printing order says " +
                       std::to_string(planeCount - i),
                   "plan"};
  const double upLength = machine.up.norm();
  if (!std::isfinite(upLength) || upLength < 1e-12)
    return Error{ErrorCode::InvalidParameter, "the machine's up must be a finite, non-zero vector", "up"};

  Layout layout;
  layout.planes = plan.clippingPlanes;
  layout.platformUp = machine.up / upLength;
  layout.platformHeight = lowestAlong(model, layout.platformUp);
  layout.regionCount = static_cast<int>(plan.regions.size());
  for (std::size_t k = 0; k <= planeCount; ++k) {
    Cell cell;
    // Cell k holds the region plane k cut off, printed at position N-1-k; the last cell holds region 0.
    const std::size_t region = planeCount - k;
    cell.region = static_cast<int>(region);
    cell.mesh = &plan.regions[region].mesh;
    if (k < planeCount) {
      cell.base = plan.clippingPlanes[k];
      cell.up = plan.clippingPlanes[k].normal;
    } else {
      cell.up = layout.platformUp;
    }
    cell.walls.assign(plan.clippingPlanes.begin(), plan.clippingPlanes.begin() + static_cast<std::ptrdiff_t>(k));
    layout.cells.push_back(std::move(cell));
  }
  return grow(model, layout, options, job);
}

Result<ProjectedSupports> generateFixedDirectionSupports(const TriangleMesh& model, const Vec3& up,
                                                         const SupportOptions& options, JobContext& job) {
  if (Status s = checkModel(model, options); !s) return s.error();
  const double upLength = up.norm();
  if (!std::isfinite(upLength) || upLength < 1e-12)
    return Error{ErrorCode::InvalidParameter, "the up direction must be a finite, non-zero vector", "up"};
  Layout layout;
  layout.platformUp = up / upLength;
  layout.platformHeight = lowestAlong(model, layout.platformUp);
  Cell cell;
  cell.region = 0;
  cell.up = layout.platformUp;
  cell.mesh = &model;
  layout.cells.push_back(cell);
  return grow(model, layout, options, job);
}

}  // namespace multidir::core
