// Teacher-forced rebuild with the reference's patches (lab teacher_forced.hpp,
// TeacherForcedOptions::patches): a stroke drawn over a patch CASSIE had is
// projected onto it (CASSIE app, item 20), and not before the patch exists
// or after it was deleted.
#include <catch2/catch.hpp>
#include <cmath>

#include "sketchlab/lab/teacher_forced.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "synthetic.hpp"

using namespace sketchlab;
using sketchlab::test::make_stroke;

namespace {

void add_stroke(Recording& rec, double time, const Stroke& s, const Curve& reference) {
  rec.events.push_back({time, StrokeEvent{s}});
  rec.events.push_back({time, ReferenceEvent{s.id, "cassie", reference}});
}

// The wavy stroke of on_surface_test.cpp, 1 cm above z = 0, inside the square.
Stroke wavy(StrokeId id) {
  return make_stroke(id, 60, [](double u) {
    return Vec3(-0.1 + 0.2 * u, 0.05 * std::sin(6.0 * u), 0.01 + 0.003 * std::sin(9.0 * u));
  }, 2.0);
}

double highest(const Curve& c) {
  double z = 0.0;
  for (const Vec3& p : c.control_points) z = std::max(z, std::abs(p.z()));
  return z;
}

}  // namespace

TEST_CASE("Teacher-forced: a stroke over a logged patch is projected onto it", "[cassie][teacher][surface]") {
  PluginHost host;
  host.load_directories({SKETCHLAB_BUILD_PLUGIN_DIR});
  REQUIRE(host.find(PluginKind::surfacer, "soapfilm"));  // CGAL: scripts/setup.sh
  auto corrector = host.make_corrector("cassie", {});
  auto surfacer = host.make_surfacer("soapfilm", {});

  // CASSIE's square of four lines (strokes 1–4, at 1–4 s) in z = 0, its patch
  // logged at 4.5 s and deleted by hand at 7.5 s; the same wavy stroke drawn
  // at 4.2 s (before the patch), 6 s (on it) and 8 s (after its deletion).
  Recording rec;
  const Vec3 c[4] = {{-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0.2, 0}, {-0.2, 0.2, 0}};
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = c[i], b = c[(i + 1) % 4];
    add_stroke(rec, 1.0 + i, make_stroke(static_cast<StrokeId>(i + 1), 20, [&](double u) { return Vec3(a + u * (b - a)); }),
               make_line(a, b));
  }
  // Their reference curves far away: the later strokes must not meet them.
  const Curve far = make_line({-0.1, 0, 1.0}, {0.1, 0, 1.0});
  add_stroke(rec, 4.2, wavy(5), far);
  add_stroke(rec, 6.0, wavy(6), far);
  add_stroke(rec, 8.0, wavy(7), far);

  TeacherForcedOptions opt;
  opt.patches.push_back({42, {1, 2, 3, 4}, 4.5, 7.5, true});
  opt.surfacer = surfacer.get();
  std::vector<std::string> warnings;
  const auto rows = teacher_forced(rec, *corrector, opt, &warnings);
  CHECK(warnings.empty());
  REQUIRE(rows.size() == 7);
  for (const auto& r : rows) REQUIRE(r.compared);
  CHECK(rows[4].patches == 0);
  CHECK(rows[5].patches == 1);
  CHECK(rows[6].patches == 0);
  // On the patch: every control point on the soap film of a planar square,
  // which is that plane.
  CHECK(highest(rows[5].output_curve) < 1e-9);
  CHECK(rows[5].stats.extra.at("on_surface_patch") >= 1);
  // Without the patch the stroke stays above the plane.
  CHECK(highest(rows[4].output_curve) > 5e-3);
  CHECK(highest(rows[6].output_curve) > 5e-3);

  SECTION("patches without a surfacer are refused") {
    opt.surfacer = nullptr;
    CHECK_THROWS_AS(teacher_forced(rec, *corrector, opt), std::invalid_argument);
  }
  SECTION("a patch over a stroke without a reference curve is left out with a warning") {
    opt.patches = {{43, {1, 2, 99}, 4.5, std::nullopt, true}};
    warnings.clear();
    const auto again = teacher_forced(rec, *corrector, opt, &warnings);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("patch 43") != std::string::npos);
    CHECK(again[5].patches == 0);
  }
}
