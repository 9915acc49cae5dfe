#pragma once
// A solid to show in its own colour with a label (a part's number) at a point of it: what the viewer's
// setSolids takes. No VTK.
#include <QColor>
#include <QString>

#include "multidir/core/mesh/triangle_mesh.h"

namespace multidir::ui {

struct ColouredSolid {
  core::TriangleMesh mesh;  // mm, in the frame the view shows
  QColor colour;
  QString label;            // empty: none
  core::Vec3 labelAt = core::Vec3::Zero();
};

}  // namespace multidir::ui
