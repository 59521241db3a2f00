// Strokes drawn on a patch (CASSIE app item 20; thesis §3.3.5).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "cassie_corrector.hpp"
#include "synthetic.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;
using sketchlab::test::add_curve;
using sketchlab::test::make_stroke;

namespace {

// A 40 cm square patch in z = 0 bounded by four lines (curves 1–4).
Sketch square_patch() {
  Sketch sketch;
  const Vec3 c[4] = {{-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0.2, 0}, {-0.2, 0.2, 0}};
  for (int i = 0; i < 4; ++i) add_curve(sketch, make_line(c[i], c[(i + 1) % 4]));
  Edit e;
  Patch p;
  p.id = sketch.network.next_patch_id();
  for (CurveId id = 1; id <= 4; ++id) p.boundary.push_back({id, 0.0, 1.0});
  p.mesh.vertices = {c[0], c[1], c[2], c[3]};
  p.mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  e.patches_added.push_back(p);
  sketch.network.apply(e);
  return sketch;
}

}  // namespace

TEST_CASE("Item 20: a stroke drawn on a patch is projected onto it", "[cassie][surface]") {
  const Sketch sketch = square_patch();
  // A wavy stroke 1 cm above the patch, well inside its border.
  const Stroke s = make_stroke(1, 60, [](double u) {
    return Vec3(-0.1 + 0.2 * u, 0.05 * std::sin(6.0 * u), 0.01 + 0.003 * std::sin(9.0 * u));
  }, 2.0);
  const Correction c = correct_stroke(s, sketch, CassieParams{});
  REQUIRE(c.error.empty());
  const Curve& out = c.edit.curves_added[0].curve;
  for (const Vec3& p : out.control_points) CHECK(std::abs(p.z()) < 1e-12);
  CHECK(c.stats.extra.at("on_surface_patch") == 1);
  bool whole = false;
  for (const Constraint& k : c.constraints) whole |= k.kind == ConstraintKind::on_surface && k.enforced;
  CHECK(whole);
  // 6 cm above it (beyond 2.5δ): left alone.
  const Stroke high = make_stroke(2, 60, [](double u) { return Vec3(-0.1 + 0.2 * u, 0.05 * std::sin(6.0 * u), 0.06); }, 2.0);
  const Correction d = correct_stroke(high, sketch, CassieParams{});
  CHECK(d.stats.extra.count("on_surface_patch") == 0);
}

TEST_CASE("Item 20: a stroke leaving the patch has only its ends projected", "[cassie][surface]") {
  const Sketch sketch = square_patch();
  // From 1 cm above the patch to 40 cm beyond its border, rising (6.5 cm
  // above the border where it crosses it).
  const Stroke s = make_stroke(1, 80, [](double u) { return Vec3(0.0, -0.1 + 0.7 * u, 0.01 + 0.3 * u * u); }, 2.0);
  const Correction c = correct_stroke(s, sketch, CassieParams{});
  REQUIRE(c.error.empty());
  const Curve& out = c.edit.curves_added[0].curve;
  REQUIRE(c.stats.extra.count("on_surface_patch") == 1);
  // The start (within 2.5δ of the patch) is on it; the far end is not moved.
  CHECK(std::abs(out.control_points.front().z()) < 1e-12);
  CHECK(out.control_points.back().z() > 0.25);
}

TEST_CASE("Items 6 and 20: a brush on a boundary curve does not touch the patch", "[cassie][surface]") {
  const Sketch sketch = square_patch();
  // Along the border y = -0.2, 1 cm above it, wavy: every hand position is in
  // the collider of curve 1 (the curve is the brush's main collider), while
  // the control points are within 2.5δ of the patch.
  const Stroke s = make_stroke(1, 60, [](double u) {
    return Vec3(-0.15 + 0.3 * u, -0.2 + 0.005 * std::sin(7.0 * u), 0.01);
  }, 2.0);
  const Correction brush = correct_stroke(s, sketch, CassieParams{});
  REQUIRE(brush.error.empty());
  CHECK(brush.stats.extra.count("on_surface_patch") == 0);
  CassieParams by_points;
  by_points.surface_touch = SurfaceTouch::control_points;
  const Correction points = correct_stroke(s, sketch, by_points);
  REQUIRE(points.error.empty());
  CHECK(points.stats.extra.count("on_surface_patch") == 1);
}

namespace {

bool projected_whole(const Correction& c) {
  bool whole = false;
  for (const Constraint& k : c.constraints) whole |= k.kind == ConstraintKind::on_surface && k.enforced;
  return whole;
}

// Ends on the patch (z = 0) exactly, and a control point left above it.
void check_ends_only(const Correction& c) {
  REQUIRE(c.error.empty());
  REQUIRE(c.stats.extra.count("on_surface_patch") == 1);
  CHECK_FALSE(projected_whole(c));
  const auto& cp = c.edit.curves_added[0].curve.control_points;
  CHECK(std::abs(cp.front().z()) < 1e-12);
  CHECK(std::abs(cp.back().z()) < 1e-12);
  double top = 0.0;
  for (const Vec3& p : cp) top = std::max(top, p.z());
  CHECK(top > 0.005);
}

void check_whole(const Correction& c) {
  REQUIRE(c.error.empty());
  REQUIRE(c.stats.extra.count("on_surface_patch") == 1);
  CHECK(projected_whole(c));
  for (const Vec3& p : c.edit.curves_added[0].curve.control_points) CHECK(std::abs(p.z()) < 1e-12);
}

}  // namespace

TEST_CASE("Item 20: the patch spans the stroke (surface_span)", "[cassie][surface]") {
  const Sketch sketch = square_patch();
  CassieParams box, ends, brush;  // δ = 2 cm: brush radius 2 cm, surface_snap 5 cm
  box.surface_span = SurfaceSpan::box;
  ends.surface_span = SurfaceSpan::stroke_ends;
  brush.surface_span = SurfaceSpan::brush;
  SECTION("a stroke starting 3.5 cm above the patch: its first hand position is off it") {
    const Stroke s = make_stroke(1, 60, [](double u) {
      return Vec3(-0.1 + 0.2 * u, 0.05 * std::sin(6.0 * u), 0.035 - 0.03 * u);
    }, 2.0);
    check_whole(correct_stroke(s, sketch, box));  // every control point in the grown box
    check_ends_only(correct_stroke(s, sketch, ends));
    check_ends_only(correct_stroke(s, sketch, brush));
  }
  SECTION("a stroke with both ends on the patch lifting 2.7 cm off it in the middle") {
    const Stroke s = make_stroke(1, 60, [](double u) {
      return Vec3(-0.1 + 0.2 * u, 0.05 * std::sin(6.0 * u), 0.005 + 0.022 * std::sin(std::numbers::pi * u));
    }, 2.0);
    check_whole(correct_stroke(s, sketch, box));
    check_whole(correct_stroke(s, sketch, ends));
    check_ends_only(correct_stroke(s, sketch, brush));
  }
}
