#include "zero_set_mesh.hpp"

#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>

#include "vtk_mesh.hpp"

namespace sketchlab::hermite_rbf {

Mesh extract_zero_set(const ScalarGrid& grid) {
  const GridSpec& s = grid.spec;
  vtkNew<vtkImageData> image;
  image->SetDimensions(s.n[0], s.n[1], s.n[2]);
  image->SetOrigin(s.origin.x(), s.origin.y(), s.origin.z());
  image->SetSpacing(s.h, s.h, s.h);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("f");
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(grid.values.size()));
  for (std::size_t i = 0; i < grid.values.size(); ++i) scalars->SetValue(static_cast<vtkIdType>(i), grid.values[i]);
  image->GetPointData()->SetScalars(scalars);

  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetNumberOfContours(1);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->InterpolateAttributesOff();
  contour->Update();
  Mesh mesh = mesh_from_polydata(contour->GetOutput());

  // Orientation: the grid's finite-difference gradient (f rises outwards)
  // decides; flying edges orients every triangle alike, so one vote suffices.
  auto value_at = [&](const Vec3& p) {
    const Vec3 u = (p - s.origin) / s.h;
    int c[3];
    double w[3];
    for (int a = 0; a < 3; ++a) {
      c[a] = std::clamp(static_cast<int>(std::floor(u[a])), 0, s.n[static_cast<std::size_t>(a)] - 2);
      w[a] = std::clamp(u[a] - c[a], 0.0, 1.0);
    }
    double v = 0.0;
    for (int d = 0; d < 8; ++d) {
      const double weight = (d & 1 ? w[0] : 1 - w[0]) * (d & 2 ? w[1] : 1 - w[1]) * (d & 4 ? w[2] : 1 - w[2]);
      v += weight * grid.values[s.index(c[0] + (d & 1), c[1] + (d & 2 ? 1 : 0), c[2] + (d & 4 ? 1 : 0))];
    }
    return v;
  };
  double vote = 0.0;
  for (const auto& f : mesh.faces) {
    const Vec3 &a = mesh.vertices[static_cast<std::size_t>(f[0])], &b = mesh.vertices[static_cast<std::size_t>(f[1])],
               &c = mesh.vertices[static_cast<std::size_t>(f[2])];
    const Vec3 n = (b - a).cross(c - a);
    if (!(n.norm() > 0.0)) continue;
    const Vec3 centroid = (a + b + c) / 3.0;
    const Vec3 step = 0.25 * s.h * n.normalized();
    vote += value_at(centroid + step) - value_at(centroid - step) > 0.0 ? 1.0 : -1.0;
  }
  if (vote < 0.0)
    for (auto& f : mesh.faces) std::swap(f[1], f[2]);

  compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace sketchlab::hermite_rbf
