// The Hermite RBF surfacer end to end: shapes it must reproduce, exactness
// at the constraints, watertightness, and errors on degenerate input.
#include <catch2/catch.hpp>

#include "hermite_rbf_surfacer.hpp"
#include "hermite_rbf_test_support.hpp"
#include "mesh_topology.hpp"

using namespace sketchlab;
using namespace sketchlab::hermite_rbf;
using namespace sketchlab::hermite_rbf_test;

namespace {

// The closed zero set of §6 ("water-tight, manifold"): only components far
// from every curve are dropped. The default trim (Trim::enclosed) is tested
// in partition_of_unity_test.cpp.
HermiteRbfParams test_params(int resolution = 64) {
  HermiteRbfParams p;
  p.mesh.resolution = resolution;
  p.mesh.trim = Trim::far_components;
  p.mesh.threads = 2;
  return p;
}

}  // namespace

TEST_CASE("three great circles with outward normals give the sphere within 1% of its radius", "[hermite_rbf][shape]") {
  const Vec3 c(0.1, 1.2, -0.2);
  const double r = 0.3;
  const SurfaceResult s = surface_from_network(sphere_circles(c, r), test_params());
  REQUIRE(s.mesh.vertices.size() > 1000);
  double worst = 0.0;
  for (const Vec3& v : s.mesh.vertices) worst = std::max(worst, std::abs((v - c).norm() - r));
  INFO("worst radial error " << worst / r * 100.0 << " %");
  CHECK(worst <= 0.01 * r);
  CHECK(mesh_topology(s.mesh).watertight_manifold());
  CHECK(mesh_topology(s.mesh).components == 1);
  // Oriented outwards: positive volume near the ball's.
  CHECK(signed_volume(s.mesh) == Approx(4.0 / 3.0 * std::numbers::pi * r * r * r).epsilon(0.03));
}

TEST_CASE("a cube's 12 edges with face normals give a closed surface through the edges", "[hermite_rbf][shape]") {
  // Each edge carries the bisector of its two face normals: the only normal a
  // smooth surface can have there. A smooth interpolant cannot keep the faces
  // flat between the edges; it bulges like the sphere through the edges
  // (4/3 π (√2 a)³ = 1.48 × the cube). Measured: 1.54 ×. See README.
  const Vec3 c(-0.3, 0.8, 0.5);
  const double a = 0.2;
  const SurfaceResult s = surface_from_network(cube_edges(c, a), test_params());
  const MeshTopology t = mesh_topology(s.mesh);
  CHECK(t.watertight_manifold());
  CHECK(t.components == 1);
  const double cube = 8.0 * a * a * a;
  INFO("volume " << signed_volume(s.mesh) / cube << " × the cube");
  CHECK(signed_volume(s.mesh) > cube);
  CHECK(signed_volume(s.mesh) < 1.6 * cube);
  // Every edge point lies on the surface: the mesh passes within a cell of it.
  for (const Vec3& p : s.constraints.points) {
    double nearest = 1e9;
    for (const Vec3& v : s.mesh.vertices) nearest = std::min(nearest, (v - p).norm());
    CHECK(nearest <= s.stats.at("grid_cell"));
  }
}

TEST_CASE("a cube's 12 edges and face curves with face normals give the cube's volume within 10%", "[hermite_rbf][shape]") {
  // The faces pinned by 3 square loops per axis carrying the face normals.
  const Vec3 c(-0.3, 0.8, 0.5);
  const double a = 0.2;
  Network net = cube_edges(c, a);
  Edit e;
  e.curves_added = cube_face_loops(c, a, {-0.5, 0.0, 0.5}, 13);
  net.apply(e);
  const SurfaceResult s = surface_from_network(net, test_params());
  const MeshTopology t = mesh_topology(s.mesh);
  CHECK(t.watertight_manifold());
  CHECK(t.components == 1);
  const double cube = 8.0 * a * a * a;
  INFO("volume " << signed_volume(s.mesh) / cube << " × the cube");
  CHECK(std::abs(signed_volume(s.mesh) - cube) <= 0.1 * cube);
}

TEST_CASE("the interpolant meets every point and normal and tangent constraint to 1e-6", "[hermite_rbf][exact]") {
  // A sphere (normals only) and a wavy non-planar sketch (tangents too).
  std::vector<Network> nets;
  nets.push_back(sphere_circles(Vec3(0.0, 1.0, 0.0), 0.25));
  Curve wave;
  for (int i = 0; i <= 12; ++i) {
    const double a = i * std::numbers::pi / 6.0;
    wave.control_points.push_back(Vec3(0.3 * std::cos(a), 0.05 * std::sin(3.0 * a) + 0.02 * i, 0.3 * std::sin(a)));
  }
  wave.sharp.assign(5, false);
  nets.push_back(network_of({network_curve(1, wave), network_curve(2, circle(Vec3(0, 0.4, 0), 0.2, Vec3::UnitX(), Vec3::UnitZ())),
                             network_curve(3, circle(Vec3(0, 0.2, 0), 0.25, Vec3::UnitX(), Vec3::UnitY())),
                             // A straight line has no default normal: tangent constraints only.
                             network_curve(4, make_line(Vec3(-0.1, 0.3, -0.1), Vec3(0.1, 0.35, 0.1)))}));
  for (const Network& net : nets) {
    const SurfaceResult s = surface_from_network(net, test_params(32));
    REQUIRE(s.constraints.normals.size() > 10);
    CHECK(s.solve.residual_point <= 1e-6);
    CHECK(s.solve.residual_normal <= 1e-6);
    CHECK(s.solve.residual_tangent <= 1e-6);
    CHECK(s.stats.at("residual_point_max") == s.solve.residual_point);
    CHECK(s.stats.at("regularizer") >= 0.0);
  }
  CHECK(surface_from_network(nets[1], test_params(32)).constraints.tangents.size() > 0);
}

TEST_CASE("a network with a dangling curve still gives a watertight manifold mesh", "[hermite_rbf][watertight]") {
  const Vec3 c(0.0, 1.0, 0.0);
  Network net = sphere_circles(c, 0.25);
  // An open, non-planar curve sticking out of the sphere.
  Curve tail;
  tail.control_points = {c + Vec3(0.25, 0, 0), c + Vec3(0.35, 0.05, 0.02), c + Vec3(0.45, -0.05, 0.08), c + Vec3(0.55, 0.02, 0.1)};
  tail.sharp.assign(2, false);
  Edit e;
  e.curves_added.push_back(network_curve(4, tail));
  net.apply(e);
  for (int res : {32, 64}) {
    const SurfaceResult s = surface_from_network(net, test_params(res));
    const MeshTopology t = mesh_topology(s.mesh);
    INFO("resolution " << res);
    CHECK(t.boundary_edges == 0);
    CHECK(t.nonmanifold_edges == 0);
    CHECK(t.inconsistent_edges == 0);
    CHECK(t.nonmanifold_vertices == 0);
    CHECK(s.stats.at("watertight") == 1.0);
    CHECK(signed_volume(s.mesh) > 0.0);
  }
}

TEST_CASE("degenerate input gives a clear error and no crash", "[hermite_rbf][degenerate]") {
  Sketch sketch;
  SECTION("empty sketch") {
    CHECK_THAT(recompute_surface(sketch, test_params()).error, Catch::Contains("no curve"));
  }
  SECTION("a single straight line") {
    sketch.network = network_of({network_curve(1, make_line(Vec3(0, 0, 0), Vec3(0.5, 0.1, 0)))});
    const SurfaceUpdate u = recompute_surface(sketch, test_params());
    CHECK_THAT(u.error, Catch::Contains("normal"));
    CHECK(u.edit.empty());
  }
  SECTION("a single straight line with normals") {
    sketch.network = network_of({network_curve(1, make_line(Vec3(0, 0, 0), Vec3(0.5, 0.1, 0)), {{0.0, Vec3::UnitZ()}})});
    CHECK_THAT(recompute_surface(sketch, test_params()).error, Catch::Contains("straight line"));
  }
  SECTION("coincident samples") {
    Curve dot;
    dot.control_points.assign(4, Vec3(0.1, 0.2, 0.3));
    dot.sharp.assign(2, false);
    sketch.network = network_of({network_curve(1, dot), network_curve(2, dot)});
    CHECK_THAT(recompute_surface(sketch, test_params()).error, Catch::Contains("no curve of non-zero length"));
  }
  SECTION("two coincident straight lines") {
    sketch.network = network_of({network_curve(1, make_line(Vec3(0, 0, 0), Vec3(0, 0.3, 0)), {{0.0, Vec3::UnitX()}}),
                                 network_curve(2, make_line(Vec3(0, 0, 0), Vec3(0, 0.3, 0)), {{0.0, Vec3::UnitX()}})});
    CHECK_THAT(recompute_surface(sketch, test_params()).error, Catch::Contains("degenerate"));
  }
}

TEST_CASE("recompute replaces the previous surface with one patch", "[hermite_rbf][update]") {
  Sketch sketch;
  sketch.network = sphere_circles(Vec3::Zero(), 0.2);
  const SurfaceUpdate first = recompute_surface(sketch, test_params(32));
  REQUIRE(first.error.empty());
  REQUIRE(first.edit.patches_added.size() == 1);
  CHECK(first.edit.patches_removed.empty());
  CHECK(first.stats.at("constraints_point") > 0);
  CHECK(first.stats.at("constraints_normal") > 0);
  CHECK(first.stats.count("solve_ms"));
  CHECK(first.stats.count("eval_ms"));
  CHECK(first.stats.at("grid_nodes") > 0);
  sketch.network.apply(first.edit);
  const SurfaceUpdate second = recompute_surface(sketch, test_params(32));
  REQUIRE(second.error.empty());
  CHECK(second.edit.patches_removed == std::vector<PatchId>{first.edit.patches_added[0].id});
  CHECK(second.edit.patches_added.size() == 1);
  sketch.network.apply(second.edit);
  CHECK(sketch.network.patches().size() == 1);
  // The surface stays valid while curves change length; removing a curve drops it.
  Edit replace;
  NetworkCurve shorter = *sketch.network.find_curve(1);
  shorter.curve = circle(Vec3::Zero(), 0.2, Vec3::UnitX(), Vec3::UnitY(), 4);
  shorter.keypoints = default_keypoints(shorter.curve);
  replace.curves_replaced.push_back(shorter);
  CHECK_NOTHROW(sketch.network.apply(replace));
  Edit remove;
  remove.curves_removed.push_back(2);
  sketch.network.apply(remove);
  CHECK(sketch.network.patches().empty());
}
