// Metrics of long strokes (issue 17: a 10^6-sample stroke took 78 s in the
// input deviation, every sample searched on every curve piece). The pruned
// search must give the brute-force figures exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "session_fixtures.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/run/metrics.hpp"

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
