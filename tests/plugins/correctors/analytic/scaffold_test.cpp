// Scaffold vanishing directions (Schmidt et al. 2009 §2, §4.2 / Fig. 11d): the
// first segment defines the primary directions; a later segment skewed from
// one of them adds a vanishing direction of its own unless it lies within
// `vanishing_merge` of it (the paper's suggested filtering of
// nearly-parallel vanishing directions).
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic_params.hpp"
#include "demo_scenes.hpp"
#include "scaffold.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

constexpr double deg = 3.14159265358979323846 / 180.0;

// The first segment along x in the ground plane, then one along x rotated
// by `skew` about the vertical.
Sketch skewed_pair(double skew) {
  Sketch sketch;
  demo::add_curve(sketch, make_line(Vec3(0, 0, 0), Vec3(0.3, 0, 0)), Layer::scaffold);
  const Vec3 d(std::cos(skew), 0, std::sin(skew));
  demo::add_curve(sketch, make_line(Vec3(0, 0, 0.2), Vec3(0, 0, 0.2) + 0.3 * d), Layer::scaffold);
  return sketch;
}

bool has_direction(const Scaffold& s, const Vec3& d) {
  for (const Vec3& e : s.vanishing)
    if (std::abs(e.dot(d.normalized())) > 1.0 - 1e-12) return true;
  return false;
}

}  // namespace

TEST_CASE("a skewed segment adds a vanishing direction unless within vanishing_merge",
          "[analytic][scaffold]") {
  const double skew = 2.0 * deg;
  const Vec3 d(std::cos(skew), 0, std::sin(skew));
  const Sketch sketch = skewed_pair(skew);

  // Default (0.26°): up, x, z and the skewed direction (Fig. 11d).
  const Scaffold by_default = build_scaffold(sketch.network, Vec3::UnitY(), AnalyticParams{}.vanishing_merge);
  CHECK(by_default.vanishing.size() == 4);
  CHECK(has_direction(by_default, Vec3::UnitX()));
  CHECK(has_direction(by_default, Vec3::UnitZ()));
  CHECK(has_direction(by_default, Vec3::UnitY()));
  CHECK(has_direction(by_default, d));

  // Within 3°: no new direction; the segment itself stays as drawn.
  const Scaffold merged = build_scaffold(sketch.network, Vec3::UnitY(), 3.0 * deg);
  CHECK(merged.vanishing.size() == 3);
  CHECK_FALSE(has_direction(merged, d));
  REQUIRE(merged.lines.size() == 2);
  CHECK(merged.lines[1].direction().dot(d) > 1.0 - 1e-12);

  // Beyond it (1°), the skewed direction is kept.
  const Scaffold narrow = build_scaffold(sketch.network, Vec3::UnitY(), 1.0 * deg);
  CHECK(has_direction(narrow, d));
}
