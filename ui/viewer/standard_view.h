#pragma once
// The standard views of the 3D view (View > Standard views): where the camera looks from and which way is up
// on screen, relative to the model's up (the document's printing direction), so "Top" looks down the up
// direction whatever axis it is. No VTK: the directions are plain vectors, tested on their own.
#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::ui {

enum class StandardView {
  Home,  // the framing a new model gets: from the front, a little from the right and from above
  Front,
  Back,
  Left,
  Right,
  Top,
  Bottom,
  Iso,  // isometric: the front, the right and the top equally foreshortened
};

struct ViewOrientation {
  core::Vec3 fromCentre;  // unit: from the model's centre towards the camera
  core::Vec3 screenUp;    // unit: what points up on screen (the camera keeps its part across fromCentre)
};

// The model's front: the side facing the camera in the Front view. -Y for a model standing on +/-Z (the usual
// front of a part on a printer bed), else +Z projected off `up` (the front of a Y-up scanned model).
[[nodiscard]] core::Vec3 frontSideFor(const core::Vec3& up);

// `view` of a model whose up is `up` (unit). Front, Back, Left, Right and Iso keep `up` up on screen; Top
// looks down `up` with the model's back at the top of the screen, Bottom looks up at it with the front there.
[[nodiscard]] ViewOrientation orientationOf(StandardView view, const core::Vec3& up);

}  // namespace multidir::ui
