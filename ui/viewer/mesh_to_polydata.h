#pragma once
// core::TriangleMesh -> vtkPolyData. Part of ui/viewer, the only code that includes VTK.
#include <vtkSmartPointer.h>

#include "multidir/core/mesh/triangle_mesh.h"

class vtkPolyData;

namespace multidir::ui {

// Points and triangles of `mesh`, in the same order (cell i is triangle i). Triangles whose indices are
// out of range are skipped rather than handed to VTK, which would read out of bounds.
vtkSmartPointer<vtkPolyData> toPolyData(const core::TriangleMesh& mesh);

}  // namespace multidir::ui
