#include "surface_trim.hpp"

#include <vtkClipPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "parallel_for.hpp"
#include "vtk_mesh.hpp"

namespace sketchlab::hermite_rbf {

double enclosure_gap(const Vec3& x, const Vec3& normal, const PointTree& samples, const TrimParams& params) {
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
  const double sin_max = std::sin(params.max_elevation);
  std::vector<double> angles;
  for (std::size_t i : samples.within(x, params.reach)) {
    const Vec3 u = samples.points()[i] - x;
    const double len = u.norm();
    if (!(len > 0.0)) return 0.0;  // on a curve sample: enclosed by definition of the trim line
    if (std::abs(u.dot(normal)) > sin_max * len) continue;
    angles.push_back(std::atan2(u.dot(e2), u.dot(e1)));
  }
  if (angles.empty()) return 2.0 * std::numbers::pi;
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2.0 * std::numbers::pi - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k) gap = std::max(gap, angles[k] - angles[k - 1]);
  return gap;
}

Mesh trim_unenclosed(const Mesh& mesh, const ImplicitFunction& f, const PointTree& samples, const TrimParams& params,
                     double cell, int threads) {
  if (mesh.faces.empty()) return mesh;
  Box3 box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  const Vec3 origin = box.min() - Vec3::Constant(cell);
  std::array<int, 3> n{};
  for (int a = 0; a < 3; ++a) n[static_cast<std::size_t>(a)] = static_cast<int>(std::ceil(box.sizes()[a] / cell)) + 3;
  auto index = [&](int i, int j, int k) { return std::size_t(i) + std::size_t(n[0]) * (std::size_t(j) + std::size_t(n[1]) * std::size_t(k)); };
  auto cell_of = [&](const Vec3& p, int c[3], double w[3]) {
    const Vec3 u = (p - origin) / cell;
    for (int a = 0; a < 3; ++a) {
      c[a] = std::clamp(static_cast<int>(std::floor(u[a])), 0, n[static_cast<std::size_t>(a)] - 2);
      w[a] = u[a] - c[a];
    }
  };
  // The lattice nodes around the vertices, each evaluated once.
  std::vector<char> needed(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0);
  for (const Vec3& v : mesh.vertices) {
    int c[3];
    double w[3];
    cell_of(v, c, w);
    for (int d = 0; d < 8; ++d) needed[index(c[0] + (d & 1), c[1] + (d >> 1 & 1), c[2] + (d >> 2 & 1))] = 1;
  }
  std::vector<std::size_t> nodes;
  for (std::size_t i = 0; i < needed.size(); ++i)
    if (needed[i]) nodes.push_back(i);
  std::vector<double> gap(needed.size(), 0.0);
  parallel_for(nodes.size(), threads, [&](std::size_t t) {
    const std::size_t id = nodes[t];
    const int i = static_cast<int>(id % std::size_t(n[0])), j = static_cast<int>(id / std::size_t(n[0]) % std::size_t(n[1])),
              k = static_cast<int>(id / (std::size_t(n[0]) * std::size_t(n[1])));
    const Vec3 x = origin + cell * Vec3(i, j, k);
    Vec3 g;
    f.value_gradient(x, g);
    gap[id] = g.norm() > 0.0 ? enclosure_gap(x, g.normalized(), samples, params) : 2.0 * std::numbers::pi;
  });

  // Keep where max_gap − gap > 0; exact zeros nudged so no cut passes through a vertex.
  vtkSmartPointer<vtkPolyData> poly = polydata_from_mesh(mesh);
  vtkNew<vtkDoubleArray> keep;
  keep->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertices.size()));
  bool any_cut = false;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    int c[3];
    double w[3];
    cell_of(mesh.vertices[v], c, w);
    double g = 0.0;
    for (int d = 0; d < 8; ++d)
      g += (d & 1 ? w[0] : 1 - w[0]) * (d >> 1 & 1 ? w[1] : 1 - w[1]) * (d >> 2 & 1 ? w[2] : 1 - w[2]) *
           gap[index(c[0] + (d & 1), c[1] + (d >> 1 & 1), c[2] + (d >> 2 & 1))];
    double s = params.max_gap - g;
    if (s == 0.0) s = 1e-12;
    any_cut = any_cut || s < 0.0;
    keep->SetValue(static_cast<vtkIdType>(v), s);
  }
  if (!any_cut) return mesh;
  poly->GetPointData()->SetScalars(keep);
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputData(poly);
  clip->SetValue(0.0);
  clip->GenerateClipScalarsOff();
  clip->InsideOutOff();  // keeps scalar > value
  clip->Update();
  Mesh out = mesh_from_polydata(clip->GetOutput());
  // The clip keeps unused points; drop them.
  std::vector<int> remap(out.vertices.size(), -1);
  Mesh compact;
  for (auto& face : out.faces) {
    for (int& v : face) {
      int& r = remap[static_cast<std::size_t>(v)];
      if (r < 0) {
        r = static_cast<int>(compact.vertices.size());
        compact.vertices.push_back(out.vertices[static_cast<std::size_t>(v)]);
      }
      v = r;
    }
    compact.faces.push_back(face);
  }
  compute_vertex_normals(compact);
  return compact;
}

}  // namespace sketchlab::hermite_rbf
