#include "cassie_edit.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/network_curve.hpp"

namespace sketchlab::cassie {
namespace {

ConstraintKind kind_of(TargetKind k) {
  switch (k) {
    case TargetKind::curve:
    case TargetKind::node: return ConstraintKind::intersection;
    case TargetKind::grid: return ConstraintKind::grid_point;
    case TargetKind::mirror: return ConstraintKind::mirror_plane;
  }
  return ConstraintKind::intersection;
}

ConstraintRef reference_of(const Candidate& c) {
  switch (c.kind) {
    case TargetKind::curve: return {ConstraintRef::Kind::curve, c.curve, c.t_curve};
    case TargetKind::node: return {ConstraintRef::Kind::node, c.node, 0.0};
    case TargetKind::grid: return {ConstraintRef::Kind::grid, 0, 0.0};
    case TargetKind::mirror: return {ConstraintRef::Kind::mirror, 0, 0.0};
  }
  return {};
}

}  // namespace

Correction build_correction(const Stroke& stroke, const Sketch& sketch, const CorrectedStroke& cs,
                            bool copy_wanted) {
  Correction out;
  const Workspace& ws = sketch.workspace;
  const Curve& result = cs.curve;
  const CurveId new_id = sketch.network.next_curve_id();
  const NetworkCurve nc = make_network_curve(new_id, result, curve_layer(stroke.layer), stroke.id);
  out.edit.curves_added.push_back(nc);
  bool copy = false;
  if (copy_wanted && cs.mirror_copy) {
    NetworkCurve mc = nc;
    mc.id = new_id + 1;
    for (Vec3& p : mc.curve.control_points) p = mirror_point(ws, p);
    if (mc.curve.closed) mc.curve.control_points.back() = mc.curve.control_points.front();
    double apart = 0.0;
    for (std::size_t i = 0; i < mc.curve.control_points.size(); ++i)
      apart = std::max(apart, (mc.curve.control_points[i] - result.control_points[i]).norm());
    if (apart > 1e-9) {  // a stroke lying in the plane is its own mirror
      mc.keypoints = default_keypoints(mc.curve);
      out.edit.curves_added.push_back(mc);
      copy = true;
    }
  }

  NodeId next_node = sketch.network.next_node_id();
  auto clamp_t = [](double t, const Curve& c) { return std::clamp(t, 0.0, c.t_max()); };
  auto on_plane = [&](const Vec3& p) { return (mirror_point(ws, p) - p).norm() < 1e-9; };
  std::vector<Node> replaced;
  for (const Placement& p : cs.placed) {
    const Candidate& c = cs.constraints[p.constraint];
    const double t = clamp_t(p.t, result);
    if (c.kind == TargetKind::node) {
      auto it = std::find_if(replaced.begin(), replaced.end(), [&](const Node& n) { return n.id == c.node; });
      if (it == replaced.end()) {
        replaced.push_back(sketch.network.nodes().at(c.node));
        it = replaced.end() - 1;
      }
      it->incidences.push_back({new_id, t});
      if (copy && on_plane(c.target)) it->incidences.push_back({new_id + 1, t});
      continue;
    }
    Node n;
    n.id = next_node++;
    n.position = evaluate(result, t);
    n.incidences.push_back({new_id, t});
    if (c.kind == TargetKind::curve)
      n.incidences.push_back({c.curve, clamp_t(c.t_curve, sketch.network.curves().at(c.curve).curve)});
    if (copy && c.kind == TargetKind::mirror) n.incidences.push_back({new_id + 1, t});
    out.edit.nodes_added.push_back(n);
  }
  // The copy meets the mirror images of what the stroke met, where such
  // curves exist (mirrored twins of existing curves).
  if (copy) {
    for (const Placement& p : cs.placed) {
      const Candidate& c = cs.constraints[p.constraint];
      if (!is_intersection(c)) continue;
      const Vec3 q = mirror_point(ws, c.target);
      if ((q - c.target).norm() < 1e-9) continue;
      Node n;
      n.id = next_node;
      n.position = q;
      n.incidences.push_back({new_id + 1, clamp_t(p.t, result)});
      for (const CurveHit& h : sketch.network.curves_near(q, 1e-7))
        if (std::none_of(n.incidences.begin(), n.incidences.end(),
                         [&](const NodeIncidence& i) { return i.curve == h.curve; }))
          n.incidences.push_back({h.curve, h.t});
      if (n.incidences.size() > 1) {
        out.edit.nodes_added.push_back(n);
        ++next_node;
      }
    }
  }
  out.edit.nodes_replaced = std::move(replaced);

  // Item 21: every constraint, enforced ("applied") or not ("rejected").
  const ConstraintRef stroke_ref{ConstraintRef::Kind::stroke, stroke.id, 0.0};
  for (std::size_t i = 0; i < cs.constraints.size(); ++i) {
    const Candidate& c = cs.constraints[i];
    Constraint k;
    k.kind = kind_of(c.kind);
    k.references = {{ConstraintRef::Kind::stroke, stroke.id, c.t_stroke}, reference_of(c)};
    k.target = c.target;
    k.weight = c.weight;
    k.hard = true;
    k.enforced = cs.enforced[i];
    k.residual = closest_point(result, c.target).distance;
    out.constraints.push_back(k);
  }
  if (cs.closure_considered) {
    Constraint k;
    k.kind = ConstraintKind::closure;
    k.references = {stroke_ref, {ConstraintRef::Kind::stroke, stroke.id, 1.0}};
    k.weight = 0.0;  // item 10: no weight, never rejected
    k.hard = true;
    k.enforced = cs.closure_enforced;
    k.residual = (result.control_points.back() - result.control_points.front()).norm();
    out.constraints.push_back(k);
  }
  for (const Constraint& c : cs.soft) out.constraints.push_back(c);
  int rejected = 0;
  for (bool e : cs.enforced) rejected += !e;
  out.stats.extra["candidates"] = static_cast<double>(cs.constraints.size());
  out.stats.extra["rejected"] = rejected;
  return out;
}

}  // namespace sketchlab::cassie
