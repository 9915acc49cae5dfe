#include "multidir/slicing/placement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "multidir/core/geometry/clipping.h"
#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/slicing/clearance.h"
#include "multidir/slicing/slice_job.h"

namespace multidir::slicing {

namespace {

using core::Error;
using core::ErrorCode;
using core::Vec3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Overhangs below this are rounding, not a part off the bed (the G-code checks allow 1e-3 mm).
constexpr double kFitToleranceMm = 1e-3;

std::string mm(double value, int digits = 1) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

struct Box {
  Vec3 lo = Vec3::Constant(kInfinity);
  Vec3 hi = Vec3::Constant(-kInfinity);
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool empty() const { return !(lo.x() <= hi.x()); }
  Box shifted(const Vec3& by) const { return empty() ? *this : Box{lo + by, hi + by}; }
};

// The rotation taking the rest pose (step 1's) to step k's, machine frame, about the pivot (the origin).
Eigen::Matrix3d restToStep(const core::PrintJob& job, std::size_t k) {
  return job.steps[k].modelToFile.linear() * job.steps.front().modelToFile.linear().transpose();
}

// What must stay on the bed, machine frame at offset 0: each step's part as posed for it, and (4-DOF) the part
// printed up to step k swept through the turn after it, in XY.
struct Extents {
  std::vector<Box> parts;       // one per step
  std::vector<Box> sweeps;      // one per turn (4-DOF); XY only (z 0: heights are planTurns' clearance)
  Vec3 axis = Vec3::UnitX();    // 4-DOF: the rotation axis, machine frame (rest pose)
};

// How the part moves between steps, for placing it: as the plan's machine does, except on two firmware axes,
// which turn it about their own lines for any plan (its turns' heights are planTurns', like a robot arm's).
core::MachineKind motionKind(const core::PrintJob& job, const PrinterProfile& profile) {
  return profile.platform == PlatformDrive::FirmwareTwoAxis && job.steps.size() > 1 ? core::MachineKind::TiltRotate
                                                                                      : job.machine.kind;
}

Extents extentsOf(const core::PrintJob& job, core::MachineKind kind) {
  Extents e;
  for (const core::PrintJobStep& step : job.steps) {
    Box b;
    for (const core::TriangleMesh* mesh : {&step.region, &step.supports})
      for (const Vec3& v : mesh->vertices) b.add(v);
    e.parts.push_back(b);
  }
  if (kind != core::MachineKind::RotaryPlatform) return e;
  e.axis = (job.steps.front().modelToFile.linear() * job.machine.rotationAxis.normalized()).normalized();
  for (std::size_t k = 0; k + 1 < job.steps.size(); ++k) {
    const std::vector<Vec3> points = printedPoints(job, k);
    const double turnRadians =
        -(job.steps[k + 1].angles.rotaryDegrees - job.steps[k].angles.rotaryDegrees) * M_PI / 180.0;
    const Vec3 axisK = job.steps[k].modelToFile.linear() * job.machine.rotationAxis.normalized();
    Box swept;
    swept.lo.x() = -sweptMax(points, axisK, turnRadians, -Vec3::UnitX());
    swept.hi.x() = sweptMax(points, axisK, turnRadians, Vec3::UnitX());
    swept.lo.y() = -sweptMax(points, axisK, turnRadians, -Vec3::UnitY());
    swept.hi.y() = sweptMax(points, axisK, turnRadians, Vec3::UnitY());
    swept.lo.z() = 0.0;
    swept.hi.z() = 0.0;  // heights: planTurns' clearance
    e.sweeps.push_back(swept);
  }
  return e;
}

// Everything at offset d, in the printer's frame.
struct Placed {
  std::vector<Box> parts;
  std::vector<Box> sweeps;
  Box all;  // XY of every part and sweep
};

Placed placedAt(const core::PrintJob& job, const Extents& e, const Vec3& d, const PrinterProfile& profile) {
  const Vec3 printer(profile.platformCenter.x(), profile.platformCenter.y(), profile.platformZMm);
  Placed p;
  for (std::size_t k = 0; k < e.parts.size(); ++k) {
    p.parts.push_back(e.parts[k].shifted(restToStep(job, k) * d + printer));
    p.all.add(p.parts.back());
  }
  // A move along the axis is not changed by turns about it (4-DOF moves only along it).
  for (const Box& s : e.sweeps) {
    p.sweeps.push_back(s.shifted(d + printer));
    p.all.add(p.sweeps.back());
  }
  return p;
}

Eigen::Vector2d bedCentre(const PrinterProfile& profile) { return 0.5 * (profile.bedMin() + profile.bedMax()); }

Eigen::Vector2d centreXy(const Box& b) { return 0.5 * (b.lo.head<2>() + b.hi.head<2>()); }

// The largest distance anything reaches past the bed's sides (negative: the smallest room left).
double worstOverhang(const Placed& p, const PrinterProfile& profile) {
  const Eigen::Vector2d lo = profile.bedMin(), hi = profile.bedMax();
  return std::max({lo.x() - p.all.lo.x(), p.all.hi.x() - hi.x(), lo.y() - p.all.lo.y(), p.all.hi.y() - hi.y()});
}

// The worst of everything's overhang past the bed's sides, above the printer's height and below the bed, as
// placed (negative: the least room left).
double worstViolation(const Placed& p, const PrinterProfile& profile) {
  double worst = worstOverhang(p, profile);
  for (const Box& b : p.parts) worst = std::max({worst, b.hi.z() - profile.maxPrintHeightMm, -b.lo.z()});
  return worst;
}

// What the 5-DOF search minimises: the worst violation, then (a thousandth as much) each axis' worse side, so
// that an axis which does not decide the worst is still balanced between its two sides.
double searchCost(const core::PrintJob& job, const Extents& e, const Vec3& d, const PrinterProfile& profile) {
  const Placed p = placedAt(job, e, d, profile);
  const Eigen::Vector2d lo = profile.bedMin(), hi = profile.bedMax();
  const double x = std::max(lo.x() - p.all.lo.x(), p.all.hi.x() - hi.x());
  const double y = std::max(lo.y() - p.all.lo.y(), p.all.hi.y() - hi.y());
  return worstViolation(p, profile) + 1e-3 * (x + y);
}

Vec3 chooseOffset(const core::PrintJob& job, const Extents& e, const PrinterProfile& profile, core::MachineKind kind) {
  const Placed atZero = placedAt(job, e, Vec3::Zero(), profile);
  const Eigen::Vector2d miss = bedCentre(profile) - centreXy(atZero.all);
  switch (kind) {
    case core::MachineKind::ThreeAxis:
      return Vec3(miss.x(), miss.y(), 0.0);
    case core::MachineKind::RotaryPlatform: {
      Eigen::Vector2d along = e.axis.head<2>();
      if (along.norm() < 1e-9) return Vec3::Zero();
      along.normalize();
      const double t = along.dot(miss);
      return Vec3(t * along.x(), t * along.y(), 0.0);
    }
    case core::MachineKind::TiltRotate:
    case core::MachineKind::Apart:
      break;
  }
  // 5-DOF: the plan centres the first region's footprint on the platform (the pivot), and every step moves by
  // its own Q_k d: a move raises or lowers every tilted step and swings it wider. The part stays where the plan
  // put it when it fits there; else the offset that leaves the most room over every side, the height and the
  // bed (the worst overhang is convex in d: a pattern search finds its least).
  if (worstViolation(atZero, profile) <= kFitToleranceMm) return Vec3::Zero();
  Vec3 d = Vec3::Zero();
  double best = searchCost(job, e, d, profile);
  for (double step = 32.0; step > 0.01;) {
    bool moved = false;
    for (const Eigen::Vector2d& direction : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1),
                                             Eigen::Vector2d(0, -1), Eigen::Vector2d(1, 1), Eigen::Vector2d(1, -1),
                                             Eigen::Vector2d(-1, 1), Eigen::Vector2d(-1, -1)}) {
      const Vec3 candidate = d + Vec3(direction.x(), direction.y(), 0.0) * step;
      const double v = searchCost(job, e, candidate, profile);
      if (v < best - 1e-9) {
        best = v;
        d = candidate;
        moved = true;
      }
    }
    if (!moved) step *= 0.5;
  }
  return d;
}

core::PrintJob movedBy(const core::PrintJob& job, const Vec3& d) {
  core::PrintJob out = job;
  // The pivot in the model: the point that goes to the origin of the rest pose once the part moved by d.
  out.platform.center = job.steps.front().modelToFile.inverse() * (-d);
  for (std::size_t k = 0; k < out.steps.size(); ++k) {
    core::PrintJobStep& step = out.steps[k];
    const Vec3 shift = restToStep(job, k) * d;
    step.modelToFile.pretranslate(shift);
    for (core::TriangleMesh* mesh : {&step.region, &step.supports})
      for (Vec3& v : mesh->vertices) v += shift;
    step.lowestHeightMm += shift.z();
  }
  return out;
}

struct Overhang {
  double mm = 0.0;
  int step = 0;
  bool swept = false;
};

std::string sideText(const char* side, const Overhang& o, bool first) {
  return (first ? "" : ", ") + std::string("step ") + std::to_string(o.step) + (o.swept ? " sweeps " : " reaches ") +
         mm(o.mm) + " mm past the bed's " + side + " side" + (o.swept ? " while the platform turns after it" : "");
}

}  // namespace

core::Result<core::TriangleMesh> supportsAboveBasePlane(const core::TriangleMesh& supports, double baseZMm, int step) {
  core::TriangleMesh out;
  if (supports.empty()) return out;
  bool anyBelow = false;
  for (const Vec3& v : supports.vertices) anyBelow = anyBelow || v.z() < baseZMm;
  if (!anyBelow) return supports;
  const core::FaceComponents components = core::faceComponents(supports);
  std::vector<core::TriangleMesh> solids(static_cast<std::size_t>(components.count));
  std::vector<std::vector<std::int32_t>> remap(solids.size());
  for (std::size_t f = 0; f < supports.faceCount(); ++f) {
    const auto c = static_cast<std::size_t>(components.componentOfFace[f]);
    core::TriangleMesh& solid = solids[c];
    std::vector<std::int32_t>& index = remap[c];
    if (index.empty()) index.assign(supports.vertexCount(), -1);
    core::Triangle t{};
    for (int i = 0; i < 3; ++i) {
      const std::int32_t v = supports.triangles[f][static_cast<std::size_t>(i)];
      if (index[static_cast<std::size_t>(v)] < 0) {
        index[static_cast<std::size_t>(v)] = static_cast<std::int32_t>(solid.vertices.size());
        solid.vertices.push_back(supports.vertices[static_cast<std::size_t>(v)]);
      }
      t[static_cast<std::size_t>(i)] = index[static_cast<std::size_t>(v)];
    }
    solid.triangles.push_back(t);
    solid.origins.push_back(f < supports.origins.size() ? supports.origins[f] : core::FaceOrigin{});
  }
  remap.clear();
  const core::Plane base{Vec3::UnitZ(), baseZMm};
  for (std::size_t c = 0; c < solids.size(); ++c) {
    core::TriangleMesh& solid = solids[c];
    double low = kInfinity, high = -kInfinity;
    for (const Vec3& v : solid.vertices) {
      low = std::min(low, v.z());
      high = std::max(high, v.z());
    }
    if (high <= baseZMm) continue;  // wholly below: printed with the lower step, or resting on it
    core::TriangleMesh kept;
    if (low >= baseZMm) {
      kept = std::move(solid);
    } else {
      core::Result<core::ClipResult> clipped = core::clipByPlane(solid, base, -1);
      if (!clipped)
        return Error{clipped.error().code,
                     "step " + std::to_string(step) + ": a support strut cannot be clipped to the step's base plane (z " +
                         mm(baseZMm, 3) + " mm): " + clipped.error().message +
                         "; regrow the supports (multidir decompose) or slice without them",
                     "supports"};
      kept = std::move(clipped->above);
    }
    const auto offset = static_cast<std::int32_t>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), kept.vertices.begin(), kept.vertices.end());
    for (const core::Triangle& t : kept.triangles) out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    out.origins.insert(out.origins.end(), kept.origins.begin(), kept.origins.end());
  }
  return out;
}

core::Result<core::PrintJob> withSupportsOnTheirBasePlanes(const core::PrintJob& job) {
  core::PrintJob out = job;
  for (core::PrintJobStep& step : out.steps) {
    core::Result<core::TriangleMesh> clipped = supportsAboveBasePlane(step.supports, step.lowestHeightMm, step.index);
    if (!clipped) return clipped.error();
    if (clipped->vertices.size() != step.supports.vertices.size() || clipped->faceCount() != step.supports.faceCount())
      step.supportVolumeMm3 = core::signedVolume(*clipped);
    step.supports = std::move(clipped).value();
    if (step.supports.empty()) step.supportsFile.clear();
  }
  return out;
}

core::Result<Placement> placeOnPlatform(const core::PrintJob& job, const PrinterProfile& profile) {
  if (job.options.frame != core::PrintJobOptions::Frame::Machine)
    return Error{ErrorCode::InvalidParameter, "placing the part needs the job in the machine frame", "print job"};
  if (job.steps.empty()) return Error{ErrorCode::InvalidParameter, "the job has no steps", "print job"};
  const core::MachineKind kind = motionKind(job, profile);
  const Extents extents = extentsOf(job, kind);
  Placement placement;
  placement.offsetMm = chooseOffset(job, extents, profile, kind);
  placement.job = movedBy(job, placement.offsetMm);
  const Placed p = placedAt(job, extents, placement.offsetMm, profile);

  const Eigen::Vector2d lo = profile.bedMin(), hi = profile.bedMax();
  Overhang minusX, plusX, minusY, plusY, top, bottom;
  const auto worse = [](Overhang& o, double by, int step, bool swept) {
    if (by > o.mm) o = {by, step, swept};
  };
  const auto measure = [&](const Box& b, int step, bool swept) {
    worse(minusX, lo.x() - b.lo.x(), step, swept);
    worse(plusX, b.hi.x() - hi.x(), step, swept);
    worse(minusY, lo.y() - b.lo.y(), step, swept);
    worse(plusY, b.hi.y() - hi.y(), step, swept);
    if (swept) return;
    worse(top, b.hi.z() - profile.maxPrintHeightMm, step, false);
    worse(bottom, -b.lo.z(), step, false);
  };
  for (std::size_t k = 0; k < p.parts.size(); ++k) measure(p.parts[k], job.steps[k].index, false);
  for (std::size_t k = 0; k < p.sweeps.size(); ++k) measure(p.sweeps[k], job.steps[k].index, true);

  // The turns' clearance (planTurns) on the placed job: the nozzle waits above the swept part.
  const core::Result<std::vector<TurnPlan>> turns = planTurns(placement.job, profile, placement.offsetMm);
  if (!turns) return turns.error();
  placement.turns = *turns;
  Overhang clearance;
  double highestClearance = -kInfinity;
  for (const TurnPlan& t : *turns) {
    worse(clearance, t.clearanceZMm - profile.maxPrintHeightMm, t.fromStep, true);
    highestClearance = std::max(highestClearance, t.clearanceZMm);
  }

  const double t = kFitToleranceMm;
  if (minusX.mm <= t && plusX.mm <= t && minusY.mm <= t && plusY.mm <= t && top.mm <= t && bottom.mm <= t &&
      clearance.mm <= t)
    return placement;

  // Refused: say where, by how much, and what would fit.
  std::string where;
  bool first = true;
  const std::pair<const char*, const Overhang*> sides[] = {{"-X", &minusX}, {"+X", &plusX}, {"-Y", &minusY}, {"+Y", &plusY}};
  for (const auto& [side, o] : sides)
    if (o->mm > t) {
      where += sideText(side, *o, first);
      first = false;
    }
  double highestZ = -kInfinity;
  for (const Box& b : p.parts) highestZ = std::max(highestZ, b.hi.z());
  if (top.mm > t) {
    where += (first ? "" : ", ") + std::string("step ") + std::to_string(top.step) + " reaches z " +
             mm(top.mm + profile.maxPrintHeightMm) + " mm, " + mm(top.mm) + " mm above the printer's height";
    first = false;
  }
  if (clearance.mm > t) {
    where += (first ? "" : ", ") + std::string("after step ") + std::to_string(clearance.step) +
             " the nozzle would have to wait at z " + mm(clearance.mm + profile.maxPrintHeightMm) +
             " mm above the part the platform's turn sweeps (" + mm(clearance.mm) + " mm above the printer's height)";
    first = false;
  }
  if (bottom.mm > t) {
    where += (first ? "" : ", ") + std::string("step ") + std::to_string(bottom.step) + " would print " +
             mm(bottom.mm) + " mm below the bed (z 0)";
    first = false;
  }
  const Vec3 span = p.all.hi - p.all.lo;
  const Eigen::Vector2d bed = hi - lo;
  const double heightFromPlatform = profile.maxPrintHeightMm - profile.platformZMm;
  // A scaled part scales about the pivot. Along an axis it moves freely on (3-DOF both; 4-DOF its rotation
  // axis) it is centred again, so the spans decide; across, it stays where the plan put it (5-DOF: a smaller
  // part fits there), so each side's reach from the pivot does. The bed a printer needs likewise.
  const Placed planned = kind == core::MachineKind::TiltRotate
                             ? placedAt(job, extents, Vec3::Zero(), profile)
                             : p;
  const Eigen::Vector2d pivot = profile.platformCenter;
  double scale = kInfinity;
  Eigen::Vector2d neededBed = Eigen::Vector2d::Zero();
  for (int axis = 0; axis < 2; ++axis) {
    const bool free = kind == core::MachineKind::ThreeAxis ||
                      (kind == core::MachineKind::RotaryPlatform && std::abs(extents.axis[axis]) > 1.0 - 1e-6);
    if (free) {
      scale = std::min(scale, bed[axis] / span[axis]);
      neededBed[axis] = span[axis];
      continue;
    }
    const double below = pivot[axis] - planned.all.lo[axis], above = planned.all.hi[axis] - pivot[axis];
    if (below > 0.0) scale = std::min(scale, (pivot[axis] - lo[axis]) / below);
    if (above > 0.0) scale = std::min(scale, (hi[axis] - pivot[axis]) / above);
    neededBed[axis] = 2.0 * std::max(below, above);
  }
  if (highestZ - profile.platformZMm > 0.0) scale = std::min(scale, heightFromPlatform / (highestZ - profile.platformZMm));
  for (const TurnPlan& turn : *turns) {
    const double swept = turn.sweptTopZMm - profile.platformZMm;
    if (swept > 0.0) scale = std::min(scale, (heightFromPlatform - profile.clearanceMarginMm) / swept);
  }
  // A part printed below the bed where the plan put it is not helped by scaling (z scales about the platform);
  // one the search moved there is, as a smaller part stays where the plan put it.
  bool belowWherePlanned = false;
  for (const Box& b : placedAt(job, extents, Vec3::Zero(), profile).parts) belowWherePlanned |= b.lo.z() < -t;
  std::string help;
  if (!belowWherePlanned && scale > 0.0 && scale < 1.0) {
    const double fits = std::floor(scale * 100.0) / 100.0;
    help = "scale the model by " + mm(fits, 2) + " or less (multidir decompose --scale " + mm(fits, 2) + "), or ";
  }
  const double neededHeight = std::max(highestZ, highestClearance);
  help += "use a printer whose bed is at least " + mm(std::ceil(neededBed.x()), 0) + " x " +
          mm(std::ceil(neededBed.y()), 0) + " mm (the platform at its centre)" + (neededHeight > profile.maxPrintHeightMm ? " with " + mm(std::ceil(neededHeight), 0) + " mm of height" : "");
  const std::string placed = placement.offsetMm.norm() > 1e-6 ? "placed where it has the most room (moved X " +
                                                                   mm(placement.offsetMm.x()) + ", Y " +
                                                                   mm(placement.offsetMm.y()) + " mm on the platform)"
                                                             : "placed where it has the most room";
  return Error{ErrorCode::TooLarge,
               "the part does not fit the printer '" + profile.name + "' (bed X " + mm(lo.x()) + " to " + mm(hi.x()) +
                   ", Y " + mm(lo.y()) + " to " + mm(hi.y()) + " mm, max_print_height " +
                   mm(profile.maxPrintHeightMm) + " mm), even " + placed + ": " + where +
                   ". All steps together span " + mm(span.x()) + " x " + mm(span.y()) + " mm; " + help +
                   ". Nothing was sliced",
               profile.path};
}

}  // namespace multidir::slicing
