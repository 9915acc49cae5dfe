// 5-DOF plans on a printer with two firmware axes, stitched into one program (docs/slicing.md "Two firmware
// axes"), checked by replaying job.gcode with the machine as built written out here: the axes turn only inside
// transitions, with the nozzle above everything printed so far (and the platform) as it sweeps through the
// commanded moves, and every extrusion of a step, carried back through the axes' positions, lies in that step's
// region or supports as the plan made them.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "multidir/core/common/units.h"
#include "multidir/slicing/gcode_program.h"
#include "multidir/slicing/printer_profile.h"
#include "multidir/slicing/slice_job.h"
#include "multidir/slicing/stitch.h"
#include "slicing_fixtures.h"
#include "support/primitives.h"
#include "support/test_models.h"

using namespace multidir;
using namespace multidir::slicing;
using core::Vec3;

namespace {

// The machine as docs/slicing.md describes it: firmware coordinates to the convention's angles, the rotation
// about the platform's normal through rotation_center, the tilt by minus its angle about the line along
// tilt_along at tilt_height through the rotation axis. Printer frame in, printer frame out.
struct BuiltMachine {
  PrinterProfile p;
  [[nodiscard]] Eigen::Isometry3d platformToPrinter(double tiltCoordinate, double rotationCoordinate) const {
    const TwoAxisPlatform& a = p.twoAxis;
    const double t = core::degToRad((tiltCoordinate - a.tilt.zeroDegrees) / a.tilt.direction);
    const double r = core::degToRad((rotationCoordinate - a.rotation.zeroDegrees) / a.rotation.direction);
    const Vec3 rotationPoint(a.rotationCenter.x(), a.rotationCenter.y(), p.platformZMm);
    const Vec3 tiltPoint(a.rotationCenter.x(), a.rotationCenter.y(), a.tiltHeightMm);
    const Vec3 tiltLine = a.tiltAlong == TiltAlong::X ? Vec3::UnitX() : Vec3::UnitY();
    Eigen::Isometry3d rotate = Eigen::Isometry3d::Identity();
    rotate.translate(rotationPoint).rotate(Eigen::AngleAxisd(r, Vec3::UnitZ())).translate(-rotationPoint);
    Eigen::Isometry3d tilt = Eigen::Isometry3d::Identity();
    tilt.translate(tiltPoint).rotate(Eigen::AngleAxisd(-t, tiltLine)).translate(-tiltPoint);
    return tilt * rotate;
  }
};

// Is a point inside a closed mesh or within `tolerance` of its surface? Triangles bucketed in a grid of cells.
class NearSolid {
 public:
  NearSolid(std::vector<core::TriangleMesh> meshes, double tolerance) : m_meshes(std::move(meshes)), m_tol(tolerance) {
    for (std::size_t m = 0; m < m_meshes.size(); ++m)
      for (std::size_t f = 0; f < m_meshes[m].faceCount(); ++f) {
        Eigen::AlignedBox3d box;
        for (int i = 0; i < 3; ++i) box.extend(m_meshes[m].corner(f, i));
        const Eigen::Vector3i lo = cell(box.min().array() - m_tol), hi = cell(box.max().array() + m_tol);
        for (int x = lo.x(); x <= hi.x(); ++x)
          for (int y = lo.y(); y <= hi.y(); ++y) {
            m_columns[{x, y}].push_back({m, f});
            for (int z = lo.z(); z <= hi.z(); ++z) m_cells[{x, y, z}].push_back({m, f});
          }
      }
  }
  [[nodiscard]] bool contains(const Vec3& q) const {
    const Eigen::Vector3i c = cell(q);
    if (const auto it = m_cells.find({c.x(), c.y(), c.z()}); it != m_cells.end())
      for (const auto& [m, f] : it->second)
        if (distance(q, m_meshes[m].corner(f, 0), m_meshes[m].corner(f, 1), m_meshes[m].corner(f, 2)) <= m_tol)
          return true;
    // Inside one of the meshes: an odd number of its faces above the point (a ray nudged off the grid's lines).
    const Vec3 p = q + Vec3(1.3e-7, 1.7e-7, 0.0);
    const auto column = m_columns.find({c.x(), c.y()});
    if (column == m_columns.end()) return false;
    std::vector<int> crossings(m_meshes.size(), 0);
    for (const auto& [m, f] : column->second) {
      const Vec3 &a = m_meshes[m].corner(f, 0), &b = m_meshes[m].corner(f, 1), &d = m_meshes[m].corner(f, 2);
      const double area = (b.x() - a.x()) * (d.y() - a.y()) - (d.x() - a.x()) * (b.y() - a.y());
      if (std::abs(area) < 1e-15) continue;
      const double u = ((b.x() - p.x()) * (d.y() - p.y()) - (d.x() - p.x()) * (b.y() - p.y())) / area;
      const double v = ((d.x() - p.x()) * (a.y() - p.y()) - (a.x() - p.x()) * (d.y() - p.y())) / area;
      const double w = 1.0 - u - v;
      if (u < 0 || v < 0 || w < 0) continue;
      if (u * a.z() + v * b.z() + w * d.z() > p.z()) ++crossings[m];
    }
    return std::any_of(crossings.begin(), crossings.end(), [](int n) { return n % 2 == 1; });
  }

 private:
  static constexpr double kCell = 2.0;
  static Eigen::Vector3i cell(const Eigen::Array3d& p) { return (p / kCell).floor().cast<int>(); }
  static double distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Closest point on a triangle (Ericson, Real-Time Collision Detection 5.1.5).
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return ap.norm();
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return bp.norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return cp.norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
      return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
    const double denom = 1.0 / (va + vb + vc);
    return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
  }
  std::vector<core::TriangleMesh> m_meshes;
  double m_tol;
  std::map<std::tuple<int, int, int>, std::vector<std::pair<std::size_t, std::size_t>>> m_cells;
  std::map<std::pair<int, int>, std::vector<std::pair<std::size_t, std::size_t>>> m_columns;
};

core::TriangleMesh movedMesh(core::TriangleMesh mesh, const Eigen::Isometry3d& motion) {
  for (Vec3& v : mesh.vertices) v = motion * v;
  return mesh;
}

struct Case {
  const char* model;
  double scale;
  Dialect dialect;
};

std::string caseName(const testing::TestParamInfo<Case>& info) {
  std::string model = info.param.model;
  model = model.substr(0, model.find('.'));
  return model + "_" + dialectName(info.param.dialect);
}

class TwoAxisStitch : public testing::TestWithParam<Case> {};

}  // namespace

TEST_P(TwoAxisStitch, TheReplayedProgramPrintsEveryStepOnItsRegionAndTurnsOnlyAboveWhatItSweeps) {
  const Case c = GetParam();
  core::MachineSpec machine;
  machine.kind = core::MachineKind::TiltRotate;
  machine.up = Vec3::UnitY();
  const core::LoadedPlan plan = test::plannedInMemory(test::loadSharedModel(c.model), machine, c.model, c.scale);
  const core::PrintJob job = test::machineJob(plan);
  ASSERT_GE(job.steps.size(), 2u) << c.model << "'s plan should have more than one region";
  const core::Result<PrinterProfile> profile = loadPrinterProfile("open5x-rrf");
  ASSERT_TRUE(profile.ok()) << profile.error().describe();
  SliceJobOptions options;
  options.settings = test::coarseSettings(0.3);
  // No skirt or brim: every extrusion after the step marker is then the step's own region or supports.
  options.settings.push_back({"skirts", "0"});
  options.settings.push_back({"brim_width", "0"});
  options.fixedDirection = false;
  options.dialect = c.dialect;
  const std::string dir = test::scratchDirectory(std::string("two_axis_stitch.") + caseName({c, 0}));
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, *profile, options, dir, context);
  ASSERT_TRUE(sliced.ok()) << sliced.error().describe();
  ASSERT_EQ(sliced->stitchedFile, "job.gcode");

  const core::Result<GcodeProgram> program =
      parseGcode(test::readFile(dir + "/job.gcode"), rotaryAxisNames(*profile), "job.gcode");
  ASSERT_TRUE(program.ok()) << program.error().describe();
  const BuiltMachine built{*profile};
  const Eigen::Isometry3d rest = job.steps.front().modelToFile;
  Eigen::Isometry3d restToPrinter = Eigen::Isometry3d::Identity();
  restToPrinter.translate(Vec3(profile->platformCenter.x(), profile->platformCenter.y(), profile->platformZMm) +
                          sliced->placementMm);

  // Each step's solid as the plan made it (region and supports), in the printer's frame at rest.
  std::vector<core::TriangleMesh> solids;
  for (const core::PrintJobStep& step : job.steps) {
    const Eigen::Isometry3d toRest = restToPrinter * rest * step.modelToFile.inverse();
    solids.push_back(movedMesh(step.region, toRest));
    if (!step.supports.empty()) solids.push_back(movedMesh(step.supports, toRest));
  }

  std::map<int, int> checked;
  double tilt = 0.0, rotation = 0.0;
  std::size_t printedUpTo = 0;  // solids[0, printedUpTo) are printed
  std::vector<Vec3> printed;
  double largestTilt = 0.0;
  for (const GcodeMove& move : program->moves) {
    if (move.rotates()) {
      ASSERT_TRUE(move.inTransition) << "line " << move.line << " turns the platform outside a transition";
      // The nozzle stands above everything printed (and the platform) wherever this move sweeps it.
      double top = -1e300;
      for (int i = 0; i <= 200; ++i) {
        const double s = i / 200.0;
        const Eigen::Isometry3d pose =
            built.platformToPrinter(move.rotaryFromDegrees + s * (move.rotaryToDegrees - move.rotaryFromDegrees),
                                    move.secondFromDegrees + s * (move.secondToDegrees - move.secondFromDegrees));
        for (const Vec3& q : printed) top = std::max(top, (pose * q).z());
      }
      EXPECT_GT(move.from.z(), top) << "line " << move.line << ": the nozzle waits at z " << move.from.z()
                                    << " but the part sweeps up to " << top;
      largestTilt = std::max(largestTilt, std::abs(move.rotaryToDegrees));
    }
    tilt = move.rotaryToDegrees;
    rotation = move.secondToDegrees;
    if (!move.extrudes() || move.step < 1 || move.inTransition) continue;
    const int k = move.step;
    // Step k prints: everything of steps 1..k is (or is being) printed.
    std::size_t upTo = 0;
    for (std::size_t s = 0, index = 0; s < job.steps.size() && static_cast<int>(s) < k; ++s)
      upTo = (index += job.steps[s].supports.empty() ? 1 : 2);
    for (; printedUpTo < upTo; ++printedUpTo)
      for (const Vec3& v : solids[printedUpTo].vertices) printed.push_back(v);
    ++checked[k];
    if (checked[k] % 7 != 1) continue;  // every seventh extrusion: enough to catch a wrong pose, quick
    const Vec3 back = built.platformToPrinter(tilt, rotation).inverse() * move.to;
    const std::size_t first = upTo - (job.steps[static_cast<std::size_t>(k - 1)].supports.empty() ? 1 : 2);
    std::vector<core::TriangleMesh> own(solids.begin() + static_cast<std::ptrdiff_t>(first),
                                        solids.begin() + static_cast<std::ptrdiff_t>(upTo));
    static std::map<int, NearSolid> near;
    if (checked[k] == 1) near.erase(k), near.emplace(k, NearSolid(own, 0.5));
    ASSERT_TRUE(near.at(k).contains(back)) << "line " << move.line << ": step " << k << "'s extrusion at ("
                                           << move.to.transpose() << ") lies at (" << back.transpose()
                                           << ") on the part, outside its region and supports";
  }
  for (const core::PrintJobStep& step : job.steps) EXPECT_GT(checked[step.index], 0) << "step " << step.index;
  EXPECT_GT(largestTilt, 10.0) << "the plan should tilt the platform";
}

INSTANTIATE_TEST_SUITE_P(KittenAndBunny, TwoAxisStitch,
                         testing::Values(Case{"kitten.off", 0.4, Dialect::RepRapFirmware},
                                         Case{"kitten.off", 0.4, Dialect::Klipper},
                                         Case{"kitten.off", 0.4, Dialect::Marlin},
                                         Case{"bunny.off", 0.4, Dialect::RepRapFirmware},
                                         Case{"bunny.off", 0.4, Dialect::Klipper},
                                         Case{"bunny.off", 0.4, Dialect::Marlin}),
                         caseName);

TEST(TwoAxisStitch, APlanNeedingATiltPastTheLimitIsRefusedNamingTheStep) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::TiltRotate;
  job.options.frame = core::PrintJobOptions::Frame::Machine;
  for (int k = 0; k < 2; ++k) {
    core::PrintJobStep step;
    step.index = k + 1;
    step.region = test::makeBox(Vec3(-5, -5, 10.0 * k), Vec3(5, 5, 10.0 * (k + 1)));
    step.regionFile = "step-0" + std::to_string(k + 1) + "-region.stl";
    // Step 2 prints 100 degrees from up: beyond the profile's +-90 degree tilt.
    step.printingDirection = k == 0 ? Vec3::UnitZ()
                                    : Vec3(0.0, std::sin(100.0 * M_PI / 180.0), std::cos(100.0 * M_PI / 180.0));
    job.steps.push_back(step);
  }
  const core::Result<PrinterProfile> profile = loadPrinterProfile("open5x-rrf");
  ASSERT_TRUE(profile.ok()) << profile.error().describe();
  SliceJobOptions options;
  options.slicerExecutable = "/nonexistent/prusa-slicer";  // reached only if the refusal were missing
  options.fixedDirection = false;
  const std::string dir = test::scratchDirectory("two_axis_stitch.refused") + "/out";
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, *profile, options, dir, context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_EQ(sliced.error().code, core::ErrorCode::InvalidParameter) << sliced.error().describe();
  EXPECT_EQ(sliced.error().where, "step 2") << sliced.error().describe();
  EXPECT_NE(sliced.error().message.find("tilt of"), std::string::npos) << sliced.error().message;
  EXPECT_NE(sliced.error().message.find("100.0"), std::string::npos) << sliced.error().message;
}

TEST(TwoAxisStitch, AStepWhoseBasePlaneLiesBelowTheTiltedPlatformsRimIsRefusedBeforeSlicing) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::TiltRotate;
  job.options.frame = core::PrintJobOptions::Frame::Machine;
  job.platform.radiusMm = 60.0;
  for (int k = 0; k < 2; ++k) {
    core::PrintJobStep step;
    step.index = k + 1;
    // A wide platform; step 2 prints 60 degrees towards +Y: the platform tilts by 60 degrees, its rim rising
    // 52 mm, but step 2's base (y 10 at rest) only to 8.7 mm.
    step.region = k == 0 ? test::makeBox(Vec3(-5, -5, 0.0), Vec3(5, 20, 1.0)) : test::makeBox(Vec3(-5, 10, 1.0), Vec3(5, 20, 3.0));
    step.regionFile = "step-0" + std::to_string(k + 1) + "-region.stl";
    step.printingDirection = k == 0 ? Vec3::UnitZ() : Vec3(0.0, std::sin(M_PI / 3.0), std::cos(M_PI / 3.0));
    job.steps.push_back(step);
  }
  const core::Result<PrinterProfile> profile = loadPrinterProfile("open5x-rrf");
  ASSERT_TRUE(profile.ok()) << profile.error().describe();
  SliceJobOptions options;
  options.slicerExecutable = "/nonexistent/prusa-slicer";
  options.fixedDirection = false;
  const std::string dir = test::scratchDirectory("two_axis_stitch.body") + "/out";
  core::JobContext context;
  const core::Result<SlicedJob> sliced = sliceJob(job, *profile, options, dir, context);
  ASSERT_FALSE(sliced.ok());
  EXPECT_NE(sliced.error().message.find("step 2"), std::string::npos) << sliced.error().describe();
  EXPECT_NE(sliced.error().message.find("platform's body"), std::string::npos) << sliced.error().describe();
}
