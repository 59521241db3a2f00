// The metrics of a case holding one very long stroke (issue 17: a 10^6-sample
// stroke took 78 s and 496 MB in the metrics, its correction being fast; the
// Session now refuses strokes above max_stroke_samples = 10^5). A noisy helix
// of 10^4 and 10^5 samples is corrected by the freehand fit
// (the kernel's freehand_edit, as the freehand plugin does) and the case's
// metrics are computed once. Prints "name value unit" lines: the fit's and the
// metrics' CPU and wall time, the curve pieces and the peak memory.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>

#include "sketchlab/lab/metrics.hpp"
#include "sketchlab/session.hpp"

using namespace sketchlab;

namespace {

class Fit : public Corrector {
 public:
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction c;
    c.edit = freehand_edit(stroke, sketch, {});
    return c;
  }
};

// n samples over 4 turns of a 0.3 m helix drawn at 90 Hz, 1 mm jitter.
Stroke helix(int n, std::mt19937_64& rng) {
  std::normal_distribution<double> jitter(0.0, 0.001);
  Stroke s;
  s.id = 1;
  for (int i = 0; i < n; ++i) {
    const double u = double(i) / (n - 1);
    Sample smp;
    smp.position = Vec3(0.15 * std::cos(8 * M_PI * u) + jitter(rng), 0.15 * std::sin(8 * M_PI * u) + jitter(rng),
                        0.3 * u + jitter(rng));
    smp.time = i / 90.0;
    s.samples.push_back(smp);
  }
  return s;
}

double cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double wall_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

}  // namespace

int main() {
  std::mt19937_64 rng(17);
  for (const int n : {10000, 100000}) {
    ReplayResult result{"freehand", RecordingHeader{}, Session(Workspace{}, std::make_shared<Fit>(), nullptr), {}};
    double cpu = cpu_s(), wall = wall_s();
    result.steps.push_back(result.session.handle(Event{n / 90.0, StrokeEvent{helix(n, rng)}}));
    std::printf("fit_%d_cpu %.3f s\nfit_%d_wall %.3f s\n", n, cpu_s() - cpu, n, wall_s() - wall);
    if (!result.steps.back().error.empty()) {
      std::printf("error %s\n", result.steps.back().error.c_str());
      return 1;
    }
    int pieces = 0;
    for (const auto& [id, c] : result.session.sketch().network.curves()) pieces += c.curve.segment_count();
    cpu = cpu_s();
    wall = wall_s();
    const CaseMetrics m = compute_metrics(result);
    std::printf("metrics_%d_cpu %.3f s\nmetrics_%d_wall %.3f s\n", n, cpu_s() - cpu, n, wall_s() - wall);
    std::printf("metrics_%d_pieces %d count\nmetrics_%d_input_deviation_max %.6f m\n", n, pieces, n,
                m.values.at("input_deviation_max_m"));
    std::printf("peak_rss_after_%d %.0f MB\n", n, peak_rss_mb());
  }
  return 0;
}
