// Metrics of long strokes (issue 17: a 10^6-sample stroke took 78 s in the
// input deviation, every sample searched on every curve piece). The pruned
// search must give the brute-force figures exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "session_fixtures.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/lab/metrics.hpp"
#include "sketchlab/view.hpp"

using namespace sketchlab;

TEST_CASE("input deviation of a long noisy stroke equals the brute-force distances", "[metrics][reliability]") {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> jitter(0.0, 0.002);
  const int n = 4000;
  const Stroke stroke = test::sampled_stroke(1, n, 0.0, 1.0 / 90.0, [&](int i) -> Vec3 {
    const double u = double(i) / (n - 1);
    return {0.15 * std::cos(6 * M_PI * u) + jitter(rng), 0.15 * std::sin(6 * M_PI * u) + jitter(rng),
            0.2 * u + jitter(rng)};
  });
  ReplayResult result{"fit", RecordingHeader{}, Session(Workspace{}, std::make_shared<test::FitCorrector>(), nullptr), {}};
  result.steps.push_back(result.session.handle(Event{n / 90.0, StrokeEvent{stroke}}));
  REQUIRE(result.steps.back().error.empty());
  const Sketch& sketch = result.session.sketch();
  REQUIRE(!sketch.network.curves().empty());

  double sum = 0, max = 0;
  const auto& samples = sketch.strokes.at(1).samples;
  for (const Sample& s : samples) {
    double d = INFINITY;
    for (const auto& [id, c] : sketch.network.curves()) d = std::min(d, closest_point(c.curve, s.position).distance);
    sum += d;
    max = std::max(max, d);
  }
  const CaseMetrics m = compute_metrics(result);
  CHECK(m.values.at("input_deviation_max_m") == Approx(max).margin(1e-12));
  CHECK(m.values.at("input_deviation_mean_m") == Approx(sum / double(samples.size())).margin(1e-12));
}

namespace {

// Puts, for each 2D stroke, the intended curve of that stroke scaled by
// `scale` about the stroke's camera eye: what a single view cannot tell from
// the intended curve.
class EyeScaledCorrector : public Corrector {
 public:
  // take_over: each stroke's curve replaces the curves drawn before it (an
  // oversketch taking over a curve, JustDrawIt §4.4).
  EyeScaledCorrector(std::map<StrokeId, Curve> truth, double scale, bool take_over = false)
      : truth_(std::move(truth)), scale_(scale), take_over_(take_over) {}
  StrokeSpace stroke_space() const override { return StrokeSpace::pixels; }
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Curve c = truth_.at(stroke.id);
    const Vec3 eye = eye_position(*stroke.view);
    for (Vec3& p : c.control_points) p = eye + scale_ * (p - eye);
    NetworkCurve nc;
    nc.id = sketch.network.next_curve_id();
    nc.curve = c;
    nc.source_stroke = stroke.id;
    Correction out;
    out.edit.curves_added.push_back(nc);
    if (take_over_)
      for (const auto& [id, old] : sketch.network.curves()) out.edit.curves_removed.push_back(id);
    return out;
  }

 private:
  std::map<StrokeId, Curve> truth_;
  double scale_;
  bool take_over_;
};

ReplayResult eye_scaled_case(double scale, bool second_eye, bool take_over = false) {
  const std::map<StrokeId, Curve> truth{{1, make_line({0, 1, 0}, {0.3, 1, 0})},
                                        {2, make_line({0.3, 1, 0}, {0.3, 1.3, 0.1})}};
  ReplayResult r{"eye", RecordingHeader{}, Session(Workspace{}, std::make_shared<EyeScaledCorrector>(truth, scale, take_over), nullptr), {}};
  for (const auto& [id, curve] : truth) {
    View v;
    const Vec3 eye = (second_eye && id == 2) ? Vec3(-0.8, 1.6, 0.9) : Vec3(0.6, 1.5, 1.0);
    v.view = look_at(eye, {0.15, 1.1, 0}, Vec3::UnitY());
    v.projection = perspective(0.6, 1.6, 0.01, 100.0);
    v.viewport = Vec4(0, 0, 1600, 1000);
    Stroke s = test::sampled_stroke(id, 3, double(id), 0.1, [](int i) { return Vec3(100.0 + 10 * i, 200.0, 0.0); });
    s.view = v;
    s.samples_are_pixels = true;
    r.steps.push_back(r.session.handle(Event{double(id) + 0.5, StrokeEvent{s}}));
    REQUIRE(r.steps.back().error.empty());
    r.steps.push_back(r.session.handle(Event{double(id) + 0.5, ReferenceEvent{id, "ground_truth", curve}}));
  }
  return r;
}

}  // namespace

TEST_CASE("the eye-scale alignment removes exactly the scale one view leaves open", "[metrics][ground_truth]") {
  const CaseMetrics m = compute_metrics(eye_scaled_case(0.4, false));
  CHECK(m.values.at("gt_distance_mean_m") > 0.1);
  CHECK(m.values.at("gt_distance_max_aligned_eye_scale_m") < 1e-9);
  CHECK(m.values.at("gt_eye_scale") == Approx(2.5).epsilon(1e-9));
  CHECK(m.values.at("gt_shape_distance_mean_m") > 0.1);
  CHECK(m.values.at("gt_shape_distance_mean_aligned_eye_scale_m") < 1e-9);
  CHECK(m.values.at("gt_shape_coverage_mean_aligned_eye_scale_m") < 1e-9);

  // Two eye positions fix the scale: no aligned figure, the raw one stays.
  const CaseMetrics two = compute_metrics(eye_scaled_case(0.4, true));
  CHECK(two.values.count("gt_distance_mean_m") == 1);
  CHECK(two.values.count("gt_distance_mean_aligned_eye_scale_m") == 0);
  CHECK(two.values.count("gt_shape_distance_mean_aligned_eye_scale_m") == 0);
  // Still none when the second view's stroke took over the first's curve:
  // the live strokes share one eye, the session does not.
  const CaseMetrics over = compute_metrics(eye_scaled_case(0.4, true, true));
  CHECK(over.values.at("curves") == 1);
  CHECK(over.values.count("gt_distance_mean_m") == 1);
  CHECK(over.values.count("gt_distance_mean_aligned_eye_scale_m") == 0);
}

namespace {

// Draws each stroke's intended curve exactly; a stroke whose intended curve
// is already drawn takes that curve over (removes it, adds its own), as
// JustDrawIt keeps one curve for the last stroke of a multi-stroke curve.
class TakeOverCorrector : public Corrector {
 public:
  explicit TakeOverCorrector(std::map<StrokeId, Curve> truth) : truth_(std::move(truth)) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction out;
    for (const auto& [id, c] : sketch.network.curves())
      if (c.curve == truth_.at(stroke.id)) out.edit.curves_removed.push_back(id);
    NetworkCurve nc;
    nc.id = sketch.network.next_curve_id();
    nc.curve = truth_.at(stroke.id);
    nc.source_stroke = stroke.id;
    out.edit.curves_added.push_back(nc);
    return out;
  }

 private:
  std::map<StrokeId, Curve> truth_;
};

}  // namespace

TEST_CASE("relations on a stroke whose curve a later stroke took over are scored on that stroke",
          "[metrics][ground_truth]") {
  const Curve a = make_line({0, 1, 0}, {0.3, 1, 0}), b = make_line({0.3, 1, 0}, {0.3, 1.3, 0});
  // Strokes 1 and 3 draw a (3 takes it over), stroke 2 draws b; the ground
  // truth lists the relations on the curves' first strokes, 1 and 2.
  const std::map<StrokeId, Curve> truth{{1, a}, {2, b}, {3, a}};
  ReplayResult r{"takeover", RecordingHeader{}, Session(Workspace{}, std::make_shared<TakeOverCorrector>(truth), nullptr), {}};
  for (const auto& [id, curve] : truth) {
    const Stroke s = test::sampled_stroke(id, 3, double(id), 0.1, [&](int i) { return evaluate(curve, 0.5 * i); });
    r.steps.push_back(r.session.handle(Event{double(id) + 0.5, StrokeEvent{s}}));
    REQUIRE(r.steps.back().error.empty());
    r.steps.push_back(r.session.handle(Event{double(id) + 0.5, ReferenceEvent{id, "ground_truth", curve}}));
    if (id == 2) {
      r.steps.push_back(r.session.handle(Event{2.5, RelationEvent{"ground_truth", ConstraintKind::perpendicular, {1, 2}, {0.3, 0.0}}}));
      r.steps.push_back(r.session.handle(Event{2.5, RelationEvent{"ground_truth", ConstraintKind::coincident_point, {1, 2}, {0.3, 0.0}}}));
    }
  }
  REQUIRE(r.session.sketch().network.curves().size() == 2);
  const CaseMetrics m = compute_metrics(r);
  CHECK(m.values.at("gt_distance_max_m") < 1e-12);
  CHECK(m.values.at("gt_perpendicular_recall") == 1.0);
  CHECK(m.values.at("gt_coincident_point_recall") == 1.0);
}

namespace {

// Stroke 1 draws `first`; stroke 2 extends it into `merged` (one curve for
// both, kept for the last stroke), as JustDrawIt extends a curve with a
// stroke drawn in line with it (§4.2).
class ExtendCorrector : public Corrector {
 public:
  ExtendCorrector(Curve first, Curve merged) : first_(std::move(first)), merged_(std::move(merged)) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction out;
    for (const auto& [id, c] : sketch.network.curves()) out.edit.curves_removed.push_back(id);
    NetworkCurve nc;
    nc.id = sketch.network.next_curve_id();
    nc.curve = stroke.id == 1 ? first_ : merged_;
    nc.source_stroke = stroke.id;
    out.edit.curves_added.push_back(nc);
    return out;
  }

 private:
  Curve first_, merged_;
};

CaseMetrics extended_case(const Curve& second_truth) {
  const Curve a = make_line({0, 1, 0}, {0.3, 1, 0});
  const std::map<StrokeId, Curve> truth{{1, a}, {2, second_truth}};
  ReplayResult r{"extend", RecordingHeader{},
                 Session(Workspace{}, std::make_shared<ExtendCorrector>(a, make_line({0, 1, 0}, {0.6, 1, 0})), nullptr), {}};
  for (const auto& [id, curve] : truth) {
    const Stroke s = test::sampled_stroke(id, 3, double(id), 0.1, [&](int i) { return evaluate(curve, 0.5 * i); });
    r.steps.push_back(r.session.handle(Event{double(id) + 0.5, StrokeEvent{s}}));
    REQUIRE(r.steps.back().error.empty());
    r.steps.push_back(r.session.handle(Event{double(id) + 0.5, ReferenceEvent{id, "ground_truth", curve}}));
  }
  REQUIRE(r.session.sketch().network.curves().size() == 1);
  return compute_metrics(r);
}

}  // namespace

TEST_CASE("the shape figures score a curve built from two strokes against both intended curves",
          "[metrics][ground_truth]") {
  // Exactly the two intended curves, drawn in line: the per-stroke figure
  // compares the whole curve with the second stroke's half only.
  const CaseMetrics exact = extended_case(make_line({0.3, 1, 0}, {0.6, 1, 0}));
  CHECK(exact.values.at("gt_distance_max_m") == Approx(0.3).margin(1e-6));
  CHECK(exact.values.at("gt_shape_distance_mean_m") < 1e-12);
  CHECK(exact.values.at("gt_shape_coverage_mean_m") < 1e-12);

  // The second intended curve reaches 0.3 m further than the output: the
  // output lies on the intended shape, the coverage counts what it misses.
  const CaseMetrics shorter = extended_case(make_line({0.3, 1, 0}, {0.9, 1, 0}));
  CHECK(shorter.values.at("gt_shape_distance_mean_m") < 1e-12);
  CHECK(shorter.values.at("gt_shape_coverage_mean_m") > 0.02);
}
