// CGAL is confined to this translation unit (slow to compile).
#include "patch_mesh.hpp"
#include "timed_soapfilm.hpp"
#include "sketchlab/geometry/polyline.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/SparseLU>

#include <array>
#include <algorithm>
#include <memory>
#include <cmath>
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

// smooth_shape's system (M - tL) X = M X_old (thesis §3.3.4, Desbrun et al.
// implicit curvature flow) has identity rows for the fixed border, so it is
// not symmetric: a sparse LU solves it exactly. Its sparsity pattern is the
// same at every step of one smoothing (same mesh), so the fill-reducing
// ordering and symbolic analysis are done once and only the numeric
// factorisation is repeated; CGAL's default (BiCGSTAB with an incomplete LUT
// preconditioner) rebuilds its preconditioner and iterates at every step
// (measured: README.md). Models CGAL's SparseLinearAlgebraWithFactorTraits_d.
class PatternCachingLu {
 public:
  using Matrix = CGAL::Eigen_sparse_matrix<double>;
  using Vector = CGAL::Eigen_vector<double>;
  using NT = double;

  bool factor(const Matrix& a, NT& d) {
    d = 1.0;
    const Matrix::EigenType& m = a.eigen_object();
    State& s = *state_;
    if (!s.analysed || !m.isCompressed() || !same_pattern(s, m)) {
      s.lu.analyzePattern(m);
      s.analysed = m.isCompressed();
      if (s.analysed) {
        s.outer.assign(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1);
        s.inner.assign(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros());
      }
    }
    s.lu.factorize(m);
    return s.lu.info() == Eigen::Success;
  }

  bool linear_solver(const Vector& b, Vector& x) {
    x = state_->lu.solve(b);
    return state_->lu.info() == Eigen::Success;
  }

 private:
  struct State {
    Eigen::SparseLU<Matrix::EigenType, Eigen::COLAMDOrdering<int>> lu;
    bool analysed = false;
    std::vector<int> outer, inner;
  };
  static bool same_pattern(const State& s, const Matrix::EigenType& m) {
    return static_cast<Eigen::Index>(s.outer.size()) == m.outerSize() + 1 &&
           static_cast<Eigen::Index>(s.inner.size()) == m.nonZeros() &&
           std::equal(s.outer.begin(), s.outer.end(), m.outerIndexPtr()) &&
           std::equal(s.inner.begin(), s.inner.end(), m.innerIndexPtr());
  }
  // Shared: smooth_shape copies the solver object it is given.
  std::shared_ptr<State> state_ = std::make_shared<State>();
};

Mesh to_kernel_mesh(const SurfaceMesh& sm, const std::vector<VertexIndex>& border) {
  Mesh mesh;
  mesh.vertices.reserve(sm.number_of_vertices());
  mesh.faces.reserve(sm.number_of_faces());
  // Removed (garbage) vertices keep their slots in the index space.
  std::vector<int> index(sm.num_vertices(), -1);
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

// Whether a boundary point lies inside a boundary edge that does not end
// at it (within 1e-9 of the perimeter): the polygon runs along itself.
// Coincident points (a node the cycle passes twice) do not count.
bool retraces_itself(const std::vector<Vec3>& boundary, double perimeter) {
  const std::size_t n = boundary.size();
  const double eps = 1e-9 * perimeter;
  for (std::size_t e = 0; e < n; ++e) {
    const Vec3& a = boundary[e];
    const Vec3 ab = boundary[(e + 1) % n] - a;
    const double len2 = ab.squaredNorm();
    if (!(len2 > eps * eps)) continue;
    const double reach = eps / std::sqrt(len2);  // eps as a fraction of the edge
    for (std::size_t i = 0; i < n; ++i) {
      if (i == e || i == (e + 1) % n) continue;
      const double t = (boundary[i] - a).dot(ab) / len2;
      if (t <= reach || t >= 1.0 - reach) continue;
      if ((a + t * ab - boundary[i]).norm() < eps) return true;
    }
  }
  return false;
}

}  // namespace

Mesh patch_mesh(const std::vector<Vec3>& boundary, double target_edge,
                const PatchMeshParams& params, PatchMeshTimings* timings) {
  if (boundary.size() < 3) throw std::runtime_error("patch_mesh: boundary needs at least 3 points");
  if (!(target_edge > 0.0) || !std::isfinite(target_edge))
    throw std::runtime_error("patch_mesh: target edge length must be finite and > 0");
  for (const Vec3& p : boundary)
    if (!p.allFinite()) throw std::runtime_error("patch_mesh: non-finite boundary point");
  // A boundary that runs back along itself (a spike: a curve whose control
  // point lies far beyond its ends, out and back along one line) is filled
  // with triangles folded over each other, on which the isotropic remeshing
  // read a removed halfedge (segfault; found by fuzz_cassie_graph). No
  // surface spans it. Other folded fillings (a cycle passing a node twice,
  // curves nearly touching) are meshed as before: refusing every
  // self-intersecting filling cost the bundled replays 34 patches, 14 of
  // them CASSIE's (README.md).
  const double perimeter = polyline_length(boundary) + (boundary.front() - boundary.back()).norm();
  if (retraces_itself(boundary, perimeter))
    throw std::runtime_error("patch_mesh: the boundary runs back along itself");
  PatchMeshTimings local;
  PatchMeshTimings& time = timings ? *timings : local;
  time = PatchMeshTimings{};
  double stage = thread_cpu_ms();

  // 1. Hole-filling triangulation of the boundary polyline (Liepa / Zou et
  //    al.; thesis §3.3.4 "Triangle mesh from patch boundary").
  std::vector<Point> polyline;
  polyline.reserve(boundary.size() + 1);
  for (const Vec3& p : boundary) polyline.emplace_back(p.x(), p.y(), p.z());
  polyline.push_back(polyline.front());
  std::vector<CGAL::Triple<int, int, int>> triangles;
  triangles.reserve(boundary.size());
  PMP::triangulate_hole_polyline(
      polyline, std::back_inserter(triangles),
      CGAL::parameters::use_delaunay_triangulation(params.delaunay_hole_filling));
  if (triangles.empty()) throw std::runtime_error("patch_mesh: boundary could not be triangulated");
  {
    // Issue 17: a boundary running back over itself (a cycle of coincident
    // curves) encloses no area; remeshing its degenerate triangles crashed.
    double area = 0.0;
    auto at = [&](int i) { return boundary[static_cast<std::size_t>(i) % boundary.size()]; };
    for (const auto& t : triangles) area += 0.5 * (at(t.second) - at(t.first)).cross(at(t.third) - at(t.first)).norm();
    if (!(area > 1e-9 * perimeter * perimeter))
      throw std::runtime_error("patch_mesh: the boundary encloses no area (its curves run over each other)");
  }

  SurfaceMesh sm;
  sm.reserve(static_cast<SurfaceMesh::size_type>(boundary.size()), 0, 0);
  std::vector<VertexIndex> border;
  border.reserve(boundary.size());
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) border.push_back(sm.add_vertex(polyline[i]));
  const int n = static_cast<int>(border.size());
  for (const auto& t : triangles) {
    auto at = [&](int i) { return border[static_cast<std::size_t>(i % n)]; };
    if (sm.add_face(at(t.first), at(t.second), at(t.third)) == SurfaceMesh::null_face())
      throw std::runtime_error("patch_mesh: triangulation is not a manifold disk");
  }
  time.fill_ms = thread_cpu_ms() - stage;
  stage = thread_cpu_ms();

  // 2. Isotropic remeshing of the interior, border edges protected (thesis
  //    §3.3.4 "Mesh processing", first step). Protected vertices are never
  //    removed and, without collect_garbage, keep their indices. No
  //    projection back onto the hole-filling triangulation: that surface is
  //    only a first guess which the smoothing replaces, and projecting (an
  //    AABB tree and a closest-point query per vertex and pass) cost ~20 % of
  //    the remeshing (README.md).
  if (params.remesh_iterations > 0) {
    auto constrained_edges = sm.add_property_map<EdgeIndex, bool>("e:constrained", false).first;
    for (EdgeIndex e : sm.edges())
      if (sm.is_border(e)) constrained_edges[e] = true;
    PMP::isotropic_remeshing(faces(sm), target_edge, sm,
                             CGAL::parameters::number_of_iterations(
                                 static_cast<unsigned>(params.remesh_iterations))
                                 .edge_is_constrained_map(constrained_edges)
                                 .protect_constraints(true)
                                 .do_project(false));
    for (int i = 0; i < n; ++i) {
      const VertexIndex v = border[static_cast<std::size_t>(i)];
      if (sm.is_removed(v) || !sm.is_border(v) || sm.point(v) != polyline[static_cast<std::size_t>(i)])
        throw std::runtime_error("patch_mesh: remeshing moved a border vertex");
    }
  }
  time.remesh_ms = thread_cpu_ms() - stage;
  stage = thread_cpu_ms();

  // 3. Curvature-flow shape smoothing with the border fixed (thesis §3.3.4,
  //    second step; CGAL smooth_shape, Desbrun et al. implicit mean
  //    curvature flow).
  if (params.smooth_iterations > 0 && params.smoothing_time > 0.0) {
    auto fixed = sm.add_property_map<VertexIndex, bool>("v:fixed", false).first;
    for (VertexIndex v : border) fixed[v] = true;
    Eigen::AlignedBox3d box;
    for (const Vec3& p : boundary) box.extend(p);
    const double diameter = box.diagonal().norm();
    const double step = params.smoothing_time * diameter * diameter;
    const auto np = CGAL::parameters::number_of_iterations(static_cast<unsigned>(params.smooth_iterations))
                        .vertex_is_constrained_map(fixed);
    PMP::smooth_shape(sm, step, np.sparse_linear_solver(PatternCachingLu()));
    // Constrained rows come back equal only to rounding: put the border
    // back exactly on the curves.
    for (std::size_t i = 0; i < border.size(); ++i) sm.point(border[i]) = polyline[i];
  }
  for (VertexIndex v : sm.vertices()) {
    const Point& p = sm.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw std::runtime_error("patch_mesh: smoothing diverged");
  }
  time.smooth_ms = thread_cpu_ms() - stage;
  stage = thread_cpu_ms();
  Mesh out = to_kernel_mesh(sm, border);
  time.output_ms = thread_cpu_ms() - stage;
  return out;
}

}  // namespace sketchlab::soapfilm
