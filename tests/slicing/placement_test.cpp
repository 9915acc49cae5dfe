// Before anything is sliced: each step's supports clipped to its base plane, and the part placed on the
// platform where it fits the printer, or refused at once saying by how much.
#include "multidir/slicing/placement.h"

#include <gtest/gtest.h>

#include "multidir/core/mesh/mesh_measure.h"
#include "multidir/slicing/slice_job.h"
#include "support/primitives.h"

using namespace multidir;
using namespace multidir::slicing;
using core::Vec3;

namespace {

PrinterProfile profileNamed(const std::string& name) {
  core::Result<PrinterProfile> p = loadPrinterProfile(name);
  if (!p) throw std::runtime_error(p.error().describe());
  return *p;
}

core::PrintJobStep boxStep(int index, const Vec3& lo, const Vec3& hi) {
  core::PrintJobStep step;
  step.index = index;
  step.region = test::makeBox(lo, hi);
  step.lowestHeightMm = lo.z();
  return step;
}

// A 4-DOF job of two steps about the machine's x axis: step 1 (the model box from lo to hi) at rest, step 2 (the
// box from lo2 to hi2) turned by `degrees`.
core::PrintJob rotaryJob(const Vec3& lo, const Vec3& hi, const Vec3& lo2, const Vec3& hi2, double degrees) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::RotaryPlatform;
  job.machine.rotationAxis = Vec3::UnitX();
  core::PrintJobStep first = boxStep(1, lo, hi);
  core::PrintJobStep second = boxStep(2, lo2, hi2);
  second.angles.rotaryDegrees = degrees;
  second.modelToFile = Eigen::AngleAxisd(-degrees * M_PI / 180.0, Vec3::UnitX());
  for (Vec3& v : second.region.vertices) v = second.modelToFile * v;
  second.lowestHeightMm = core::boundingBox(second.region).min.z();
  job.steps = {first, second};
  return job;
}

}  // namespace

TEST(Placement, SupportsReachingBelowTheBasePlaneAreClippedToItAndStayClosed) {
  // A strut from z 8 to 20 under a step whose base plane is at z 10: what lies below is plastic or air.
  const core::TriangleMesh strut = test::makeBox(Vec3(-1, -1, 8), Vec3(1, 1, 20));
  const core::Result<core::TriangleMesh> clipped = supportsAboveBasePlane(strut, 10.0, 2);
  ASSERT_TRUE(clipped.ok()) << clipped.error().describe();
  EXPECT_NEAR(core::boundingBox(*clipped).min.z(), 10.0, 1e-9);
  EXPECT_NEAR(core::boundingBox(*clipped).max.z(), 20.0, 1e-9);
  EXPECT_TRUE(core::edgeCensus(*clipped).closedOriented());
  EXPECT_NEAR(core::signedVolume(*clipped), 2.0 * 2.0 * 10.0, 1e-6);
  // A strut wholly below the base plane is printed with the lower step: nothing is left of it.
  const core::Result<core::TriangleMesh> below =
      supportsAboveBasePlane(test::makeBox(Vec3(-1, -1, 2), Vec3(1, 1, 9)), 10.0, 2);
  ASSERT_TRUE(below.ok());
  EXPECT_TRUE(below->empty());
}

TEST(Placement, APartOffCentreOnAPlainPrinterIsCentredOnTheBed) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::ThreeAxis;
  job.steps = {boxStep(1, Vec3(20, -10, 0), Vec3(60, 10, 30))};  // its centre 40 mm off the pivot in X
  const core::Result<Placement> placed = placeOnPlatform(job, profileNamed("marlin-220"));
  ASSERT_TRUE(placed.ok()) << placed.error().describe();
  EXPECT_NEAR(placed->offsetMm.x(), -40.0, 1e-9);
  EXPECT_NEAR(placed->offsetMm.y(), 0.0, 1e-9);
  const core::BoundingBox box = core::boundingBox(placed->job.steps[0].region);
  EXPECT_NEAR(box.min.x() + box.max.x(), 0.0, 1e-9);  // centred on the platform centre, the bed's
  EXPECT_NEAR(box.min.z(), 0.0, 1e-9);
}

TEST(Placement, ARotaryPartMovesOnlyAlongTheAxisAndEveryPoseFollows) {
  // Off-centre along the axis (x) and across it (y): only the move along x leaves the turns' sweep alone.
  // Step 2's box, turned by 90 degrees, stands over the platform (y' = z, z' = -y).
  const core::PrintJob job = rotaryJob(Vec3(30, 5, 0), Vec3(70, 25, 20), Vec3(30, -25, 0), Vec3(70, -5, 20), 90.0);
  const core::Result<Placement> placed = placeOnPlatform(job, profileNamed("marlin-220"));
  ASSERT_TRUE(placed.ok()) << placed.error().describe();
  EXPECT_NEAR(placed->offsetMm.x(), -50.0, 1e-9);
  EXPECT_NEAR(placed->offsetMm.y(), 0.0, 1e-9);
  // Every step's mesh is its model mesh under its new pose: one placement on the platform serves both steps.
  for (const core::PrintJobStep& step : placed->job.steps) {
    const core::TriangleMesh model = step.index == 1 ? test::makeBox(Vec3(30, 5, 0), Vec3(70, 25, 20))
                                                     : test::makeBox(Vec3(30, -25, 0), Vec3(70, -5, 20));
    for (std::size_t v = 0; v < model.vertices.size(); ++v)
      ASSERT_LT((step.modelToFile * model.vertices[v] - step.region.vertices[v]).norm(), 1e-9) << "step " << step.index;
    EXPECT_NEAR(step.lowestHeightMm, core::boundingBox(step.region).min.z(), 1e-9);
  }
  // The pivot (the point the platform turns about) is where the rest pose puts the origin.
  EXPECT_LT((placed->job.steps[0].modelToFile * placed->job.platform.center).norm(), 1e-9);
}

TEST(Placement, APartTooBigForTheBedIsRefusedSayingByHowMuchAndWhatWouldFit) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::ThreeAxis;
  job.steps = {boxStep(1, Vec3(-130, -50, 0), Vec3(130, 50, 40))};  // 260 mm on a 220 mm bed
  const core::Result<Placement> placed = placeOnPlatform(job, profileNamed("marlin-220"));
  ASSERT_FALSE(placed.ok());
  EXPECT_EQ(placed.error().code, core::ErrorCode::TooLarge);
  const std::string& m = placed.error().message;
  EXPECT_NE(m.find("step 1 reaches 20.0 mm past the bed's -X side"), std::string::npos) << m;
  EXPECT_NE(m.find("20.0 mm past the bed's +X side"), std::string::npos) << m;
  EXPECT_NE(m.find("scale the model by 0.84 or less"), std::string::npos) << m;
  EXPECT_NE(m.find("at least 260 x 100 mm"), std::string::npos) << m;
}

TEST(Placement, APartTallerThanThePrinterIsRefusedNamingTheHeight) {
  core::PrintJob job;
  job.machine.kind = core::MachineKind::ThreeAxis;
  job.steps = {boxStep(1, Vec3(-10, -10, 0), Vec3(10, 10, 300))};
  const core::Result<Placement> placed = placeOnPlatform(job, profileNamed("marlin-220"));
  ASSERT_FALSE(placed.ok());
  EXPECT_NE(placed.error().message.find("reaches z 300.0 mm, 50.0 mm above the printer's height"), std::string::npos)
      << placed.error().message;
  EXPECT_NE(placed.error().message.find("with 300 mm of height"), std::string::npos) << placed.error().message;
}

TEST(Placement, ARotaryPartThatSwingsPastTheBedWhenTurnedIsRefused) {
  // A part standing 150 mm tall on the axis fits the bed at rest, but turned by 90 degrees it lies 150 mm to one
  // side of the axis, past the 220 mm bed (110 mm from its centre).
  const core::PrintJob job =
      rotaryJob(Vec3(-10, -10, 0), Vec3(10, 10, 150), Vec3(-10, -10, 0), Vec3(10, 10, 150), 90.0);
  const core::Result<Placement> placed = placeOnPlatform(job, profileNamed("marlin-220"));
  ASSERT_FALSE(placed.ok());
  EXPECT_NE(placed.error().message.find("past the bed's"), std::string::npos) << placed.error().message;
}
