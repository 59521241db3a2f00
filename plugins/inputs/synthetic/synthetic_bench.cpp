// Synthetic input figures: generation time per session, and how far the
// freehand baseline (kernel preprocessing, CASSIE defaults) lands from the
// ground truth at the default noise. Prints `name value unit` lines.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>

#include "session_synthesis.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/preprocess/preprocess.hpp"

using namespace sketchlab;
using namespace sketchlab::synthetic;

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}  // namespace

int main() {
  for (const std::string model : {"cube", "rounded_box", "mug", "chair", "lamp"}) {
    for (Modality modality : {Modality::vr, Modality::tablet}) {
      SynthesisParams p;
      p.model = model;
      p.modality = modality;
      const int runs = 5;
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < runs; ++i) synthesize_session(p);
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / runs;
      std::cout << "synthetic_" << model << (modality == Modality::vr ? "_vr" : "_tablet")
                << "_generate " << ms << " ms\n";
    }
    std::vector<double> mean_dev, max_dev, sample_dev;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      SynthesisParams p;
      p.model = model;
      p.seed = seed;
      std::map<StrokeId, Stroke> strokes;
      for (const Event& e : synthesize_session(p).events) {
        if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) strokes[s->stroke.id] = s->stroke;
        const auto* r = std::get_if<ReferenceEvent>(&e.payload);
        if (!r) continue;
        const Stroke& stroke = strokes.at(r->stroke);
        for (const Sample& s : stroke.samples) sample_dev.push_back(closest_point(r->curve, s.position).distance);
        const Curve fit = preprocess_stroke(stroke).curve;
        double mx = 0.0, sum = 0.0;
        const auto pts = sample_with_spacing(fit, 0.002);
        for (const Vec3& q : pts) {
          const double d = closest_point(r->curve, q).distance;
          mx = std::max(mx, d);
          sum += d;
        }
        mean_dev.push_back(sum / static_cast<double>(pts.size()));
        max_dev.push_back(mx);
      }
    }
    std::cout << "synthetic_" << model << "_vr_sample_deviation_median " << 1000 * median(sample_dev) << " mm\n"
              << "synthetic_" << model << "_freehand_mean_deviation_median " << 1000 * median(mean_dev) << " mm\n"
              << "synthetic_" << model << "_freehand_max_deviation_median " << 1000 * median(max_dev) << " mm\n";
  }
}
