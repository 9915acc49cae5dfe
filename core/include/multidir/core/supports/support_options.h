#pragma once
// Parameters of support generation (the paper's Section V), with their defaults.
#include "multidir/core/common/result.h"
#include "multidir/core/common/units.h"

namespace multidir::core {

struct SupportOptions {
  // R: spacing of the overhang samples. The paper uses 2 mm with a 0.4 mm nozzle and 3 mm with 0.8 mm. The
  // base strut radius is R/4 (Eq. 14). In (0.1, 100].
  double samplingSpacingMm = 2.0;
  // Largest tilt of a strut from its region's printing direction (the paper's self-supporting angle for
  // sparse trees, after Vanek et al. 2014). Two struts merge where their downward cones of this half-angle
  // meet. In [0, 80].
  double strutAngleDegrees = 30.0;
  // lambda of Eq. 14 (1/mm^4): how much the torque of the struts above thickens a strut. >= 0.
  double torqueLambda = 1e-6;
  // A contact tip is a cone of this length from a strut to the model, touching it in a disc of this radius.
  double tipLengthMm = 1.0;        // in (0, 50]
  double contactRadiusMm = 0.2;    // in (0, R/4]
  int strutSides = 8;              // sides of a strut's prism, 3 to 64
  // Greedy merging of nearby struts into trees (Vanek et al.); off: each sample gets its own column.
  bool mergeStruts = true;
  // The overhang criterion, as the search uses it (see analysis/overhang.h).
  double alphaMaxDegrees = kDefaultAlphaMaxDegrees;
  double supportedBandMm = kDefaultSupportedBandMm;
  // A strut stopped by a wall of its sub-space slides along it while it tilts at most this much from its
  // printing direction; beyond, it ends there unresolved (counted in the result). In [0, 89].
  double maxWallSlideDegrees = 60.0;
};

// Names the first field out of range and its valid range. Errors: InvalidParameter.
Status validate(const SupportOptions& options);

}  // namespace multidir::core
