// Preprocessing + fitting latency of one finished stroke: a 300-sample noisy
// curved stroke (hook removal, line test, RDP, G1 poly-Bézier fit) and a
// straight one, each repeated 200 times. Prints "name value unit" lines.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "sketchlab/preprocess/preprocess.hpp"

using namespace sketchlab;

namespace {

struct Input {
  std::vector<Vec3> points;
  std::vector<double> times;
};

// 300 samples along a 3D path about 0.5 m long with 1 mm jitter: the curve
// drawn at 90 Hz (3.3 s), the line drawn quickly (1 s, so it is a line).
Input make_stroke(bool straight, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 0.001);
  Input in;
  for (int i = 0; i < 300; ++i) {
    const double s = i / 299.0;
    const Vec3 p = straight ? Vec3(0.5 * s, 0.1 * s, 0.05 * s)
                            : Vec3(0.15 * std::cos(4.0 * s), 0.15 * std::sin(4.0 * s),
                                   0.1 * std::sin(6.0 * s));
    in.points.push_back(p + Vec3(g(rng), g(rng), g(rng)));
    in.times.push_back(straight ? i / 300.0 : i / 90.0);
  }
  return in;
}

void run(const char* name, bool straight) {
  std::mt19937_64 rng(2024);
  const PreprocessParams params;
  constexpr int kRepeats = 200;
  std::vector<double> ms;
  std::size_t segments = 0;
  for (int r = 0; r < kRepeats; ++r) {
    const Input in = make_stroke(straight, rng);
    const auto t0 = std::chrono::steady_clock::now();
    const Preprocessed out = preprocess_stroke(in.points, in.times, params, 1.0);
    const auto t1 = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    segments += static_cast<std::size_t>(out.curve.segment_count());
  }
  std::sort(ms.begin(), ms.end());
  const double median = ms[ms.size() / 2];
  const double p95 = ms[static_cast<std::size_t>(std::ceil(0.95 * ms.size())) - 1];
  std::printf("%s_ms %.4f ms\n", name, median);
  std::printf("%s_p95_ms %.4f ms\n", name, p95);
  std::printf("%s_mean_segments %.2f segments\n", name,
              static_cast<double>(segments) / kRepeats);
}

}  // namespace

int main() {
  run("fit_300_samples", false);
  run("fit_300_samples_line", true);
  return 0;
}
