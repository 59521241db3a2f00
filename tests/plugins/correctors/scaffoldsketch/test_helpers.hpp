#pragma once
// Small builders shared by the ScaffoldSketch tests.
#include <vector>

#include "sketchlab/network_curve.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::scaffoldsketch::test {

// A stroke of n+1 samples from a to b (straight), 10 ms apart.
inline Stroke straight_stroke(StrokeId id, const Vec3& a, const Vec3& b, Layer layer, int n = 30) {
  Stroke s;
  s.id = id;
  s.layer = layer;
  for (int i = 0; i <= n; ++i) {
    Sample smp;
    smp.position = a + (b - a) * (static_cast<double>(i) / n);
    smp.time = 0.01 * i;
    s.samples.push_back(smp);
  }
  return s;
}

inline Stroke polyline_stroke(StrokeId id, const std::vector<Vec3>& points, Layer layer) {
  Stroke s;
  s.id = id;
  s.layer = layer;
  for (std::size_t i = 0; i < points.size(); ++i) {
    Sample smp;
    smp.position = points[i];
    smp.time = 0.01 * static_cast<double>(i);
    s.samples.push_back(smp);
  }
  return s;
}

// Adds a scaffold line a-b (with default keypoints) to the sketch; returns its id.
inline CurveId add_scaffold_line(Sketch& sketch, const Vec3& a, const Vec3& b) {
  const NetworkCurve c = make_network_curve(sketch.network.next_curve_id(), make_line(a, b), Layer::scaffold);
  Edit e;
  e.curves_added.push_back(c);
  sketch.network.apply(e);
  return c.id;
}

}  // namespace sketchlab::scaffoldsketch::test
