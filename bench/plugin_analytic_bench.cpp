// Analytic-drawing corrector benchmark (Schmidt et al. 2009): line inference
// latency against scaffolds of 50 and 500 segments (target <= 30 ms), curve
// inference over the 5- and 9-point helix constraint sets of Figure 10
// (target <= 1 s; the paper: ~2 s and over a minute). Prints `name value unit`.
#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>

#include "analytic_corrector.hpp"
#include "demo_scenes.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// About `n` scaffold segments: a lattice of 0.3 m boxes (12 edges each) on
// the ground, seen from a tablet camera; the stroke traces a vertical edge of
// the box nearest the viewer (noise 0.7 px, 10 in/s). With `arcs`, each box
// also gets a quarter-circle Bézier on its top face (centre at its back-left
// top corner), so every stroke end is tested against that many curves
// (line/curve intersections, Figure 7c).
void bench_lines(int n, bool arcs = false) {
  Sketch sketch;
  const int boxes = std::max(1, n / 12);
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(boxes))));
  const double b = 0.3, gap = 0.6;
  int added = 0;
  for (int k = 0; k < boxes; ++k) {
    const Vec3 o(gap * (k % side) - 0.5 * gap * side, 0.0, -gap * (k / side));
    const Vec3 dx = b * Vec3::UnitX(), dy = b * Vec3::UnitY(), dz = b * Vec3::UnitZ();
    const Vec3 c[8] = {o, o + dx, o + dx + dz, o + dz, o + dy, o + dx + dy, o + dx + dz + dy, o + dz + dy};
    const int e[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& ed : e) {
      if (added == n) break;
      demo::add_curve(sketch, make_line(c[ed[0]], c[ed[1]]), Layer::scaffold);
      ++added;
    }
    if (arcs) {
      const double handle = 0.5522847498 * b;  // cubic quarter-circle handle
      Curve arc;
      arc.control_points = {c[4], c[4] + handle * Vec3::UnitX(), c[6] - handle * Vec3::UnitZ(), c[6]};
      arc.sharp = {false, false};
      demo::add_curve(sketch, arc, Layer::scaffold);
    }
  }
  const std::string label =
      std::to_string(added) + "_segments" + (arcs ? "_" + std::to_string(boxes) + "_arcs" : "");
  const View view = demo::tablet_view(Vec3(0.4, 2.0, 3.0), Vec3(0.0, 0.0, -0.5 * gap * side));
  AnalyticCorrector corrector{AnalyticParams{}};
  const int reps = 20;
  std::vector<double> times;
  double combos = 0;
  // A box near the viewer: its front-left vertical edge, drawn again.
  const Vec3 o(gap * ((boxes - 1) % side) - 0.5 * gap * side, 0.0, -gap * ((boxes - 1) / side));
  for (int r = 0; r < reps; ++r) {
    const Stroke s = demo::projected_stroke(static_cast<StrokeId>(1000 + r), view,
                                            {o + Vec3(0, 0, 0.3), o + Vec3(0, 0.3, 0.3)}, 0.7, 5 + r);
    const auto t0 = std::chrono::steady_clock::now();
    const Correction c = corrector.correct(s, sketch);
    times.push_back(ms_since(t0));
    combos = c.stats.extra.count("combinations") ? c.stats.extra.at("combinations") : 0;
  }
  std::sort(times.begin(), times.end());
  std::printf("line_inference_%s_median %.3f ms\n", label.c_str(), times[times.size() / 2]);
  std::printf("line_inference_%s_max %.3f ms\n", label.c_str(), times.back());
  std::printf("line_inference_%s_triplets %.0f count\n", label.c_str(), combos);
  std::fflush(stdout);
}

Correction run_helix(int points, const AnalyticParams& params, double& ms) {
  Sketch sketch;
  demo::add_helix_scaffold(sketch, points);
  const View view = demo::tablet_view(Vec3(2.2, 1.6, 2.6), Vec3(0, 0.6, 0));
  AnalyticCorrector corrector{params};
  const Stroke s = demo::projected_stroke(1, view, demo::helix_polyline(points), 0.7, 3);
  const auto t0 = std::chrono::steady_clock::now();
  Correction c = corrector.correct(s, sketch);
  ms = ms_since(t0);
  return c;
}

// Branch-and-bound (default) against exhaustive search: the same curve must
// win; g_bound_exceeded counts fitted curves above their family's G bound.
void bench_helix(int points) {
  double t = 0, t_all = 0;
  const Correction c = run_helix(points, AnalyticParams{}, t);
  AnalyticParams all;
  all.curve_exhaustive = true;
  const Correction e = run_helix(points, all, t_all);
  auto get = [](const Correction& x, const char* k) { return x.stats.extra.count(k) ? x.stats.extra.at(k) : 0.0; };
  double diff = 1e9;
  if (c.edit.curves_added.size() == 1 && e.edit.curves_added.size() == 1 &&
      c.edit.curves_added[0].curve.control_points.size() == e.edit.curves_added[0].curve.control_points.size()) {
    diff = 0;
    const auto& a = c.edit.curves_added[0].curve.control_points;
    const auto& b = e.edit.curves_added[0].curve.control_points;
    for (std::size_t i = 0; i < a.size(); ++i) diff = std::max(diff, (a[i] - b[i]).norm());
  }
  std::printf("curve_inference_%d_points %.1f ms\n", points, t);
  std::printf("curve_inference_%d_points_combinations %.0f count\n", points, get(c, "combinations"));
  std::printf("curve_inference_%d_points_fitted %.0f count\n", points, get(c, "curves_fitted"));
  std::printf("curve_inference_%d_points_exhaustive %.1f ms\n", points, t_all);
  std::printf("curve_inference_%d_points_exhaustive_fitted %.0f count\n", points, get(e, "curves_fitted"));
  std::printf("curve_inference_%d_points_g_bound_exceeded %.0f count\n", points, get(c, "g_bound_exceeded"));
  std::printf("curve_inference_%d_points_vs_exhaustive_max_diff %.3g m\n", points, diff);
  std::fflush(stdout);
}

}  // namespace

int main() {
  bench_lines(50);
  bench_lines(500);
  bench_lines(500, true);
  bench_helix(5);
  bench_helix(9);
  return 0;
}
