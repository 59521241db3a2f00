// The partition of unity of local fits against the dense reference, its
// incremental update, and trimming where the network has no curves.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numbers>

#include "hermite_rbf_surfacer.hpp"
#include "hermite_rbf_test_support.hpp"
#include "mesh_topology.hpp"
#include "point_tree.hpp"

using namespace sketchlab;
using namespace sketchlab::hermite_rbf;
using namespace sketchlab::hermite_rbf_test;

namespace {

HermiteRbfParams params(Solver solver, Trim trim = Trim::far_components) {
  HermiteRbfParams p;
  p.solver = solver;
  p.mesh.resolution = 64;
  p.mesh.trim = trim;
  p.mesh.threads = 2;
  return p;
}

// Symmetric Hausdorff distance between the vertex sets (m).
double hausdorff(const Mesh& a, const Mesh& b) {
  auto one_sided = [](const Mesh& from, const Mesh& to) {
    const PointTree tree(to.vertices);
    double worst = 0.0;
    for (const Vec3& v : from.vertices) worst = std::max(worst, tree.nearest(v).second);
    return worst;
  };
  return std::max(one_sided(a, b), one_sided(b, a));
}

double diagonal(const HermiteConstraints& c) {
  Box3 box;
  for (const Vec3& p : c.points) box.extend(p);
  return box.diagonal().norm();
}

Network cube_with_face_loops(const Vec3& c, double a) {
  Network net = cube_edges(c, a);
  Edit e;
  e.curves_added = cube_face_loops(c, a, {-0.5, 0.0, 0.5}, 13);
  net.apply(e);
  return net;
}

}  // namespace

TEST_CASE("the partition of unity meets every constraint and stays near the dense solution", "[hermite_rbf][partition]") {
  struct Case {
    const char* name;
    Network net;
  };
  std::vector<Case> cases;
  cases.push_back({"sphere", sphere_circles(Vec3(0.1, 1.2, -0.2), 0.3)});
  cases.push_back({"cube and face loops", cube_with_face_loops(Vec3(-0.3, 0.8, 0.5), 0.2)});
  for (const Case& c : cases) {
    INFO(c.name);
    const SurfaceResult pu = surface_from_network(c.net, params(Solver::partition));
    const SurfaceResult dense = surface_from_network(c.net, params(Solver::dense));
    REQUIRE(pu.stats.at("pu_cells") > 8);  // really partitioned
    const double size = diagonal(pu.constraints);
    // The blend is exact at the constraints (partition_of_unity.hpp).
    CHECK(pu.solve.residual_point <= 1e-6 * size);
    CHECK(pu.solve.residual_normal <= 1e-6);
    CHECK(pu.solve.residual_tangent <= 1e-6);
    const double h = hausdorff(pu.mesh, dense.mesh);
    INFO("Hausdorff " << h / size << " × the diagonal, grid cell " << pu.stats.at("grid_cell") / size);
    CHECK(h <= 0.012 * size);
    CHECK(mesh_topology(pu.mesh).watertight_manifold());
  }
}

TEST_CASE("a new stroke refits only the cells around it and gives the surface of a rebuild", "[hermite_rbf][partition][update]") {
  const Vec3 c(0.0, 1.0, 0.0);
  const double r = 0.3;
  Network net = sphere_circles(c, r);
  const HermiteRbfParams p = params(Solver::partition);
  SurfaceState state;
  const SurfaceResult first = surface_from_network(net, p, &state);
  // A short arc (22.5°, 0.12 m) on the sphere between two of the circles.
  const Vec3 u = Vec3(1.0, 0.0, 1.0).normalized(), v = Vec3::UnitY();
  Edit e;
  e.curves_added.push_back(network_curve(10, arc(c, r, u, v, 1, 16)));
  net.apply(e);
  const SurfaceResult updated = surface_from_network(net, p, &state);
  const SurfaceResult rebuilt = surface_from_network(net, p);
  INFO("refitted " << updated.stats.at("pu_cells_fitted") << " of " << updated.stats.at("pu_cells") << " cells, grid computed "
                    << updated.stats.at("grid_computed_fraction") << " against " << first.stats.at("grid_computed_fraction"));
  CHECK(first.stats.at("pu_cells_fitted") == first.stats.at("pu_cells"));
  CHECK(updated.stats.at("pu_cells_fitted") <= 0.3 * updated.stats.at("pu_cells"));
  CHECK(updated.stats.at("grid_computed_fraction") <= 0.8 * first.stats.at("grid_computed_fraction"));
  REQUIRE(updated.mesh.vertices.size() == rebuilt.mesh.vertices.size());
  CHECK(updated.mesh.vertices == rebuilt.mesh.vertices);
  CHECK(updated.mesh.faces == rebuilt.mesh.faces);
}

TEST_CASE("trimming keeps a closed network closed and opens the surface where curves are missing", "[hermite_rbf][trim]") {
  const Vec3 c(0.0, 1.0, 0.0);
  const double r = 0.3;
  SECTION("closed: three great circles") {
    const SurfaceResult s = surface_from_network(sphere_circles(c, r), params(Solver::partition, Trim::enclosed));
    CHECK(mesh_topology(s.mesh).watertight_manifold());
    CHECK(s.stats.at("trimmed_area_fraction") <= 1e-9);
  }
  SECTION("open: the upper half of the circles") {
    // The equator and two half meridians over the pole: nothing below.
    const Network hemisphere = network_of({network_curve(1, circle(c, r, Vec3::UnitZ(), Vec3::UnitX())),
                                           network_curve(2, arc(c, r, Vec3::UnitX(), Vec3::UnitY(), 4)),
                                           network_curve(3, arc(c, r, Vec3::UnitZ(), Vec3::UnitY(), 4))});
    auto area_below = [&](const Mesh& m) {
      double below = 0.0, all = 0.0;
      for (const auto& f : m.faces) {
        const Vec3 &a = m.vertices[std::size_t(f[0])], &b = m.vertices[std::size_t(f[1])], &d = m.vertices[std::size_t(f[2])];
        const double area = 0.5 * (b - a).cross(d - a).norm();
        all += area;
        if ((a + b + d).y() / 3.0 < c.y() - 0.2 * r) below += area;
      }
      return below / all;
    };
    const SurfaceResult closed = surface_from_network(hemisphere, params(Solver::partition));
    const SurfaceResult open = surface_from_network(hemisphere, params(Solver::partition, Trim::enclosed));
    INFO("closed: " << area_below(closed.mesh) * 100 << " % below the equator; trimmed: " << area_below(open.mesh) * 100 << " %");
    CHECK(area_below(closed.mesh) > 0.2);
    CHECK(area_below(open.mesh) < 0.02);
    const MeshTopology t = mesh_topology(open.mesh);
    CHECK(t.boundary_edges > 0);
    CHECK(t.nonmanifold_edges == 0);
    CHECK(t.inconsistent_edges == 0);
    // The dome is kept: about the hemisphere's area 2πr².
    CHECK(surface_area(open.mesh) == Approx(2.0 * std::numbers::pi * r * r).epsilon(0.15));
  }
}
