#include <catch2/catch.hpp>

#include <numbers>
#include <random>

#include "kernel/preprocess/synthetic_strokes.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/preprocess/preprocess.hpp"
#include "sketchlab/preprocess/rdp.hpp"

using namespace sketchlab;

TEST_CASE("default parameters are CASSIE's and valid", "[preprocess]") {
  const PreprocessParams p;
  REQUIRE(validate(p).empty());
  REQUIRE(p.delta == 0.02);
  REQUIRE(p.fit_error_factor == 0.5);
  REQUIRE(p.max_g1_angle == std::numbers::pi / 4);
  REQUIRE(p.hook_max_length_factor == 3.0);
  REQUIRE(p.hook_max_fraction == 0.15);
  PreprocessParams bad;
  bad.delta = -1.0;
  REQUIRE(validate(bad).find("delta") != std::string::npos);
}

TEST_CASE("a quick straight stroke becomes a line", "[preprocess]") {
  std::mt19937_64 rng(5);
  const auto s = test::sample_path(test::straight(Vec3(0, 1, 0), Vec3(0.4, 1.1, 0.2)), 200,
                                   0.001, 0.6, rng);
  const Preprocessed r = preprocess_stroke(s.points, s.times, PreprocessParams{}, 1.0);
  REQUIRE(r.is_line);
  REQUIRE(r.curve.kind == CurveKind::line);
  REQUIRE(r.curve.control_points.front() == r.points.front());
  REQUIRE(r.curve.control_points.back() == r.points.back());
  REQUIRE(r.points.size() == r.kept.size());
}

TEST_CASE("a curved stroke is fitted within tolerance of its simplified samples",
          "[preprocess]") {
  std::mt19937_64 rng(6);
  const PreprocessParams params;
  for (double scale : {0.5, 1.0, 4.0}) {
    // Drawn at zoom s, the stroke is 1/s as large in workspace units.
    auto path = test::arc(0.2 / scale, 3.0);
    const auto s = test::sample_path(path, 300, 0.001 / scale, 0.5 / scale, rng);
    const Preprocessed r = preprocess_stroke(s.points, s.times, params, scale);
    REQUIRE_FALSE(r.is_line);
    REQUIRE(validate(r.curve).empty());
    REQUIRE(r.kept == IndexRange{0, s.points.size() - 1});
    const double d = params.delta / scale;
    for (const Vec3& p : rdp_simplify(r.points, params.rdp_epsilon_factor * d)) {
      REQUIRE(closest_point(r.curve, p).distance <= params.fit_error_factor * d);
    }
  }
}

TEST_CASE("the stroke overload trims hooks and reports the kept range", "[preprocess]") {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 0.0005);
  Stroke st;
  st.id = 42;
  double t = 0.0;
  auto add = [&](const Vec3& p) {
    Sample smp;
    smp.position = p + Vec3(g(rng), g(rng), g(rng));
    smp.time = t;
    t += 0.005;
    st.samples.push_back(smp);
  };
  for (int i = 10; i > 0; --i) add(Vec3(0, 0.002 * i, 0));  // 2 cm hook along -y
  for (int i = 0; i <= 150; ++i) add(Vec3(0.002 * i, 0, 0));
  const Preprocessed r = preprocess_stroke(st);
  REQUIRE(r.kept.first >= 8);
  REQUIRE(r.kept.first <= 12);
  REQUIRE(r.kept.last == st.samples.size() - 1);
  REQUIRE(r.is_line);
}

TEST_CASE("preprocess_stroke rejects unusable strokes", "[preprocess]") {
  const PreprocessParams p;
  REQUIRE_THROWS_AS(preprocess_stroke({Vec3::Zero()}, {}, p, 1.0), std::invalid_argument);
  REQUIRE_THROWS_AS(preprocess_stroke({Vec3::Ones(), Vec3::Ones(), Vec3::Ones()}, {}, p, 1.0),
                    std::invalid_argument);
  REQUIRE_THROWS_AS(preprocess_stroke({Vec3::Zero(), Vec3::UnitX()}, {}, p, 0.0),
                    std::invalid_argument);
  REQUIRE_THROWS_AS(preprocess_stroke({Vec3::Zero(), Vec3::UnitX()}, {0.0}, p, 1.0),
                    std::invalid_argument);
  PreprocessParams no_lines;
  no_lines.detect_lines = false;
  REQUIRE_THROWS_AS(preprocess_stroke({Vec3::Zero(), Vec3::UnitX()}, {1.0, 0.0}, no_lines, 1.0),
                    std::invalid_argument);
  Stroke empty;
  empty.id = 12;
  try {
    preprocess_stroke(empty);
    FAIL("expected std::invalid_argument");
  } catch (const std::invalid_argument& e) {
    REQUIRE(std::string(e.what()).find("stroke 12") != std::string::npos);
  }
  // Two distinct points are enough.
  const Preprocessed two = preprocess_stroke({Vec3::Zero(), Vec3(0.1, 0, 0)}, {}, p, 1.0);
  REQUIRE(validate(two.curve).empty());
}

// Item 1 as CASSIE's structuring shows it (app_trim_last_end): the curve ends
// 0.02 s of hand motion before the last sample, at the hand's speed over its
// last 0.1 s, on the input; the first end stays at the first sample, and
// without the flag the last end too.
TEST_CASE("app_trim_last_end ends the curve 0.02 s of motion before the last sample", "[preprocess]") {
  std::mt19937_64 rng(8);
  struct Case {
    const char* name;
    test::SyntheticStroke s;
    bool line;
  };
  // An arc (6.8 mm between samples, 13.6 ms apart) and a quick straight
  // stroke (item 2 makes it a line, whose ends are the trimmed samples'),
  // both at constant speed.
  const std::vector<Case> cases{
      {"arc", test::sample_path(test::arc(0.2, 2.0), 60, 0.0, 0.5, rng), false},
      {"line", test::sample_path(test::straight(Vec3(0, 1, 0), Vec3(0.3, 1.0, 0.1)), 50, 0.0, 1.0, rng), true}};
  for (const Case& c : cases) {
    INFO(c.name);
    const std::vector<Vec3>& p = c.s.points;
    const std::vector<double>& t = c.s.times;
    PreprocessParams params = cassie_app_preprocess();
    const Preprocessed kept = preprocess_stroke(p, t, params, 1.0);
    params.app_trim_last_end = true;
    const Preprocessed trimmed = preprocess_stroke(p, t, params, 1.0);
    REQUIRE(kept.is_line == c.line);
    REQUIRE(trimmed.is_line == c.line);

    // At constant speed, where the times put the hand 0.02 s before the end.
    const double at = t.back() - params.app_end_trim;
    std::size_t j = 1;
    while (t[j] <= at) ++j;
    const Vec3 expected = p[j - 1] + (at - t[j - 1]) / (t[j] - t[j - 1]) * (p[j] - p[j - 1]);
    CHECK((trimmed.curve.control_points.back() - expected).norm() < 1e-12);
    CHECK(trimmed.curve.control_points.front() == p.front());
    CHECK(trimmed.kept == IndexRange{0, j - 1});
    CHECK(kept.curve.control_points.back() == p.back());
    CHECK(kept.curve.control_points.front() == p.front());
  }

  // Times in bursts (a desktop viewer stamps coalesced events with one time):
  // 30 samples 1 cm apart, three to a time, 40 ms apart, i.e. 0.75 m/s. The
  // cut is 0.75 m/s × 0.02 s = 1.5 cm, not what the last burst's times say
  // (they put 2 cm of motion in no time).
  test::SyntheticStroke bursts;
  for (int i = 0; i < 30; ++i) {
    bursts.points.emplace_back(0.01 * i, 1.0, 0.0);
    bursts.times.push_back(0.04 * (i / 3));
  }
  PreprocessParams params = cassie_app_preprocess();
  params.app_trim_last_end = true;
  const Preprocessed r = preprocess_stroke(bursts.points, bursts.times, params, 1.0);
  REQUIRE(r.is_line);
  CHECK((r.curve.control_points.back() - Vec3(0.275, 1.0, 0.0)).norm() < 1e-12);
  CHECK(r.curve.control_points.front() == bursts.points.front());
}
