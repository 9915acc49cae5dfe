#pragma once
// What a step printed onto an earlier step needs from the slicer (docs/slicing.md, "Interfaces between
// steps"). A later step stands on its base plane, a cut face inside the part, on the lower step's solid top
// skin (the slicer closes every surface that has nothing above it in that step's frame, the cut faces
// included, so the lower step always leaves a printable surface). The later step's first layers are then
// interior layers of the part, not the bottom of a part on a bed: no bottom skin (its bottom is inside the
// part, where an uncut print has sparse infill), and the first layer printed like any other layer, at the
// normal extrusion width and speed (the bed's first-layer width and speed are for adhesion to the bed).
#include <string>
#include <utility>
#include <vector>

namespace multidir::slicing {

// PrusaSlicer settings, applied to every step after the first after the profile and the user's settings.
std::vector<std::pair<std::string, std::string>> interfaceSettings();

}  // namespace multidir::slicing
