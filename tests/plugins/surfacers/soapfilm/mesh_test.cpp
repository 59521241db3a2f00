// Patch geometry: manifold disks whose border is the cycle, smoothed.
#include <catch2/catch.hpp>

#include "boundary_polyline.hpp"
#include "mesh_energy.hpp"
#include "patch_mesh.hpp"
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
