// Sharp feature curves of meshes read with OpenMesh.
#include <catch2/catch.hpp>
#include <array>
#include <filesystem>
#include <fstream>
#include <set>

#include "mesh_features.hpp"
#include "relations.hpp"
#include "test_paths.hpp"
#include "synthetic_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::synthetic;

namespace {

std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = sketchlab::test::binary_path("tests/scratch/synthetic");
  std::filesystem::create_directories(dir);
  return dir / name;
}

// Unit cube, 8 vertices, each quad split into two triangles, outward normals.
const std::vector<Vec3> cube_vertices{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<std::array<int, 4>> cube_quads{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                 {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};

std::filesystem::path write_cube_off() {
  const auto path = scratch("cube.off");
  std::ofstream out(path);
  out << "OFF\n8 12 0\n";
  for (const Vec3& v : cube_vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& q : cube_quads) {
    out << "3 " << q[0] << " " << q[1] << " " << q[2] << "\n";
    out << "3 " << q[0] << " " << q[2] << " " << q[3] << "\n";
  }
  return path;
}

std::filesystem::path write_cube_ply() {
  const auto path = scratch("cube.ply");
  std::ofstream out(path);
  out << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
         "property float z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& v : cube_vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& q : cube_quads) {
    out << "3 " << q[0] << " " << q[1] << " " << q[2] << "\n";
    out << "3 " << q[0] << " " << q[2] << " " << q[3] << "\n";
  }
  return path;
}

// The cube's 12 edges as sorted vertex-index pairs.
std::set<std::pair<int, int>> cube_edges() {
  std::set<std::pair<int, int>> e;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) {
        auto index = [](int k) {  // corner bits (x, y, z) -> vertex index above
          const Vec3 p(k & 1, (k >> 1) & 1, (k >> 2) & 1);
          for (int v = 0; v < 8; ++v) if (cube_vertices[static_cast<std::size_t>(v)] == p) return v;
          return -1;
        };
        const int a = index(i), b = index(i | bit);
        e.insert({std::min(a, b), std::max(a, b)});
      }
  return e;
}

int vertex_of(const Vec3& p) {
  for (int v = 0; v < 8; ++v) if ((cube_vertices[static_cast<std::size_t>(v)] - p).norm() < 1e-12) return v;
  return -1;
}

void check_cube_features(const std::filesystem::path& file) {
  const auto polylines = mesh_feature_polylines(file);
  REQUIRE(polylines.size() == 12);
  std::set<std::pair<int, int>> found;
  for (const auto& pl : polylines) {
    REQUIRE(pl.size() == 2);  // the diagonals (dihedral 0) are not features
    const int a = vertex_of(pl[0]), b = vertex_of(pl[1]);
    REQUIRE(a >= 0);
    REQUIRE(b >= 0);
    found.insert({std::min(a, b), std::max(a, b)});
  }
  CHECK(found == cube_edges());
}

}  // namespace

TEST_CASE("a cube OFF file gives its 12 edges as feature curves", "[synthetic][mesh]") {
  check_cube_features(write_cube_off());
}

TEST_CASE("a cube PLY file gives its 12 edges as feature curves", "[synthetic][mesh]") {
  check_cube_features(write_cube_ply());
}

TEST_CASE("a feature angle above 90° finds no cube edge", "[synthetic][mesh]") {
  MeshFeatureParams p;
  p.feature_angle = 2.0;  // rad, > 90°
  CHECK(mesh_feature_polylines(write_cube_off(), p).empty());
}

TEST_CASE("mesh feature networks become lines, scaled and centred, with cube relations", "[synthetic][mesh]") {
  synthetic::SynthesisParams p = synthetic::support::perfect("mesh");
  p.mesh = write_cube_off().string();
  p.size = 0.4;
  const GroundTruthNetwork net = build_network(p);
  REQUIRE(net.curves.size() == 12);
  Box3 box;
  for (const auto& c : net.curves) {
    CHECK(c.curve.kind == CurveKind::line);
    CHECK(c.layer == Layer::shape);
    for (const Vec3& q : c.curve.control_points) box.extend(q);
  }
  CHECK(box.sizes().maxCoeff() == Approx(0.4));
  CHECK((box.center() - model_center).norm() < 1e-12);
  const auto n = synthetic::support::count_by_kind(synthetic::support::relations(synthesize_session(p)));
  CHECK(n.at(ConstraintKind::coincident_point) == 24);
  CHECK(n.at(ConstraintKind::perpendicular) == 24);
  CHECK(n.at(ConstraintKind::parallel) == 9);
}

TEST_CASE("bad mesh files are clear errors", "[synthetic][mesh]") {
  CHECK_THROWS_WITH(mesh_feature_polylines(scratch("missing.off")), Catch::Contains("not found"));
  const auto junk = scratch("junk.off");
  std::ofstream(junk) << "this is not a mesh\n";
  CHECK_THROWS_WITH(mesh_feature_polylines(junk), Catch::Contains("junk.off"));
  synthetic::SynthesisParams p = synthetic::support::perfect("mesh");
  CHECK_THROWS_WITH(build_network(p), Catch::Contains("'mesh' parameter"));
}
