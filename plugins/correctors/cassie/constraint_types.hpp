#pragma once
// The position constraints a stroke collects while it is drawn (CASSIE app,
// `InputStroke.AddConstraint`; CHI §4.4 "Intersections").
#include <optional>

#include "sketchlab/curve.hpp"
#include "sketchlab/network_types.hpp"

namespace sketchlab::cassie {

enum class TargetKind {
  curve,   // a point on an existing curve
  node,    // an existing node (end node of the crossed piece, item 8)
  grid,    // a grid point (item 19)
  mirror,  // a point on the mirror plane (item 18)
};

struct Candidate {
  TargetKind kind = TargetKind::curve;
  Vec3 target = Vec3::Zero();  // where the stroke must pass (m)
  double time = 0.0;           // s, when the brush detected it
  Vec3 brush = Vec3::Zero();   // brush centre then
  CurveId curve = 0;           // curve and node kinds: the curve met
  double t_curve = 0.0;        // its parameter at the target
  bool at_curve_end = false;   // t_curve is exactly 0 or t_max: not corrected (item 8)
  NodeId node = 0;             // node kind
  // On the new stroke (place_on_stroke):
  double t_stroke = 0.0;       // parameter of the closest point to the target
  double distance = 0.0;       // m, stroke to target before solving
  double weight = 1.0;         // CHI eq. 3 weight with the app's bonuses (item 11)
  std::optional<Vec3> tangent;  // unit direction the stroke should take at the target (item 14)
};

// An intersection with the network (curve or node kind).
inline bool is_intersection(const Candidate& c) {
  return c.kind == TargetKind::curve || c.kind == TargetKind::node;
}

}  // namespace sketchlab::cassie
