// Line inference (Schmidt et al. 2009 §3.1): a nearest point on a line
// (Figure 7d) lying along the segment is no position constraint. A stroke
// drawn over a guideline from a vertex, ending short of a tick on it, gets
// the free-ended segment only through its free distance constraint, so the
// segment ending on the tick is chosen.
#include <catch2/catch.hpp>

#include "demo_scenes.hpp"
#include "line_inference.hpp"
#include "sketchlab/camera.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

const View view = demo::tablet_view(Vec3(1.2, 1.4, 2.6), Vec3(0.0, 0.1, 0.0));
// V and T on the guideline along x from V; a segment along z from each makes
// them scaffold vertices.
const Vec3 V(-0.3, 0, 0.2), T = V + 0.5 * Vec3::UnitX();

Sketch scene() {
  Sketch sketch;
  demo::add_curve(sketch, make_line(V, V + 0.2 * Vec3::UnitX()), Layer::guide);
  demo::add_curve(sketch, make_line(V, V - 0.3 * Vec3::UnitZ()), Layer::scaffold);
  demo::add_curve(sketch, make_line(T, T - 0.3 * Vec3::UnitZ()), Layer::scaffold);
  return sketch;
}

bool at(const Vec3& p, const Vec3& q) { return (p - q).norm() < 1e-9; }

}  // namespace

TEST_CASE("a nearest point on a line along the segment is not a position constraint",
          "[analytic][line]") {
  const Sketch sketch = scene();
  const Scaffold s = build_scaffold(sketch.network, Vec3::UnitY(), AnalyticParams{}.vanishing_merge);
  const Camera cam(view);
  const AnalyticParams p;
  // Over the guideline from V, ending 0.6 δ_min short of T's projection (the
  // pen stops there, so δ is about δ_min at the end).
  const Vec2 pv = cam.project(V).value(), pt = cam.project(T).value();
  const Vec3 end = V + (1.0 - 0.6 * p.delta_min * view.dpi / (pt - pv).norm()) * (T - V);
  const Stroke stroke = demo::projected_stroke(1, view, {V, end});
  const Stroke2d s2 = make_stroke_2d(stroke, view.dpi, p);
  StrokeEnd ends[2];
  stroke_ends(cam, s2, ends);
  const LineCandidates c = collect_line_candidates(s, cam, s2, ends, p);

  // The guideline is a nearest-point candidate at the stroke's end.
  bool along_guideline = false;
  int triplets_from_it = 0, free_from_it = 0;
  for (const Triplet& t : c.triplets) {
    const PointConstraint& o = c.points[t.origin][static_cast<std::size_t>(t.point)];
    if (t.origin != 1 || o.type != PointConstraint::Type::on_line || !s.lines[static_cast<std::size_t>(o.line)].guide)
      continue;
    along_guideline = true;
    const auto seg = evaluate_triplet(t, c, s, cam, ends);
    if (!seg || !lies_on_line(s.lines[static_cast<std::size_t>(o.line)], seg->first, seg->second, s.tolerance))
      continue;
    // Along the guideline: only with a free Cᵗ (the segment on the line,
    // both ends where the stroke puts them), never with Cᵗ at V.
    ++triplets_from_it;
    CHECK(t.distance.type == DistanceConstraint::Type::free);
    free_from_it += t.distance.type == DistanceConstraint::Type::free;
  }
  REQUIRE(along_guideline);
  CHECK(triplets_from_it == free_from_it);
  CHECK(free_from_it > 0);

  const LineInference li = infer_line(s, cam, s2, p, 7);
  REQUIRE(li.best);
  CHECK(at(li.best->segment.first, V));
  CHECK(at(li.best->segment.second, T));
}
