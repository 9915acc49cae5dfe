#pragma once
// Projected tree supports (the paper's Section V, Algorithm 2) for a decomposition, and the same generator
// along one fixed direction (the baseline of an ordinary printer).
//
// Sub-spaces (the paper's Eq. 6). With clipping planes gamma_0..gamma_{P-1} in clipping order (0-based here;
// the paper counts from 1), the region cut off by plane k is printed at position N-1-k (N = P + 1 regions)
// and lies in
//     Omega_k = { x : gamma_j.signedDistance(x) <= 0 for all j < k, and gamma_k.signedDistance(x) >= 0 },
// the first region (printed on the platform) in { x : signedDistance <= 0 for every plane }. These cells
// partition space: a point belongs to the cell of the first plane it lies above, or to the first region's.
//
// Growth. Each region's overhang samples (overhang_sampling.h) get a contact tip; the tips grow down its
// printing direction inside its cell, merging greedily where their cones of half-angle strutAngleDegrees
// meet before either would reach the model, the region's base plane or the platform (Vanek et al. 2014).
// Cells are processed in clipping order (last printed region first); a strut that reaches its base plane
// without meeting the model continues from there in the cell below, along that cell's printing direction,
// where it may merge with that region's struts (progressive projection). A strut that meets a wall of its
// cell (a plane of a region printed later) slides along it. A strut ends on the model (with a tip), on
// another strut, or on the platform (the plane through the model's lowest point along the machine's up).
//
// Radii (the paper's Eq. 14): R_p = (1 + lambda |sum_i V_i ((c_i - a_p) x g)|) R/4 over every piece i above
// strut p (volume V_i, centroid c_i), a_p the top of p, g the unit gravity of the printing directions under
// which those pieces stand on p (the largest torque over them). The paper writes c_i x g; the torque about
// the strut's top is that expression with the origin moved there, which makes it independent of where the
// model sits in space.
#include <vector>

#include "multidir/core/common/job_context.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/core/supports/overhang_sampling.h"
#include "multidir/core/supports/support_set.h"

namespace multidir::core {

struct SupportStatistics {
  int faceSamples = 0;
  int edgeSamples = 0;
  int pointSamples = 0;
  int droppedSamples = 0;  // samples whose tip would leave their cell or enter the model
  int merges = 0;
  int projections = 0;     // struts carried across a base plane into the cell below
  int onPlatform = 0;      // struts ending on the platform
  int onModel = 0;         // struts ending on the model
  int stuck = 0;           // struts that could not go on (a wall too steep to slide along)
  double seconds = 0.0;
};

struct ProjectedSupports {
  std::vector<SupportSet> regions;       // one per region, in printing order (empty sets included)
  // The whole structure: every strut with the printing position of the region it is printed with.
  std::vector<SupportNode> nodes;
  std::vector<SupportStrut> struts;
  std::vector<int> strutRegion;
  double volumeMm3 = 0.0;
  double contactAreaMm2 = 0.0;
  int contacts = 0;
  SupportStatistics statistics;
};

// Supports for `plan` (regions in printing order, as decompose returns them or loadPlan reads them) of
// `model` (the whole closed model the plan was cut from: struts are kept out of it). `machine.up` gives the
// platform. Cancellation is checked once per cell and once per 64 struts grown.
// Errors: InvalidParameter (options, an empty plan or one whose regions do not match its planes), EmptyMesh,
// Cancelled.
Result<ProjectedSupports> generateSupports(const TriangleMesh& model, const Decomposition& plan,
                                           const MachineSpec& machine, const SupportOptions& options,
                                           JobContext& job);

// The baseline: `model` printed whole along `up` (unit), with the same generator.
Result<ProjectedSupports> generateFixedDirectionSupports(const TriangleMesh& model, const Vec3& up,
                                                         const SupportOptions& options, JobContext& job);

// Eq. 14: R_p = (1 + lambda |torque|) R/4, torque in mm^4 (volume times lever arm; gravity is a unit vector).
double strutRadiusMm(double samplingSpacingMm, double torqueLambda, double torqueMm4);

// The torque of pieces (volumes, centroids) about `pivot` under unit gravity `gravity`: sum V_i (c_i - pivot) x g.
Vec3 gravityTorque(const std::vector<double>& volumesMm3, const std::vector<Vec3>& centroids, const Vec3& pivot,
                   const Vec3& gravity);

}  // namespace multidir::core
