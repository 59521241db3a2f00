// Teacher-forced replays give a layer-aware corrector its reference scaffold:
// each reference curve is added on its stroke's layer (issue #18).
#include <catch2/catch.hpp>

#include "scaffoldsketch_corrector.hpp"
#include "sketchlab/lab/teacher_forced.hpp"
#include "test_helpers.hpp"

using namespace sketchlab;
using namespace sketchlab::scaffoldsketch;
using namespace sketchlab::scaffoldsketch::test;

TEST_CASE("teacher-forced references keep their stroke's layer", "[scaffoldsketch][teacher]") {
  Recording rec;
  double time = 0;
  auto add = [&](const Stroke& s, const Curve& reference) {
    rec.events.push_back({time, StrokeEvent{s}});
    rec.events.push_back({time, ReferenceEvent{s.id, "cassie", reference}});
    time += 1;
  };
  const Vec3 end(0.3, 1, 0), shape_start(1, 1.5, 0.5), shape_end(1.3, 1.5, 0.5);
  const Vec3 u = Vec3(0.3, 0.5, 0.4).normalized();  // no direction candidate
  // A scaffold line, then a scaffold stroke starting 1 cm from its end.
  add(straight_stroke(1, Vec3(0, 1, 0), end, Layer::scaffold), make_line(Vec3(0, 1, 0), end));
  const Vec3 a = end + Vec3(0.006, 0.008, 0);
  add(straight_stroke(2, a, a + 0.2 * u, Layer::scaffold), make_line(end, a + 0.2 * u));
  // A straight shape curve, then a scaffold stroke starting 1 cm from its end:
  // a shape curve is no scaffold line, nothing snaps to it.
  add(straight_stroke(3, shape_start, shape_end, Layer::shape), make_line(shape_start, shape_end));
  const Vec3 c = shape_end + Vec3(0.006, 0.008, 0);
  const Vec3 v = Vec3(-0.4, 0.5, 0.3).normalized();  // nor here, nor an equal length
  add(straight_stroke(4, c, c + 0.5 * v, Layer::scaffold), make_line(c, c + 0.5 * v));

  ScaffoldSketchCorrector corrector(ScaffoldParams{}, ShapeParams{});
  const std::vector<TeacherForcedStroke> r = teacher_forced(rec, corrector);
  REQUIRE(r.size() == 4);
  for (const TeacherForcedStroke& s : r) REQUIRE(s.error.empty());
  CHECK(r[1].constraints_enforced > 0);
  CHECK(r[1].output_snap[0] == "curve");  // joined to the reference line's end
  CHECK(r[1].endpoint_distance < 1e-9);
  CHECK(r[3].constraints_considered == 0);
  CHECK(r[3].output_snap[0].empty());
}
