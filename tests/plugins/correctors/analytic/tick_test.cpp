// Dimension ticks (Schmidt et al. 2009 §2.3, Figure 6): a tick-mark over a
// vertex on one guideline transfers its distance A from the guidelines'
// intersection to every other guideline through it, at ±A; a short stroke
// joining two known points is a segment, not a tick.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "drawing.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;
using namespace sketchlab::analytic::test;

namespace {

// The tick keypoints of the guidelines of the sketch.
std::vector<Vec3> ticks(const Sketch& sketch) {
  std::vector<Vec3> out;
  for (const auto& [id, c] : sketch.network.curves())
    for (const Keypoint& k : c.keypoints)
      if (k.kind == Keypoint::Kind::tick) out.push_back(k.position);
  return out;
}

bool has(const std::vector<Vec3>& points, const Vec3& p, double tol) {
  return std::any_of(points.begin(), points.end(), [&](const Vec3& q) { return (q - p).norm() < tol; });
}

const View view = demo::tablet_view(Vec3(1.2, 1.4, 2.6), Vec3(0.0, 0.1, 0.0));
const Vec3 x = Vec3::UnitX(), z = Vec3::UnitZ();
const Vec3 B0(-0.3, 0, 0.2), B1 = B0 + 0.5 * x;

}  // namespace

TEST_CASE("Figure 6: a tick over a vertex transfers its distance to the crossing guideline, both ways",
          "[analytic][tick]") {
  Drawing d(view);
  d.draw(demo::segment(B0, B1), 0.0);  // first stroke: the ground plane
  REQUIRE(stat(d.guideline(B0, x, 0.0), "guideline") == 1);  // along the edge, through B1
  const StepReport g = d.guideline(B0, z, 0.0);
  REQUIRE(stat(g, "guideline") == 1);
  // A 24 px tick across the x guideline over B1.
  const Vec3 across = x.cross(B1 - eye_position(view)).normalized();
  const double half = 12.0 * std::tan(17.5 * std::numbers::pi / 180.0) / 500.0 * (B1 - eye_position(view)).norm();  // 12 px
  const StepReport t = d.draw({B1 - half * across, B1 + half * across}, 0.0);
  CHECK(stat(t, "tick") == 1);
  const std::vector<Vec3> k = ticks(d.sketch());
  // The tick snaps to B1; A = 0.5 lands at B0 ± 0.5 z on the z guideline.
  CHECK(has(k, B1, 1e-9));
  CHECK(has(k, B0 + 0.5 * z, 1e-9));
  CHECK(has(k, B0 - 0.5 * z, 1e-9));
}

TEST_CASE("a short stroke between two known points is a segment, not a tick", "[analytic][tick]") {
  // A foreshortened edge shorter than a tick (0.4 in) from B0 to the vertex
  // C, drawn along a guideline through both.
  const Vec3 C = B0 + 0.06 * z;
  Sketch sketch;
  demo::add_curve(sketch, make_line(B0, B1), Layer::scaffold);
  demo::add_curve(sketch, make_line(C + 0.5 * x, C), Layer::scaffold);
  demo::add_curve(sketch, make_line(B0, B0 + z), Layer::guide);
  REQUIRE((world_to_pixel(view, C) - world_to_pixel(view, B0)).head<2>().norm() < 0.4 * 96.0);
  AnalyticCorrector corrector{AnalyticParams{}};
  const Correction r = corrector.correct(demo::projected_stroke(100, view, {B0, C}), sketch);
  REQUIRE(r.error.empty());
  CHECK(r.stats.extra.count("tick") == 0);
  REQUIRE(r.stats.extra.count("line") == 1);
  REQUIRE(r.edit.curves_added.size() == 1);
  const Curve& l = r.edit.curves_added[0].curve;
  CHECK((l.control_points.front() - B0).norm() < 1e-9);
  CHECK((l.control_points.back() - C).norm() < 1e-9);
}

TEST_CASE("a tick stopping within δ of the guideline's projection still ticks it (§3.1 eq. 3)", "[analytic][tick]") {
  // The tick lies wholly beside the x guideline, its near end about 4 px from
  // the projection (δ ≥ δ_min = 9.6 px): the guideline was drawn from a known
  // point up to 2δ off, so the user's tick over the drawn stroke can miss the
  // inferred line's projection by that much.
  const Vec3 across = x.cross(B1 - eye_position(view)).normalized();
  const double px = std::tan(17.5 * std::numbers::pi / 180.0) / 500.0 * (B1 - eye_position(view)).norm();
  for (const double reach : {1.0, 0.0}) {
    AnalyticParams p;
    p.tick_reach = reach;
    Drawing d(view, p);
    d.draw(demo::segment(B0, B1), 0.0);
    REQUIRE(stat(d.guideline(B0, x, 0.0), "guideline") == 1);
    REQUIRE(stat(d.guideline(B0, z, 0.0), "guideline") == 1);
    const StepReport t = d.draw({B1 + 4.0 * px * across, B1 + 24.0 * px * across}, 0.0);
    const std::vector<Vec3> k = ticks(d.sketch());
    if (reach > 0) {
      CHECK(stat(t, "tick") == 1);
      CHECK(has(k, B1, 1e-9));
      CHECK(has(k, B0 + 0.5 * z, 1e-9));
      CHECK(has(k, B0 - 0.5 * z, 1e-9));
    } else {
      CHECK(stat(t, "tick") == 0);
      CHECK(k.empty());
    }
  }
}
