// Patch geometry: manifold disks whose border is the cycle, smoothed.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "boundary_polyline.hpp"
#include "cassie_graph.hpp"
#include "mesh_energy.hpp"
#include "patch_mesh.hpp"
#include "patch_upkeep.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "soapfilm_surfacer.hpp"
#include "soapfilm_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::soapfilm_test;

namespace {

// Largest distance from a border vertex of the patch mesh to the nearest of
// its boundary curves.
double border_offset(const Network& net, const Patch& p, std::size_t border_count) {
  double worst = 0.0;
  for (std::size_t i = 0; i < border_count; ++i) {
    double d = INFINITY;
    for (const auto& piece : p.boundary)
      d = std::min(d, closest_point(net.find_curve(piece.curve)->curve, p.mesh.vertices[i]).distance);
    worst = std::max(worst, d);
  }
  return worst;
}

std::size_t border_vertex_count(const Mesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& f : m.faces)
    for (int i = 0; i < 3; ++i) ++count[std::minmax(f[i], f[(i + 1) % 3])];
  std::set<int> border;
  for (const auto& [e, n] : count)
    if (n == 1) border.insert({e.first, e.second});
  return border.size();
}

}  // namespace

TEST_CASE("patch meshes are manifold disks bordered by the cycle", "[soapfilm]") {
  const auto curves = cylinder(0.1, 0.3);
  PreparedSession s(curves);
  s.draw_all(curves.size());
  const Network& net = s.network();
  REQUIRE(net.patches().size() >= 4);
  for (const auto& [id, p] : net.patches()) {
    INFO("patch " << id);
    const Mesh& m = p.mesh;
    REQUIRE(!m.faces.empty());
    CHECK(soapfilm::is_manifold_disk(m));
    CHECK(m.normals.size() == m.vertices.size());
    for (const Vec3& v : m.vertices) CHECK(v.allFinite());
    // The border vertices come first, in cycle order, and lie on the curves.
    const std::size_t nb = border_vertex_count(m);
    const soapfilm::SoapfilmParams defaults;
    const auto poly = soapfilm::boundary_polyline(net, p.boundary, defaults.edge_length,
                                                  defaults.max_boundary_points);
    REQUIRE(nb == poly.points.size());
    CHECK(nb <= static_cast<std::size_t>(defaults.max_boundary_points));
    for (std::size_t i = 0; i < nb; ++i) CHECK((m.vertices[i] - poly.points[i]).norm() == 0.0);
    CHECK(border_offset(net, p, nb) < 1e-9);
    // Every cycle node is a border vertex.
    for (const auto& piece : p.boundary) {
      const Vec3 node = net.find_node(piece.node_from)->position;
      double d = INFINITY;
      for (std::size_t i = 0; i < nb; ++i) d = std::min(d, (m.vertices[i] - node).norm());
      CHECK(d < 1e-9);
    }
  }
}

TEST_CASE("curvature-flow smoothing lowers the mean curvature energy", "[soapfilm]") {
  // A saddle-shaped boundary (skew quadrilateral of curved edges) and a cube face.
  const auto curves = cylinder(0.1, 0.3);
  PreparedSession s(curves);
  s.draw_all(curves.size());
  const Network& net = s.network();
  int checked = 0;
  for (const auto& [id, p] : net.patches()) {
    const auto poly = soapfilm::boundary_polyline(net, p.boundary, 0.01, 160);
    soapfilm::PatchMeshParams raw;
    raw.smooth_iterations = 0;
    const Mesh before = soapfilm::patch_mesh(poly.points, poly.spacing, raw);
    const Mesh after = soapfilm::patch_mesh(poly.points, poly.spacing, soapfilm::PatchMeshParams{});
    const double e0 = soapfilm::mean_curvature_energy(before), e1 = soapfilm::mean_curvature_energy(after);
    INFO("patch " << id << " energy " << e0 << " -> " << e1);
    // Flat caps are already minimal (energy at rounding level).
    if (e0 < 1e-9) continue;
    CHECK(e1 < 0.5 * e0);
    // Border untouched by smoothing.
    for (std::size_t i = 0; i < poly.points.size(); ++i) CHECK(after.vertices[i] == poly.points[i]);
    ++checked;
  }
  CHECK(checked >= 4);  // the four curved side patches
}

TEST_CASE("patch_mesh rejects bad input with a clear error", "[soapfilm]") {
  const soapfilm::PatchMeshParams p;
  CHECK_THROWS_WITH(soapfilm::patch_mesh({Vec3::Zero(), Vec3::UnitX()}, 0.01, p),
                    Catch::Contains("at least 3"));
  CHECK_THROWS_WITH(soapfilm::patch_mesh({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()}, 0.0, p),
                    Catch::Contains("target edge"));
  CHECK_THROWS_WITH(soapfilm::patch_mesh({Vec3::Zero(), Vec3(NAN, 0, 0), Vec3::UnitY()}, 0.01, p),
                    Catch::Contains("non-finite"));
}

TEST_CASE("a cycle whose curve runs out and back over itself gets no patch and does not crash", "[soapfilm]") {
  // Found by fuzz_cassie_graph: a 10 cm square whose first side is a cubic
  // with a control point 5 m out along the side, so that the curve runs out
  // 2.2 m and back along itself. The hole filling folds over that spike and
  // CGAL's isotropic remeshing then read a removed halfedge (segfault in
  // make_patch, the surfacer's own path).
  const auto square = [](const std::string& first_side) {
    return R"({"strokes": [{"id": 0, "segments": [0]}, {"id": 1, "segments": [1]}, {"id": 2, "segments": [2]},
                          {"id": 3, "segments": [3]}],
      "segments": [{"id": 0, "stroke_id": 0, "ctrl_pts": [)" + first_side + R"(], "nodes": [0, 1]},
        {"id": 1, "stroke_id": 1, "ctrl_pts": [[[0.1,0,0],[0.1,0.1,0]]], "nodes": [1, 2]},
        {"id": 2, "stroke_id": 2, "ctrl_pts": [[[0.1,0.1,0],[0,0.1,0]]], "nodes": [2, 3]},
        {"id": 3, "stroke_id": 3, "ctrl_pts": [[[0,0.1,0],[0,0,0]]], "nodes": [3, 0]}],
      "nodes": [{"id": 0, "position": [0,0,0]}, {"id": 1, "position": [0.1,0,0]},
                {"id": 2, "position": [0.1,0.1,0]}, {"id": 3, "position": [0,0.1,0]}]})";
  };
  const soapfilm::SoapfilmParams params;
  const auto patch_of = [&](const std::string& first_side) {
    const auto file = std::filesystem::temp_directory_path() / "sketchlab_test_spiked_square.json";
    std::ofstream(file) << square(first_side);
    const auto net = soapfilm::load_cassie_network(file);
    std::filesystem::remove(file);
    const auto cycles = soapfilm::detect_all_cycles(net.network, params.search);
    REQUIRE(cycles.size() == 1);
    const auto poly = soapfilm::boundary_polyline(net.network, cycles[0], params.edge_length, params.max_boundary_points);
    return std::pair{soapfilm::make_patch(net.network, 1, cycles[0], true, params, nullptr), poly.points};
  };
  const auto [spiked, spiked_boundary] = patch_of("[[0,0,0],[0.0333333,0,0],[5.0666667,0,0],[0.1,0,0]]");
  CHECK_FALSE(spiked.has_value());
  CHECK_THROWS_WITH(soapfilm::patch_mesh(spiked_boundary, 0.05, params.mesh), Catch::Contains("runs back along itself"));
  const auto [plain, plain_boundary] = patch_of("[[0,0,0],[0.1,0,0]]");
  REQUIRE(plain.has_value());
  CHECK(soapfilm::is_manifold_disk(plain->mesh));
}

TEST_CASE("patch_mesh refuses a boundary running back along itself but not one passing a point twice", "[soapfilm]") {
  const soapfilm::PatchMeshParams p;
  // Out along the x axis to 0.2 and back to 0.1: the point at 0.13 lies
  // inside the edge from 0.06 to 0.2.
  const std::vector<Vec3> spike{Vec3(0, 0, 0),     Vec3(0.06, 0, 0), Vec3(0.2, 0, 0), Vec3(0.13, 0, 0),
                                Vec3(0.1, 0, 0),   Vec3(0.1, 0.1, 0), Vec3(0, 0.1, 0)};
  CHECK_THROWS_WITH(soapfilm::patch_mesh(spike, 0.02, p), Catch::Contains("runs back along itself"));
  // A figure of eight through one point twice (a cycle passing a node
  // twice, which item 24 allows) is meshed as before.
  const std::vector<Vec3> eight{Vec3(0, 0, 0),    Vec3(0.1, 0.05, 0), Vec3(0.1, -0.05, 0),
                                Vec3(0, 0, 0),    Vec3(-0.1, 0.05, 0.01), Vec3(-0.1, -0.05, 0.01)};
  const Mesh m = soapfilm::patch_mesh(eight, 0.02, p);
  CHECK_FALSE(m.faces.empty());
  for (const Vec3& v : m.vertices) CHECK(v.allFinite());
}
