#pragma once
// A lower bound on the J_G of every plan a 4-DOF machine can print with one rotation axis.
//
// On a rotary platform every region is printed along up turned about the axis r by a realizable angle (a whole
// stepper step of the range; up itself prints the platform's region). A piece of a face is saved only by a
// region whose direction d faces it within alpha_max (jg-definition.md rule 1) and that holds it. Two things
// limit which regions can hold it:
//  - cuts split faces but keep their normals, and only a cap (a face the cut made) rests on a cut plane (rule 3);
//  - a region printed along d != up lies above its clipping plane, whose normal is d and which clears the
//    platform region P (Criterion III: its offset is above P's highest point along d). A face wholly at or
//    below P's highest point along d (less how far clipping may move a corner) cannot lie in a region printed
//    along d.
// A face that no realizable direction saves under both is risky in whichever region it, or any piece of it,
// ends up in. The one exemption left is the bed's band (rule 2): the region on the platform keeps the model's
// lowest point (Criterion III: no plane cuts the platform region, which holds it), so its band is the model's;
// faces with a corner within the band are left out of the bound. The sum of the areas of the other such faces
// is a lower bound on J_G that holds for every plan on this axis: searched, refined between lattice angles or
// polished (their directions are all realizable, their planes all clear P).
#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/machine.h"

namespace multidir::core::detail {

// The bound for `machine`'s rotation axis, angle range and stepper angle (mm^2), with `platform` the platform
// region the search keeps every plane above. `alphaMaxDegrees` and `supportedBandMm` as in SearchOptions.
double unavoidableRiskyAreaMm2(const TriangleMesh& model, const MachineSpec& machine, const PlatformRegion& platform,
                               double alphaMaxDegrees, double supportedBandMm);

}  // namespace multidir::core::detail
