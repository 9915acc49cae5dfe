#pragma once
// A lower bound on the J_G of every plan a 4-DOF machine can print with one rotation axis.
//
// On a rotary platform every region is printed along up turned about the axis r by an angle in the machine's
// range [min, max] (up itself among them). A face of the model whose normal is risky (jg-definition.md rule 1)
// for every direction of that arc is risky in whichever region it, or any piece of it, ends up in: cuts split
// faces but keep their normals, and only a cap (a face the cut made) rests on a cut plane (rule 3). The one
// exemption left is the bed's band (rule 2): the region on the platform keeps the model's lowest point
// (Criterion III: no plane cuts the platform region, which holds it), so its band is the model's; faces with
// a corner within the band are left out of the bound. The sum of the areas of the other such faces is a lower
// bound on J_G that holds for every plan on this axis: searched, refined between lattice angles or polished
// (their directions all lie on the arc).
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/machine.h"

namespace multidir::core::detail {

// The bound for `machine`'s rotation axis and angle range (mm^2). `alphaMaxDegrees` and `supportedBandMm` as in
// SearchOptions.
double unavoidableRiskyAreaMm2(const TriangleMesh& model, const MachineSpec& machine, double alphaMaxDegrees,
                               double supportedBandMm);

}  // namespace multidir::core::detail
