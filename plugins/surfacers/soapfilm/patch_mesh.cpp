// CGAL is confined to this translation unit (slow to compile).
#include "patch_mesh.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace sketchlab::soapfilm {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using VertexIndex = SurfaceMesh::Vertex_index;
using EdgeIndex = SurfaceMesh::Edge_index;
namespace PMP = CGAL::Polygon_mesh_processing;

Mesh to_kernel_mesh(const SurfaceMesh& sm, const std::vector<VertexIndex>& border) {
  Mesh mesh;
  std::vector<int> index(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
  // Border first, in cycle order, so vertex i of the result is boundary[i].
  for (VertexIndex v : border) {
    index[v] = static_cast<int>(mesh.vertices.size());
    const Point& p = sm.point(v);
    mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (VertexIndex v : sm.vertices()) {
    if (index[v] >= 0) continue;
    index[v] = static_cast<int>(mesh.vertices.size());
    const Point& p = sm.point(v);
    mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto f : sm.faces()) {
    std::array<int, 3> tri{};
    int i = 0;
    for (VertexIndex v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (i < 3) tri[i] = index[v];
      ++i;
    }
    if (i == 3) mesh.faces.push_back(tri);
  }
  // Area-weighted vertex normals.
  mesh.normals.assign(mesh.vertices.size(), Vec3::Zero());
  for (const auto& f : mesh.faces) {
    const Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                       .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]);
    for (int v : f) mesh.normals[v] += n;
  }
  for (Vec3& n : mesh.normals) {
    const double len = n.norm();
    n = len > 0.0 ? Vec3(n / len) : Vec3::UnitZ();
  }
  return mesh;
}

}  // namespace

Mesh patch_mesh(const std::vector<Vec3>& boundary, double target_edge,
                const PatchMeshParams& params) {
  if (boundary.size() < 3) throw std::runtime_error("patch_mesh: boundary needs at least 3 points");
  if (!(target_edge > 0.0) || !std::isfinite(target_edge))
    throw std::runtime_error("patch_mesh: target edge length must be finite and > 0");
  for (const Vec3& p : boundary)
    if (!p.allFinite()) throw std::runtime_error("patch_mesh: non-finite boundary point");

  // 1. Hole-filling triangulation of the boundary polyline (Liepa / Zou et al.).
  std::vector<Point> polyline;
  polyline.reserve(boundary.size() + 1);
  for (const Vec3& p : boundary) polyline.emplace_back(p.x(), p.y(), p.z());
  polyline.push_back(polyline.front());
  std::vector<CGAL::Triple<int, int, int>> triangles;
  PMP::triangulate_hole_polyline(polyline, std::back_inserter(triangles));
  if (triangles.empty()) throw std::runtime_error("patch_mesh: boundary could not be triangulated");

  SurfaceMesh sm;
  std::vector<VertexIndex> border;
  border.reserve(boundary.size());
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) border.push_back(sm.add_vertex(polyline[i]));
  for (const auto& t : triangles) {
    const int n = static_cast<int>(border.size());
    auto at = [&](int i) { return border[static_cast<std::size_t>(i % n)]; };
    if (sm.add_face(at(t.first), at(t.second), at(t.third)) == SurfaceMesh::null_face())
      throw std::runtime_error("patch_mesh: triangulation is not a manifold disk");
  }

  // 2. Isotropic remeshing of the interior, border edges protected.
  auto constrained_edges = sm.add_property_map<EdgeIndex, bool>("e:constrained", false).first;
  for (EdgeIndex e : sm.edges())
    if (sm.is_border(e)) constrained_edges[e] = true;
  if (params.remesh_iterations > 0)
    PMP::isotropic_remeshing(faces(sm), target_edge, sm,
                             CGAL::parameters::number_of_iterations(
                                 static_cast<unsigned>(params.remesh_iterations))
                                 .edge_is_constrained_map(constrained_edges)
                                 .protect_constraints(true));
  sm.collect_garbage();
  // Remeshing keeps protected vertices but may renumber them: find the
  // border again by position (each border vertex is exactly an input point).
  {
    std::vector<VertexIndex> found(boundary.size(), SurfaceMesh::null_vertex());
    std::map<std::array<double, 3>, std::size_t> where;
    for (std::size_t i = 0; i < boundary.size(); ++i)
      where.emplace(std::array<double, 3>{boundary[i].x(), boundary[i].y(), boundary[i].z()}, i);
    for (VertexIndex v : sm.vertices()) {
      const Point& p = sm.point(v);
      auto it = where.find({p.x(), p.y(), p.z()});
      if (it != where.end() && sm.is_border(v)) found[it->second] = v;
    }
    for (VertexIndex v : found)
      if (v == SurfaceMesh::null_vertex())
        throw std::runtime_error("patch_mesh: remeshing moved a border vertex");
    border = std::move(found);
  }

  // 3. Curvature-flow shape smoothing with the border fixed.
  if (params.smooth_iterations > 0 && params.smoothing_time > 0.0) {
    auto fixed = sm.add_property_map<VertexIndex, bool>("v:fixed", false).first;
    for (VertexIndex v : sm.vertices())
      if (sm.is_border(v)) fixed[v] = true;
    Eigen::AlignedBox3d box;
    for (const Vec3& p : boundary) box.extend(p);
    const double diameter = box.diagonal().norm();
    PMP::smooth_shape(sm, params.smoothing_time * diameter * diameter,
                      CGAL::parameters::number_of_iterations(
                          static_cast<unsigned>(params.smooth_iterations))
                          .vertex_is_constrained_map(fixed));
    // The solver is iterative: constrained rows come back equal only to its
    // tolerance. Put the border back exactly on the curves.
    for (std::size_t i = 0; i < border.size(); ++i)
      sm.point(border[i]) = polyline[i];
  }
  for (VertexIndex v : sm.vertices()) {
    const Point& p = sm.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw std::runtime_error("patch_mesh: smoothing diverged");
  }
  return to_kernel_mesh(sm, border);
}

}  // namespace sketchlab::soapfilm
