// §4.4–§6 pieces: depth promotion, Hermite joins, drawing surfaces and
// default normals, on plain data.
#include <catch2/catch.hpp>

#include "plane_depth.hpp"
#include "default_normals.hpp"
#include "drawing_surface.hpp"
#include "jdi_fixture.hpp"
#include "promotion.hpp"

using namespace jdi_test;

TEST_CASE("Depth relative to a plane round-trips and lifted strokes project back", "[justdrawit][depth]") {
  const View v = perspective_view(Vec3(0.5, 0.4, 3));
  const Camera cam(v);
  const Plane film = cam.film_plane(Vec3(0.1, 0, 0));
  const Vec3 p(0.2, -0.1, 0.3);
  const auto z = plane_depth(cam, film, p);
  REQUIRE(z);
  const auto px = cam.project(p);
  REQUIRE(px);
  CHECK((world_to_pixel(v, p).head<2>() - *px).norm() < 1e-9);
  const auto back = at_depth(cam, film, *px, *z);
  REQUIRE(back);
  CHECK((*back - p).norm() < 1e-9);

  Points2 stroke;
  for (int i = 0; i < 50; ++i) stroke.emplace_back(300 + 8 * i, 400 + 30 * std::sin(i / 7.0));
  std::vector<double> depth(stroke.size());
  for (std::size_t i = 0; i < depth.size(); ++i) depth[i] = 0.1 * std::sin(i / 5.0);
  const auto lifted = lift(cam, film, stroke, depth, 4);
  REQUIRE(lifted);
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    const auto q = cam.project((*lifted)[i]);
    REQUIRE(q);
    CHECK((*q - stroke[i]).norm() < 1e-6);  // smoothing stays on the rays (§4.5)
  }
}

TEST_CASE("fill_depths interpolates inside and extrapolates outside", "[justdrawit][depth]") {
  const std::vector<double> cum{0, 1, 2, 3, 4, 5};
  std::vector<std::optional<double>> known(6);
  known[1] = 1.0;
  known[3] = 3.0;
  const auto z = fill_depths(cum, known, 0.5, 2.0);
  CHECK(z[0] == Approx(1.5));
  CHECK(z[2] == Approx(2.0));
  CHECK(z[4] == Approx(5.0));
  CHECK(z[5] == Approx(7.0));
  CHECK(fill_depths(cum, std::vector<std::optional<double>>(6), 1, 1) == std::vector<double>(6, 0.0));
}

TEST_CASE("Hermite splice joins head and tail continuously", "[justdrawit][splice]") {
  Points3 head, tail;
  for (int i = 0; i <= 50; ++i) head.emplace_back(0.01 * i, 0, 0);
  for (int i = 0; i <= 50; ++i) tail.emplace_back(0.6 + 0.01 * i, 0.02, 0.01);
  const Splice s = splice(head, 50, tail, 0, 0.05, false, 0.001, 0.01);
  REQUIRE(s.pts.size() > head.size());
  // Kept parts are untouched, the Hermite starts and ends on them.
  for (std::size_t i = 0; i <= s.k; ++i) CHECK(s.pts[i] == head[i]);
  CHECK(s.pts[s.join_end] == tail[s.m]);
  CHECK(s.pts.back() == tail.back());
  for (std::size_t i = 1; i < s.pts.size(); ++i) CHECK((s.pts[i] - s.pts[i - 1]).norm() < 0.02);
  // Closing a U on itself.
  Points3 u;
  for (int i = 0; i <= 30; ++i) u.emplace_back(0, 0.01 * i, 0);
  for (int i = 1; i <= 30; ++i) u.emplace_back(0.01 * i, 0.3, 0);
  for (int i = 1; i <= 30; ++i) u.emplace_back(0.3, 0.3 - 0.01 * i, 0);
  const Splice c = close_splice(u, u.size() - 1, 0, 0.05, false, 0.005, 0.02);
  CHECK(c.pts.front() == c.pts.back());
}

TEST_CASE("Draw plane through two points is as perpendicular as possible to both tangents", "[justdrawit][surface]") {
  const Plane p = plane_through_two_points(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 0.2, 1).normalized());
  CHECK(std::abs(p.normal.dot(Vec3(1, 0, 0))) < 1e-9);  // contains both points
  CHECK(p.normal.dot(Vec3(0, 0, 1)) > 0.98);
  const Plane q = plane_at_point(Vec3(1, 2, 3), Vec3(0, 2, 0));
  CHECK((q.normal - Vec3::UnitY()).norm() < 1e-12);
}

TEST_CASE("Inflation surface bulges towards the viewer by half the width", "[justdrawit][surface]") {
  Points3 left, right;
  for (int i = 0; i <= 20; ++i) {
    left.emplace_back(-0.2, -0.3 + 0.03 * i, 0);
    right.emplace_back(0.2, -0.3 + 0.03 * i, 0);
  }
  const TriangleMesh m = inflation_surface(left, right, Vec3::UnitZ(), 17);
  const auto hit = ray_hit(m, Ray{Vec3(0, 0, 5), Vec3(0, 0, -1)});
  REQUIRE(hit);
  CHECK(hit->z() == Approx(0.2).margin(1e-3));
  CHECK_FALSE(ray_hit(m, Ray{Vec3(0.5, 0, 5), Vec3(0, 0, -1)}));
  const TriangleMesh e = extrusion_surface(left, Vec3::UnitZ(), 1.0);
  const auto he = ray_hit(e, Ray{Vec3(-1, 0, 0.3), Vec3(1, 0, 0)});
  REQUIRE(he);
  CHECK(he->x() == Approx(-0.2));
}

TEST_CASE("Default normals: planar, non-planar and pinned (§6)", "[justdrawit][normals]") {
  Points3 circle;
  for (int i = 0; i <= 100; ++i) {
    const double a = 2 * std::numbers::pi * i / 100;
    circle.emplace_back(std::cos(a), std::sin(a), 0.5);
  }
  const auto n = default_normals(circle, true, {}, 1e-6, Vec3::UnitZ());
  for (std::size_t i = 0; i + 1 < circle.size(); ++i) {
    const Vec3 t = (circle[(i + 1) % 100] - circle[(i + 99) % 100]).normalized();
    CHECK(std::abs(n[i].dot(t)) < 1e-9);
    CHECK(n[i].norm() == Approx(1.0));
    CHECK(n[i].dot(Vec3(circle[i].x(), circle[i].y(), 0)) > 0.99);  // out of the centroid
  }
  // A non-planar arc (a helix turn): normals perpendicular to the tangent,
  // unit, and varying smoothly.
  Points3 helix;
  for (int i = 0; i <= 100; ++i) {
    const double a = 1.5 * std::numbers::pi * i / 100;
    helix.emplace_back(std::cos(a), std::sin(a), 0.3 * a);
  }
  const auto h = default_normals(helix, false, {}, 1e-3, Vec3::UnitZ());
  for (std::size_t i = 1; i + 1 < helix.size(); ++i) {
    const Vec3 t = (helix[i + 1] - helix[i - 1]).normalized();
    CHECK(std::abs(h[i].dot(t)) < 1e-9);
    CHECK(h[i].norm() == Approx(1.0));
    CHECK(h[i].dot(h[i - 1]) > 0.9);
  }
  // A pin overrides the normal at its point (rejected from the tangent).
  const auto pinned = default_normals(helix, false, {{50, Vec3(0, 0, 1)}}, 1e-3, Vec3::UnitZ());
  const Vec3 t50 = (helix[51] - helix[49]).normalized();
  const Vec3 want = (Vec3(0, 0, 1) - Vec3(0, 0, 1).dot(t50) * t50).normalized();
  CHECK(std::abs(std::abs(pinned[50].dot(want)) - 1) < 1e-9);
  // Pin normal: the plane fit of two crossing curves.
  Points3 a, b;
  for (int i = 0; i <= 20; ++i) {
    a.emplace_back(-0.1 + 0.01 * i, 0, 0);
    b.emplace_back(0, -0.1 + 0.01 * i, 0);
  }
  CHECK(std::abs(pin_normal(a, 10, b, 10).z()) == Approx(1.0));
}

TEST_CASE("Curves exported by the corrector carry unit normals perpendicular to them", "[justdrawit][normals]") {
  Drawer dr;
  const View v = perspective_view(Vec3(0, 0, 3));
  std::vector<Vec2> arc;
  for (int i = 0; i <= 100; ++i) arc.emplace_back(300 + 5 * i, 500 + 150 * std::sin(i / 30.0));
  dr.draw(v, arc);
  const NetworkCurve& nc = dr.net().curves().begin()->second;
  REQUIRE(nc.normals.size() > 10);
  const Points3 pts = curve_points(nc.curve, 1e-3);
  for (const CurveNormal& cn : nc.normals) {
    const std::size_t i = static_cast<std::size_t>(cn.t);
    const Vec3 t = (pts[std::min(i + 1, pts.size() - 1)] - pts[i > 0 ? i - 1 : 0]).normalized();
    CHECK(cn.normal.norm() == Approx(1.0));
    CHECK(std::abs(cn.normal.dot(t)) < 1e-9);
  }
}

TEST_CASE("New curves take the drawing surface's depth (§5.1)", "[justdrawit][surface]") {
  const View v = perspective_view(Vec3(0.3, 0.2, 3));
  SECTION("the stroke's draw plane") {
    Drawer dr;
    const Vec4 plane(0, 0.6, 0.8, 0.1);  // n·x = 0.1
    dr.draw(v, jdi_test::line_px({300, 300}, {800, 600}), Layer::automatic, plane);
    for (const Vec3& p : dr.only_curve()) CHECK(std::abs(plane.head<3>().dot(p) - 0.1) < 1e-9);
  }
  SECTION("the view plane through the origin by default") {
    Drawer dr;
    dr.draw(v, jdi_test::line_px({300, 300}, {800, 600}));
    const Vec3 f = Camera(v).forward();
    for (const Vec3& p : dr.only_curve()) CHECK(std::abs(f.dot(p)) < 1e-9);
  }
  SECTION("an extrusion surface") {
    JdiParams p;
    p.surface = SurfaceKind::extrusion;
    const View top = ortho_view(Vec3(0, 3, 0), Vec3::Zero(), Vec3(0, 0, -1));
    std::vector<Vec3> arc;  // an arc in the x–z plane, seen from above
    for (int i = 0; i <= 60; ++i) {
      const double a = std::numbers::pi * i / 60;
      arc.emplace_back(0.3 * std::cos(a), 0, -0.3 * std::sin(a));
    }
    JdiParams plain;
    plain.surface = SurfaceKind::draw_plane;
    plain.plane_normal = Vec3::UnitY();
    Drawer seed(plain);
    seed.draw(top, to_pixels(top, arc));
    // Extrude it along y and draw across it from the front.
    p.extrusion_direction = Vec3::UnitY();
    Sketch sk = seed.session.sketch();
    const View fr = ortho_view(Vec3(0, 0, 3));
    const Stroke s = pixel_stroke(5, fr, jdi_test::line_px({400, 420}, {800, 560}));
    const Correction c = justdrawit_correct(s, sk, p);
    REQUIRE(c.error.empty());
    REQUIRE(c.edit.curves_added.size() == 1);
    CHECK(c.stats.extra.at("surface") == 2);
    for (const Vec3& q : curve_points(c.edit.curves_added[0].curve, 1e-3)) {
      const double r = std::hypot(q.x(), q.z());
      CHECK(r == Approx(0.3).margin(2e-3));  // on the extruded arc
    }
  }
  SECTION("an inflation surface between two guide strokes") {
    JdiParams p;
    p.surface = SurfaceKind::inflation;
    Drawer dr(p);
    const View fr = ortho_view(Vec3(0, 0, 3));
    const StepReport g1 = dr.draw(fr, jdi_test::line_px({400, 200}, {400, 800}), Layer::guide);
    dr.draw(fr, jdi_test::line_px({800, 200}, {800, 800}), Layer::guide);
    CHECK(dr.net().curves().empty());
    CHECK(g1.stats.extra.at("guide") == 1);
    const StepReport r = dr.draw(fr, jdi_test::line_px({420, 500}, {780, 500}));
    CHECK(r.stats.extra.at("surface") == 3);
    const Points3 c = dr.only_curve();
    // Width 0.4 m: the middle bulges 0.2 m towards the viewer (+z).
    double zmax = 0;
    for (const Vec3& q : c) zmax = std::max(zmax, q.z());
    CHECK(zmax == Approx(0.2).margin(0.01));
  }
}
