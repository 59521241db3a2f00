#include "input_density.hpp"

#include <cmath>

namespace sketchlab::cassie {

Stroke densify_stroke(const Stroke& stroke, double max_gap) {
  if (!(max_gap > 0) || stroke.samples.size() < 2) return stroke;
  Stroke out = stroke;
  out.samples.clear();
  for (std::size_t i = 0; i < stroke.samples.size(); ++i) {
    if (i > 0) {
      const Sample& a = stroke.samples[i - 1];
      const Sample& b = stroke.samples[i];
      const int n = static_cast<int>(std::ceil((b.position - a.position).norm() / max_gap));
      for (int k = 1; k < n; ++k) {
        const double u = static_cast<double>(k) / n;
        Sample s;
        s.position = a.position + u * (b.position - a.position);
        s.time = a.time + u * (b.time - a.time);
        s.pressure = a.pressure + u * (b.pressure - a.pressure);
        s.orientation = a.orientation.slerp(u, b.orientation);
        out.samples.push_back(s);
      }
    }
    out.samples.push_back(stroke.samples[i]);
  }
  return out;
}

}  // namespace sketchlab::cassie
