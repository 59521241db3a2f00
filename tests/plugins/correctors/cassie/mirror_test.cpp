// Whole-stroke projection onto the mirror plane (CASSIE app item 18).
#include <catch2/catch.hpp>
#include <cmath>

#include "cassie_corrector.hpp"
#include "mirror_plane.hpp"
#include "synthetic.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;
using sketchlab::test::make_stroke;

namespace {

Workspace mirror_x() {
  Workspace ws;
  ws.mirror_enabled = true;
  ws.mirror_normal = Vec3::UnitX();
  ws.mirror_offset = 0.0;
  return ws;
}

}  // namespace

TEST_CASE("Item 18: a stroke drawn on the mirror plane is projected onto it, with no copy", "[cassie][mirror]") {
  Sketch sketch;
  sketch.workspace = mirror_x();
  // An arc in the plane x = 0, 1–1.8 cm off it (< 1.25δ = 2.5 cm).
  const Stroke s = make_stroke(1, 60, [](double u) {
    return Vec3(0.01 + 0.008 * std::sin(3.0 * u), 0.3 * u, 0.1 * std::sin(3.14159 * u));
  }, 1.5);
  const Correction c = correct_stroke(s, sketch, CassieParams{});
  REQUIRE(c.error.empty());
  REQUIRE(c.edit.curves_added.size() == 1);  // mirror = workspace, but projected: no copy
  for (const Vec3& p : c.edit.curves_added[0].curve.control_points) CHECK(p.x() == 0.0);
  CHECK(c.stats.extra.at("mirror_projected") == 1);
  // Drawn 4 cm off the plane it stays where it is and gets its copy.
  const Stroke far = make_stroke(2, 60, [](double u) { return Vec3(0.04, 0.3 * u, 0.1 * std::sin(3.14159 * u)); }, 1.5);
  const Correction d = correct_stroke(far, sketch, CassieParams{});
  REQUIRE(d.edit.curves_added.size() == 2);
  CHECK(d.edit.curves_added[0].curve.control_points[3].x() == Approx(0.04));
}

TEST_CASE("Item 18: no projection when an end tangent is along the normal or an intersection is off the plane",
          "[cassie][mirror]") {
  const Workspace ws = mirror_x();
  Curve c = make_line({0.01, 0, 0}, {0.015, 0.3, 0});
  Curve line = c;
  CHECK(project_onto_mirror(line, ws, {}, 0.025, 0.002, 0.5236));
  CHECK(line.control_points.front().x() == 0.0);
  // Half the mean end distance (lines): 0.5·(0.04 + 0.07)/2 = 2.75 cm > 2.5 cm.
  Curve off = make_line({0.04, 0, 0}, {0.07, 0.3, 0});
  CHECK_FALSE(project_onto_mirror(off, ws, {}, 0.025, 0.002, 0.5236));
  // An intersection 5 mm off the plane (> 0.1δ).
  Curve again = c;
  CHECK_FALSE(project_onto_mirror(again, ws, {Vec3(0.005, 0.1, 0)}, 0.025, 0.002, 0.5236));
  CHECK(again.control_points == c.control_points);
  // Leaving the plane along its normal.
  Curve normal = make_line({0.0, 0, 0}, {0.02, 0.005, 0});
  CHECK_FALSE(project_onto_mirror(normal, ws, {}, 0.025, 0.002, 0.5236));
}
