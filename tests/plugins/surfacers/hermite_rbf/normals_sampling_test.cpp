// JustDrawIt §6 normal rules and constraint sampling.
#include <catch2/catch.hpp>

#include "curve_normals.hpp"
#include "hermite_constraints.hpp"
#include "hermite_rbf_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::hermite_rbf;
using namespace sketchlab::hermite_rbf_test;

TEST_CASE("planar curves: normal = tangent × plane normal pointing out from the centroid", "[hermite_rbf][normals]") {
  const Vec3 c(0.2, 1.0, -0.4);
  Network net = network_of({network_curve(1, circle(c, 0.3, Vec3(1, 1, 0).normalized(), Vec3::UnitZ()))});
  std::vector<CurveSamples> curves = sample_curves(net, SamplingParams{});
  assign_normals(curves, net, NormalParams{});
  REQUIRE(curves.size() == 1);
  for (std::size_t i = 0; i < curves[0].points.size(); ++i) {
    const Vec3 out = (curves[0].points[i] - c).normalized();
    CHECK(curves[0].normals[i].dot(out) > 0.999);
    CHECK(std::abs(curves[0].normals[i].dot(curves[0].tangents[i])) < 1e-9);
  }
}

TEST_CASE("non-planar curves: keys where the tangent is perpendicular to the centroid direction", "[hermite_rbf][normals]") {
  // A saddle-shaped closed curve (a circle with a cos 2θ height wave).
  std::vector<Vec3> ring;
  for (int i = 0; i < 64; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 64;
    ring.push_back(Vec3(0.3 * std::cos(a), 0.08 * std::cos(2 * a), 0.3 * std::sin(a)));
  }
  const Curve saddle = smooth_closed(ring);
  Network net = network_of({network_curve(1, saddle)});
  std::vector<CurveSamples> curves = sample_curves(net, SamplingParams{});
  const std::vector<NormalKey> keys = default_normal_keys(curves[0], NormalParams{});
  REQUIRE(keys.size() >= 2);
  for (const NormalKey& k : keys) {
    const Vec3 p = curves[0].points[static_cast<std::size_t>(k.sample)];
    CHECK(std::abs(curves[0].tangents[static_cast<std::size_t>(k.sample)].dot(k.normal)) < 0.05);
    CHECK(k.normal.dot(p.normalized()) > 0.9);  // out from the centroid (the origin)
  }
  propagate_normals(curves[0], keys);
  for (std::size_t i = 0; i < curves[0].points.size(); ++i) {
    CHECK(curves[0].normals[i].norm() == Approx(1.0));
    CHECK(std::abs(curves[0].normals[i].dot(curves[0].tangents[i])) < 1e-9);
  }
}

TEST_CASE("exported normals win and are propagated by slerp", "[hermite_rbf][normals]") {
  Network net = network_of({network_curve(1, make_line(Vec3::Zero(), Vec3(0.6, 0, 0)), {{0.0, Vec3::UnitY()}, {1.0, Vec3::UnitZ()}})});
  std::vector<CurveSamples> curves = sample_curves(net, SamplingParams{});
  assign_normals(curves, net, NormalParams{});
  const CurveSamples& s = curves[0];
  const std::size_t n = s.points.size();
  CHECK(s.normals.front().dot(Vec3::UnitY()) == Approx(1.0));
  CHECK(s.normals.back().dot(Vec3::UnitZ()) == Approx(1.0));
  // Halfway in arclength: halfway in angle.
  const Vec3 mid = s.normals[n / 2];
  const double angle = std::atan2(mid.z(), mid.y());
  CHECK(angle == Approx(std::numbers::pi / 4).margin(std::numbers::pi / 2 / double(n - 1) + 1e-9));
}

TEST_CASE("intersections get the normal of a plane fitted to the samples around them", "[hermite_rbf][normals]") {
  // Two great circles crossing at (0, 0, r): the fitted plane is the sphere's tangent plane.
  const double r = 0.3;
  Node node;
  node.id = 1;
  node.position = Vec3(0, 0, r);
  Network net = network_of({network_curve(1, circle(Vec3::Zero(), r, Vec3::UnitZ(), Vec3::UnitX())),
                            network_curve(2, circle(Vec3::Zero(), r, Vec3::UnitZ(), Vec3::UnitY()))},
                           {});
  Edit e;
  node.incidences = {{1, 0.0}, {2, 0.0}};
  e.nodes_added.push_back(node);
  net.apply(e);
  std::vector<CurveSamples> curves = sample_curves(net, SamplingParams{});
  assign_normals(curves, net, NormalParams{});
  for (const CurveSamples& s : curves) CHECK(s.normals[0].dot(Vec3::UnitZ()) > 0.999);
}

TEST_CASE("§6 sampling: points every 6 samples and normals every 12 or on a change above 0.1", "[hermite_rbf][sampling]") {
  Network net = network_of({network_curve(1, circle(Vec3::Zero(), 0.3, Vec3::UnitX(), Vec3::UnitY()))});
  SamplingParams sp;
  std::vector<CurveSamples> curves = sample_curves(net, sp);
  assign_normals(curves, net, NormalParams{});
  const CurveSamples& s = curves[0];
  const std::size_t n = s.points.size();
  REQUIRE(n > 300);
  HermiteConstraints out;
  pick_constraints(s, sp, out);
  // Samples ~0.005 apart on r = 0.3: tiny turns per sample, so the strides decide.
  CHECK(out.points.size() == (n + 5) / 6);
  CHECK(out.normals.size() == (n + 11) / 12);
  CHECK(out.tangents.empty());  // every tangent is implied by a normal at the same sample
  // A coarser sampling turns faster than 0.1 between point constraints: more normals.
  sp.sample_spacing = 0.05;
  curves = sample_curves(net, sp);
  assign_normals(curves, net, NormalParams{});
  HermiteConstraints coarse;
  pick_constraints(curves[0], sp, coarse);
  const double turn = 1.0 - std::cos(6 * 2 * std::numbers::pi / curves[0].points.size());
  REQUIRE(turn > 0.1);
  CHECK(coarse.normals.size() == coarse.points.size());
}

TEST_CASE("duplicates at crossings are merged", "[hermite_rbf][sampling]") {
  HermiteConstraints c;
  c.points = {Vec3::Zero(), Vec3(1e-4, 0, 0), Vec3(1, 0, 0)};
  c.normal_points = {Vec3::Zero(), Vec3(0, 1e-4, 0)};
  c.normals = {Vec3::UnitZ(), Vec3::UnitZ()};
  c.tangent_points = {Vec3(1e-4, 0, 0), Vec3(1, 0, 0), Vec3(1, 1e-4, 0), Vec3(1, 0, 1e-4)};
  c.tangents = {Vec3::UnitX(), Vec3::UnitX(), Vec3::UnitX(), Vec3::UnitY()};
  const HermiteConstraints m = merge_duplicates(c, 1e-3);
  CHECK(m.points.size() == 2);
  CHECK(m.normals.size() == 1);
  CHECK(m.tangents.size() == 2);  // (1,0,0) x and (1,0,1e-4) y; the one at the normal and the parallel one go
}
