#include "target_correction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"

namespace sketchlab::cassie {

namespace {

// Parameter reached from t after a signed arclength s along the curve
// (clamped at its ends): a walk along short chords, so the cost depends on
// |s|, not on the curve's length.
double parameter_at_offset(const Curve& c, double t, double s) {
  constexpr double step = 1.0 / 64.0;
  const double dir = s < 0 ? -1.0 : 1.0, goal = std::abs(s);
  double u = t, walked = 0.0;
  Vec3 prev = evaluate(c, t);
  while (walked < goal) {
    const double next = std::clamp(u + dir * step, 0.0, c.t_max());
    if (next == u) break;
    const Vec3 q = evaluate(c, next);
    const double l = (q - prev).norm();
    if (walked + l >= goal) return u + (next - u) * (l > 0 ? (goal - walked) / l : 1.0);
    walked += l;
    u = next;
    prev = q;
  }
  return u;
}

}  // namespace

void correct_targets(std::vector<Candidate>& cands, const Curve& fitted, const Network& net, double span,
                     int points, bool keep_detected) {
  if (points <= 0 || !(span > 0)) return;
  for (Candidate& c : cands) {
    if (c.kind != TargetKind::curve || c.at_curve_end) continue;
    const Curve& old = net.curves().at(c.curve).curve;
    const double t0 = c.t_curve;
    double best = keep_detected ? closest_point(fitted, c.target).distance : std::numeric_limits<double>::infinity();
    for (int i = 0; i < points; ++i) {
      const double u = points > 1 ? -1.0 + 2.0 * i / (points - 1) : 0.0;
      const double t = parameter_at_offset(old, t0, u * span);
      const Vec3 q = evaluate(old, t);
      const double d = closest_point(fitted, q).distance;
      if (d < best) {
        best = d;
        c.target = q;
        c.t_curve = t;
      }
    }
  }
}

void place_on_stroke(std::vector<Candidate>& cands, const Curve& curve) {
  for (Candidate& c : cands) {
    const ClosestPoint cp = closest_point(curve, c.target);
    c.t_stroke = cp.t;
    c.distance = cp.distance;
  }
}

void assign_weights(std::vector<Candidate>& cands, const Curve& curve, const Network& net,
                    const Workspace& ws, const CassieParams& p, const Thresholds& th) {
  const Vec3 end0 = curve.control_points.front(), end1 = curve.control_points.back();
  const double cos_theta = std::cos(p.angle);
  for (Candidate& c : cands) {
    switch (c.kind) {
      case TargetKind::node: c.weight = p.weight_node; break;
      case TargetKind::curve: c.weight = p.weight_curve; break;
      case TargetKind::grid:
      case TargetKind::mirror: c.weight = p.weight_grid; break;
    }
    const Vec3 on = evaluate(curve, c.t_stroke);
    if (std::min((on - end0).norm(), (on - end1).norm()) <= th.delta) c.weight = std::max(c.weight, p.weight_endpoint);
    c.tangent.reset();
    if (!p.tangents) continue;
    const Vec3 ts = tangent(curve, c.t_stroke);
    if (is_intersection(c)) {
      const Vec3 to = tangent(net.curves().at(c.curve).curve, c.t_curve);
      const double cs = ts.dot(to);
      // Item 11. At a node, CASSIE's logs (raw_data alignTangents) align
      // where our parametric tangents point opposite ways (README).
      const bool aligned = c.kind != TargetKind::node ? std::abs(cs) > cos_theta
                           : p.node_alignment == NodeAlignment::opposite ? cs < -cos_theta
                                                                         : cs > cos_theta;
      if (aligned) c.tangent = cs >= 0 ? to : Vec3(-to);
    } else if (c.kind == TargetKind::mirror && ws.mirror_normal.norm() > 0) {
      const Vec3 n = ws.mirror_normal.normalized();
      const double cs = ts.dot(n);
      if (std::abs(cs) > cos_theta) c.tangent = cs >= 0 ? n : Vec3(-n);
    }
    if (c.tangent) c.weight += p.tangent_bonus;
  }
}

}  // namespace sketchlab::cassie
