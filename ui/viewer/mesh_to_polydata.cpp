#include "ui/viewer/mesh_to_polydata.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace multidir::ui {

vtkSmartPointer<vtkPolyData> toPolyData(const core::TriangleMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const core::Vec3& p = mesh.vertices[i];
    points->SetPoint(static_cast<vtkIdType>(i), p.x(), p.y(), p.z());
  }

  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()),
                           3 * static_cast<vtkIdType>(mesh.triangles.size()));
  const auto vertexCount = static_cast<std::int64_t>(mesh.vertices.size());
  for (const core::Triangle& t : mesh.triangles) {
    if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= vertexCount || t[1] >= vertexCount || t[2] >= vertexCount)
      continue;
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    triangles->InsertNextCell(3, ids);
  }

  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  return polyData;
}

}  // namespace multidir::ui
