#pragma once
// Small builders for synthetic strokes and sketches.
#include <cmath>
#include <functional>
#include <vector>

#include "sketchlab/network_curve.hpp"
#include "sketchlab/plugin/corrector.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::test {

// n samples of f(u), u in [0,1], over `duration` seconds.
inline Stroke make_stroke(StrokeId id, int n, const std::function<Vec3(double)>& f,
                          double duration = 1.0) {
  Stroke s;
  s.id = id;
  for (int i = 0; i < n; ++i) {
    const double u = n > 1 ? double(i) / (n - 1) : 0.0;
    Sample smp;
    smp.position = f(u);
    smp.time = u * duration;
    s.samples.push_back(smp);
  }
  return s;
}

inline void add_curve(Sketch& sketch, const Curve& c) {
  Edit e;
  e.curves_added.push_back(make_network_curve(sketch.network.next_curve_id(), c, Layer::free));
  sketch.network.apply(e);
}

inline void apply(Sketch& sketch, const Edit& e) { sketch.network.apply(e); }

// Adds a node at `position` with these incidences; returns its id.
inline NodeId add_node(Sketch& sketch, const Vec3& position, std::vector<NodeIncidence> incidences) {
  Edit e;
  Node n;
  n.id = sketch.network.next_node_id();
  n.position = position;
  n.incidences = std::move(incidences);
  e.nodes_added.push_back(n);
  sketch.network.apply(e);
  return n.id;
}

inline bool all_finite(const Curve& c) {
  for (const Vec3& p : c.control_points)
    if (!p.allFinite()) return false;
  return true;
}

// The correction's first constraint of kind k, or nullptr.
inline const Constraint* find_kind(const Correction& c, ConstraintKind k) {
  for (const Constraint& x : c.constraints)
    if (x.kind == k) return &x;
  return nullptr;
}

// A straight poly-Bézier of k segments from a to b (smooth joints).
inline Curve straight(const Vec3& a, const Vec3& b, int k) {
  Curve c;
  c.kind = CurveKind::bezier;
  for (int i = 0; i <= 3 * k; ++i) c.control_points.push_back(a + (b - a) * (i / (3.0 * k)));
  c.sharp.assign(k + 1, false);
  return c;
}

}  // namespace sketchlab::test
