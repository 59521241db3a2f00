// A box drawn stroke by stroke in two-point perspective, with the guidelines
// an analytic drawer uses (Schmidt et al. 2009 Figure 3), from exact
// projections plus 0.5 px noise: every edge is parallel or perpendicular to
// the others to 0.1° and the corners coincide.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "drawing.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

Vec3 end_of(const test::Drawing& d, StrokeId id, int which) {
  const auto curves = d.added_by(id);
  REQUIRE(curves.size() == 1);
  return which == 0 ? curves[0].curve.control_points.front() : curves[0].curve.control_points.back();
}

}  // namespace

TEST_CASE("two-point perspective box: edges parallel/perpendicular to 0.1 deg, corners coincide",
          "[analytic][box]") {
  const double th = 30.0 * std::numbers::pi / 180.0;
  const Vec3 d1(std::cos(th), 0, std::sin(th)), d2(-std::sin(th), 0, std::cos(th)), up = Vec3::UnitY();
  const double L1 = 1.0, L2 = 0.8, h = 0.6;
  const Vec3 B0(-0.4, 0, -0.6), B1 = B0 + L1 * d1, B2 = B1 + L2 * d2, B3 = B0 + L2 * d2;
  test::Drawing d(demo::tablet_view(Vec3(0.2, 0.8, 6.0), Vec3(0.2, 0.8, 0.0)));

  auto line = [&](const Vec3& a, const Vec3& b) {
    const StepReport r = d.draw({a, b});
    INFO("stroke " << *r.stroke);
    std::string stats;
    for (const auto& [k, v] : r.stats.extra) stats += k + "=" + std::to_string(v) + " ";
    for (const Constraint& k : r.constraints)
      stats += "\n  " + std::string(to_string(k.kind)) + (k.enforced ? "*" : "") + " w=" + std::to_string(k.weight);
    INFO(stats);
    REQUIRE(r.error.empty());
    REQUIRE(test::stat(r, "line") == 1);
    return *r.stroke;
  };
  auto guide = [&](const Vec3& o, const Vec3& dir) {
    const StepReport r = d.guideline(o, dir);
    REQUIRE(r.error.empty());
    REQUIRE(test::stat(r, "guideline") == 1);
  };
  // Bottom: the first stroke lies in the ground plane and defines the
  // vanishing directions; a guideline closes the rectangle exactly.
  const StrokeId s0 = line(B0, B1);
  const Vec3 b0 = end_of(d, s0, 0), b1 = end_of(d, s0, 1);
  const StrokeId s1 = line(B1, B2);
  const Vec3 b2 = end_of(d, s1, 1);
  guide(B0, d2);
  line(B2, B3);
  line(B3, B0);
  // One vertical, guidelines from its top, the other verticals up to them.
  const StrokeId v0 = line(B0, B0 + h * up);
  const Vec3 t0 = end_of(d, v0, 1);
  guide(t0, d1);
  guide(t0, d2);
  const StrokeId v1 = line(B1, B1 + h * up);
  const StrokeId v3 = line(B3, B3 + h * up);
  const Vec3 t1 = end_of(d, v1, 1), t3 = end_of(d, v3, 1);
  guide(t1, d2);
  guide(t3, d1);
  line(B2, B2 + h * up);
  // The top.
  line(B0 + h * up, B1 + h * up);
  line(B1 + h * up, B2 + h * up);
  line(B2 + h * up, B3 + h * up);
  line(B3 + h * up, B0 + h * up);

  std::vector<std::pair<Vec3, Vec3>> edges;
  for (const auto& [id, c] : d.sketch().network.curves())
    if (c.layer != Layer::guide) edges.push_back({c.curve.control_points.front(), c.curve.control_points.back()});
  REQUIRE(edges.size() == 12);
  // The reconstruction is close to the drawn box (noise only moves the free
  // lengths by millimetres) ...
  CHECK((b0 - B0).norm() < 0.05);
  CHECK((b1 - B1).norm() < 0.05);
  CHECK((b2 - B2).norm() < 0.05);
  CHECK(std::abs((t0 - b0).norm() - h) < 0.05);
  // ... and exact in its relations.
  const double tol = std::sin(0.1 * std::numbers::pi / 180.0);
  for (const auto& [a, b] : edges)
    for (const auto& [c, e] : edges) {
      const double cosang = std::abs((b - a).normalized().dot((e - c).normalized()));
      INFO("edge " << a.transpose() << " -> " << b.transpose() << " vs " << c.transpose() << " -> " << e.transpose());
      CHECK((cosang > std::cos(0.1 * std::numbers::pi / 180.0) || cosang < tol));
    }
  // 8 corners, each shared by exactly 3 edges (to 1e-9 m).
  std::vector<std::pair<Vec3, int>> corners;
  for (const auto& [a, b] : edges)
    for (const Vec3& p : {a, b}) {
      bool found = false;
      for (auto& [q, n] : corners)
        if ((q - p).norm() < 1e-9) {
          ++n;
          found = true;
        }
      if (!found) corners.push_back({p, 1});
    }
  CHECK(corners.size() == 8);
  for (const auto& [q, n] : corners) CHECK(n == 3);
}
