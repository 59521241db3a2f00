// Per-stroke latency of the JustDrawIt corrector with 10 and 200 curves in
// the sketch (target: <= 5 ms at 200 curves). Prints "name value unit".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

#include "jdi_params.hpp"
#include "justdrawit_corrector.hpp"
#include "sketchlab/session.hpp"

using namespace sketchlab;
using namespace sketchlab::justdrawit;

namespace {

View front_view() {
  View v;
  v.view = look_at(Vec3(0, 0, 3), Vec3::Zero(), Vec3::UnitY());
  v.projection = perspective(std::numbers::pi / 4, 1.0, 0.1, 100.0);
  v.viewport = Vec4(0, 0, 4000, 4000);
  return v;
}

Stroke pixel_stroke(StrokeId id, const View& v, const std::vector<Vec2>& px) {
  Stroke s;
  s.id = id;
  s.view = v;
  s.samples_are_pixels = true;
  double t = 0;
  for (const Vec2& p : px) {
    Sample smp;
    smp.position = Vec3(p.x(), p.y(), 0);
    smp.time = t += 0.01;
    s.samples.push_back(smp);
  }
  return s;
}

// A wavy stroke of `n` samples from a to b.
std::vector<Vec2> wavy(const Vec2& a, const Vec2& b, int n, double amp) {
  std::vector<Vec2> out;
  const Vec2 dir = (b - a).normalized(), perp(-dir.y(), dir.x());
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / (n - 1);
    out.push_back(a + u * (b - a) + amp * std::sin(u * 6.28) * perp);
  }
  return out;
}

double run(int curves) {
  const View v = front_view();
  const JdiParams p;
  Sketch sketch;
  // Curves on a grid of short strokes (new curves, as the corrector made
  // them), spaced more than the 8d join reach apart on a 4000 px canvas.
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(curves))));
  StrokeId id = 1;
  for (int i = 0; i < curves; ++i) {
    const double x = 240 + (i % cols) * (3520.0 / cols), y = 240 + (i / cols) * (3520.0 / cols);
    const Stroke s = pixel_stroke(id, v, wavy({x, y}, {x + 2400.0 / cols, y + 800.0 / cols}, 120, 4));
    const Correction c = justdrawit_correct(s, sketch, p);
    if (!c.error.empty()) {
      std::cerr << c.error << "\n";
      return -1;
    }
    sketch.network.apply(c.edit);
    sketch.strokes.emplace(s.id, s);
    ++id;
  }
  std::cout << "justdrawit_network_" << curves << "_curves " << sketch.network.curves().size()
            << " curves\n";
  // Timed: a stroke extending the middle curve (analysis against every
  // curve the bounding boxes do not cull, choice, promotion, join).
  const int mid = curves / 2;
  const double x = 240 + (mid % cols) * (3520.0 / cols), y = 240 + (mid / cols) * (3520.0 / cols);
  // Retrace the second half of its stroke, then run on 150 px past its end.
  const std::vector<Vec2> drawn = wavy({x, y}, {x + 2400.0 / cols, y + 800.0 / cols}, 120, 4);
  std::vector<Vec2> px(drawn.begin() + 60, drawn.end());
  const Vec2 dir = (drawn.back() - drawn[drawn.size() - 4]).normalized();
  for (int i = 1; i <= 100; ++i) px.push_back(drawn.back() + 1.5 * i * dir);
  const Stroke s = pixel_stroke(id, v, px);
  const int reps = 51;
  std::vector<double> times;
  std::string decision = "none";
  double analysed = 0;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const Correction c = justdrawit_correct(s, sketch, p);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!c.error.empty()) return -1;
    decision = c.stats.outcomes.at("decision");
    analysed = c.stats.extra.at("curves_analysed");
    times.push_back(ms);
  }
  std::sort(times.begin(), times.end());
  double total = 0;
  for (double t : times) total += t;
  std::cout << "justdrawit_stroke_latency_min_" << curves << "_curves " << times.front() << " ms\n";
  std::cout << "justdrawit_stroke_latency_p50_" << curves << "_curves " << times[times.size() / 2] << " ms\n";
  // extend: the stroke continues the middle curve.
  std::cout << "justdrawit_decision_" << curves << "_curves " << decision << " (decision)\n";
  std::cout << "justdrawit_curves_analysed_" << curves << "_curves " << analysed << " curves\n";
  return total / reps;
}

}  // namespace

int main() {
  for (int n : {10, 200}) {
    const double mean_ms = run(n);
    std::cout << "justdrawit_stroke_latency_mean_" << n << "_curves " << mean_ms << " ms\n";
  }
  return 0;
}
