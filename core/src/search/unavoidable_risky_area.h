#pragma once
// A lower bound on the J_G of every plan a machine with a platform region can print: a rotary platform (4-DOF,
// one rotation axis) or a tilting one (5-DOF).
//
// Every region but the platform's is printed along a realizable direction d (4-DOF: up turned about the axis r
// by a whole stepper step of the range; 5-DOF: any direction within the tilt limit outside the forbidden
// cones); up itself prints the platform's region. A piece of a face is saved only by a region whose direction d
// faces it within alpha_max (jg-definition.md rule 1) and that holds it. Two things limit which regions can
// hold it:
//  - cuts split faces but keep their normals, and only a cap (a face the cut made) rests on a cut plane (rule 3);
//  - a region printed along d != up lies above its clipping plane, whose normal is d and which clears the
//    platform region P (Criterion III: its offset is above P's highest point along d). A face wholly at or
//    below P's highest point along d (less how far clipping may move a corner) cannot lie in a region printed
//    along d.
// A face that no realizable direction saves under both is risky in whichever region it, or any piece of it,
// ends up in. The one exemption left is the bed's band (rule 2): the region on the platform keeps the model's
// lowest point (Criterion III: no plane cuts the platform region, which holds it), so its band is the model's;
// faces with a corner within the band are left out of the bound. The sum of the areas of the other such faces
// is a lower bound on J_G that holds for every plan on this machine: searched, refined between lattice
// directions or polished (their directions are all realizable, their planes all clear P).
//
// 5-DOF directions form a continuum: they are covered by the cells of a cube map, each cell by its centre and
// its angular radius rho. Within a cell, n.d and a corner's height above P's top along d change by at most rho
// and rho x (the corner's distance from P's centre + P's radius), so a cell is ruled out when even those
// slacks cannot save the face; a cell that is not ruled out and whose centre does not save the face is split
// in four, down to a cell of about 0.01 degree, and a cell still undecided there counts as saving the face. So
// a face is counted only when every direction is proven not to save it: the bound stays a bound, only less
// tight than the exact one.
#include <cmath>

#include "multidir/core/mesh/triangle_mesh.h"
#include "multidir/core/search/machine.h"

namespace multidir::core::detail {

// The bound for `machine` (mm^2): 4-DOF its rotation axis, angle range and stepper angle; 5-DOF its tilt limit
// and forbidden cones; 0 for the other machines (3-axis, apart: no claim). `platform` is the platform region
// the search keeps every plane above. `alphaMaxDegrees` and `supportedBandMm` as in SearchOptions.
// `stopAboveMm2`: when the only question is whether the bound is above it (the pose search: could this pose
// beat a plan already found?), the faces are visited largest first and the sum stops as soon as it is above it;
// the value returned is then above it and at most the whole bound. Below it, the whole bound.
double unavoidableRiskyAreaMm2(const TriangleMesh& model, const MachineSpec& machine, const PlatformRegion& platform,
                               double alphaMaxDegrees, double supportedBandMm, double stopAboveMm2 = INFINITY);

}  // namespace multidir::core::detail
