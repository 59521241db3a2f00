#include "vtk_mesh.hpp"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkPoints.h>

namespace sketchlab::hermite_rbf {

Mesh mesh_from_polydata(vtkPolyData* polydata) {
  Mesh mesh;
  if (vtkPoints* pts = polydata->GetPoints()) {
    mesh.vertices.resize(static_cast<std::size_t>(pts->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i) {
      double p[3];
      pts->GetPoint(i, p);
      mesh.vertices[static_cast<std::size_t>(i)] = Vec3(p[0], p[1], p[2]);
    }
  }
  if (!polydata->GetPolys()) return mesh;
  auto it = vtk::TakeSmartPointer(polydata->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell()) {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 1; k + 1 < n; ++k) {
      const std::array<int, 3> f{static_cast<int>(ids[0]), static_cast<int>(ids[k]), static_cast<int>(ids[k + 1])};
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
      mesh.faces.push_back(f);
    }
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> polydata_from_mesh(const Mesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.vertices[i].data());
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& f : mesh.faces) {
    const vtkIdType ids[3] = {f[0], f[1], f[2]};
    polys->InsertNextCell(3, ids);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

void compute_vertex_normals(Mesh& mesh) {
  mesh.normals.assign(mesh.vertices.size(), Vec3::Zero());
  for (const auto& f : mesh.faces) {
    const Vec3 n = (mesh.vertices[static_cast<std::size_t>(f[1])] - mesh.vertices[static_cast<std::size_t>(f[0])])
                       .cross(mesh.vertices[static_cast<std::size_t>(f[2])] - mesh.vertices[static_cast<std::size_t>(f[0])]);
    for (int v : f) mesh.normals[static_cast<std::size_t>(v)] += n;
  }
  for (Vec3& n : mesh.normals) n = n.norm() > 0.0 ? n.normalized() : Vec3::UnitZ();
}

}  // namespace sketchlab::hermite_rbf
