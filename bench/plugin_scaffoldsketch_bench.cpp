// ScaffoldSketch corrector benchmark (built by plugins/correctors/scaffoldsketch
// as bench_scaffoldsketch). Prints "name value unit" lines.
//   - scaffold line against 45 and 500 existing lines (edges of a lattice of
//     cubes; the new line is a noisy lattice edge, so it has point–point,
//     point–line, parallel, perpendicular and equal-length candidates), the
//     lattice exact (a corrected scaffold) or jittered by 1 mm (nothing
//     identical to merge);
// Wall-clock and thread-CPU percentiles are both printed: on the shared
// machine the wall-clock p95 mostly measures preemption.
//   - shape curve through 3, 6 and 10 keypoints (midpoints of scaffold lines
//     crossing a spiral stroke).
// Paper (Python): 0.2–1.1 s per line at ~45 lines, up to ~1 s per 10-keypoint
// curve. Targets: p95 <= 1 ms per line at 45 lines, <= 2 ms per curve.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <time.h>
#include <vector>

#include "scaffoldsketch_corrector.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/sketch.hpp"

using namespace sketchlab;
using namespace sketchlab::scaffoldsketch;

namespace {

Stroke line_stroke(StrokeId id, const Vec3& a, const Vec3& b, Layer layer) {
  Stroke s;
  s.id = id;
  s.layer = layer;
  for (int i = 0; i <= 20; ++i) {
    Sample smp;
    smp.position = a + (b - a) * (i / 20.0);
    smp.time = i * 0.01;
    s.samples.push_back(smp);
  }
  return s;
}

void add_line(Sketch& sketch, const Vec3& a, const Vec3& b) {
  Edit e;
  e.curves_added.push_back(
      make_network_curve(sketch.network.next_curve_id(), make_line(a, b), Layer::scaffold));
  sketch.network.apply(e);
}

struct Figures {
  double p50 = 0, p95 = 0;          // wall clock, ms
  double cpu_p50 = 0, cpu_p95 = 0;  // this thread's CPU time, ms (excludes preemption on a loaded machine)
  double mean_iterations = 0, mean_constraints = 0;
};

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

template <class MakeStroke>
Figures time_corrections(ScaffoldSketchCorrector& corrector, const Sketch& sketch, int runs,
                         MakeStroke make) {
  std::vector<double> ms, cpu;
  double iterations = 0, constraints = 0;
  for (int r = 0; r < runs; ++r) {
    const Stroke s = make(r);
    const double c0 = thread_cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    const Correction c = corrector.correct(s, sketch);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                     .count());
    cpu.push_back(thread_cpu_ms() - c0);
    if (!c.error.empty()) std::fprintf(stderr, "error: %s\n", c.error.c_str());
    iterations += c.stats.iterations;
    constraints += static_cast<double>(c.constraints.size());
  }
  std::sort(ms.begin(), ms.end());
  std::sort(cpu.begin(), cpu.end());
  const std::size_t i95 = std::min(ms.size() - 1, static_cast<std::size_t>(0.95 * ms.size()));
  Figures f;
  f.p50 = ms[ms.size() / 2];
  f.p95 = ms[i95];
  f.cpu_p50 = cpu[cpu.size() / 2];
  f.cpu_p95 = cpu[i95];
  f.mean_iterations = iterations / runs;
  f.mean_constraints = constraints / runs;
  return f;
}

// `jitter` (m) moves every existing end a little, so no two candidates are
// identical and the solver cannot merge them (a scaffold drawn without
// auto-correct); 0 gives the exact lattice of a corrected scaffold.
void bench_lines(int count, double jitter) {
  Sketch sketch;
  const double h = 0.3;
  std::mt19937 jitter_rng(3);
  std::uniform_real_distribution<double> shake(-jitter, jitter);
  auto moved = [&](const Vec3& p) {
    return Vec3(p + Vec3(shake(jitter_rng), shake(jitter_rng), shake(jitter_rng)));
  };
  int added = 0;
  for (int i = 0; i < 8 && added < count; ++i)
    for (int j = 0; j < 8 && added < count; ++j)
      for (int k = 0; k < 8 && added < count; ++k)
        for (int axis = 0; axis < 3 && added < count; ++axis) {
          const Vec3 p(i * h, j * h, k * h);
          add_line(sketch, moved(p), moved(p + h * Vec3::Unit(axis)));
          ++added;
        }
  ScaffoldSketchCorrector corrector{ScaffoldParams{}, ShapeParams{}};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.012);
  auto make = [&](int r) {
    const Vec3 a(h, h, 0), b(h, h, h);  // an edge next to existing ones
    const Vec3 na = a + Vec3(noise(rng), noise(rng), noise(rng));
    const Vec3 nb = b + Vec3(noise(rng), noise(rng), noise(rng));
    return line_stroke(static_cast<StrokeId>(r + 1000), na, nb, Layer::scaffold);
  };
  const Figures f = time_corrections(corrector, sketch, 400, make);
  const char* kind = jitter > 0 ? "jittered_lines" : "lines";
  std::printf("scaffold_line_%d_%s_p50 %.4f ms\n", count, kind, f.p50);
  std::printf("scaffold_line_%d_%s_p95 %.4f ms\n", count, kind, f.p95);
  std::printf("scaffold_line_%d_%s_cpu_p50 %.4f ms\n", count, kind, f.cpu_p50);
  std::printf("scaffold_line_%d_%s_cpu_p95 %.4f ms\n", count, kind, f.cpu_p95);
  std::printf("scaffold_line_%d_%s_irls_iterations %.2f mean\n", count, kind, f.mean_iterations);
  std::printf("scaffold_line_%d_%s_constraints %.1f mean\n", count, kind, f.mean_constraints);
}

void bench_curve(int keypoints) {
  Sketch sketch;
  // Keypoints on a planar spiral, 8 cm apart; each is the midpoint of a
  // 20 cm scaffold line across the spiral (tangent not snapped).
  auto spiral = [](double s) {
    const double r = 0.3 + 0.15 * s, angle = 2.2 * s;
    return Vec3(r * std::cos(angle), 1.0 + 0.05 * s, r * std::sin(angle));
  };
  std::vector<double> at;
  double s = 0;
  for (int j = 0; j < keypoints; ++j) {
    at.push_back(s);
    const double ds = 0.08 / (spiral(s + 1e-4) - spiral(s)).norm() * 1e-4;
    s += ds;
  }
  for (double sj : at) {
    const Vec3 q = spiral(sj);
    const Vec3 t = (spiral(sj + 1e-4) - q).normalized();
    const Vec3 n = t.cross(Vec3::UnitY()).normalized();
    add_line(sketch, q - 0.1 * n, q + 0.1 * n);
  }
  ScaffoldSketchCorrector corrector{ScaffoldParams{}, ShapeParams{}};
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.004);
  auto make = [&](int r) {
    Stroke st;
    st.id = static_cast<StrokeId>(r + 5000);
    st.layer = Layer::shape;
    const double s0 = at.front(), s1 = at.back();
    const int n = 200;
    for (int i = 0; i <= n; ++i) {
      Sample smp;
      smp.position = spiral(s0 + (s1 - s0) * i / n) + Vec3(noise(rng), noise(rng), noise(rng));
      smp.time = i * 0.01;
      st.samples.push_back(smp);
    }
    return st;
  };
  const Figures f = time_corrections(corrector, sketch, 200, make);
  std::printf("shape_curve_%d_keypoints_p50 %.4f ms\n", keypoints, f.p50);
  std::printf("shape_curve_%d_keypoints_p95 %.4f ms\n", keypoints, f.p95);
  std::printf("shape_curve_%d_keypoints_cpu_p50 %.4f ms\n", keypoints, f.cpu_p50);
  std::printf("shape_curve_%d_keypoints_cpu_p95 %.4f ms\n", keypoints, f.cpu_p95);
}

}  // namespace

int main() {
  bench_lines(45, 0.0);
  bench_lines(45, 1e-3);
  bench_lines(500, 0.0);
  bench_lines(500, 1e-3);
  bench_curve(3);
  bench_curve(6);
  bench_curve(10);
  return 0;
}
