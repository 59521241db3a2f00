#include "cassie_corrector.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "candidates.hpp"
#include "line_beautify.hpp"
#include "on_surface.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "subset_search.hpp"

namespace sketchlab::cassie {
namespace {

ConstraintKind kind_of(TargetKind k) {
  switch (k) {
    case TargetKind::curve: return ConstraintKind::intersection;
    case TargetKind::node: return ConstraintKind::intersection;
    case TargetKind::grid: return ConstraintKind::grid_point;
    case TargetKind::mirror: return ConstraintKind::mirror_plane;
    case TargetKind::closure: return ConstraintKind::closure;
  }
  return ConstraintKind::intersection;
}

double line_angle(const Vec3& a, const Vec3& b) {
  const double c = std::clamp(std::abs(a.normalized().dot(b.normalized())), 0.0, 1.0);
  return std::acos(c);
}

// Where an enforced candidate sits on the new curve.
struct Placed {
  int candidate = 0;
  double t = 0.0;  // parameter on the new curve
};

}  // namespace

Correction correct_stroke(const Stroke& stroke, const Sketch& sketch, const CassieParams& params) {
  const auto start = std::chrono::steady_clock::now();
  Correction out;
  const double scale = stroke.workspace_scale > 0 ? stroke.workspace_scale : 1.0;
  Preprocessed pre;
  try {
    pre = preprocess_stroke(stroke, params.preprocess);  // thesis §3.2.2
  } catch (const std::exception& e) {
    out.error = e.what();
    return out;
  }
  const Thresholds th = thresholds(params, scale);
  const Workspace& ws = sketch.workspace;
  const bool use_mirror = params.mirror != MirrorMode::off && ws.mirror_enabled &&
                          ws.mirror_normal.norm() > 0;
  const CurveId new_id = sketch.network.next_curve_id();
  const ConstraintRef stroke_ref{ConstraintRef::Kind::stroke, stroke.id, 0.0};

  std::vector<Candidate> cands;
  std::vector<bool> enforced;
  std::vector<Placed> placed;
  Curve result;
  std::vector<Constraint> soft;

  if (pre.is_line) {
    // Appendix A.
    const Vec3 a0 = pre.curve.control_points.front(), b0 = pre.curve.control_points.back();
    cands = detect_candidates(pre.curve, sketch, params, th, use_mirror, false);
    LineResult lr = beautify_line(a0, b0, cands, th.proximity, params.angle, params.line_axis_snap);
    if (!((lr.b - lr.a).norm() > 1e-9) || !lr.a.allFinite() || !lr.b.allFinite()) {
      lr = LineResult{a0, b0, {}, -1};
    }
    result = make_line(lr.a, lr.b);
    enforced.assign(cands.size(), false);
    for (int i : lr.enforced) {
      enforced[i] = true;
      placed.push_back({i, closest_point(result, cands[i].target).t});
    }
    Constraint straight{ConstraintKind::straight, {stroke_ref}, (lr.b - lr.a).normalized(), 1.0,
                        false, true, 0.0};
    soft.push_back(straight);
    if (lr.axis >= 0) {
      Constraint axis{ConstraintKind::parallel,
                      {stroke_ref, {ConstraintRef::Kind::axis, static_cast<std::uint64_t>(lr.axis), 0.0}},
                      Vec3::Unit(lr.axis), 1.0, false, true, 0.0};
      soft.push_back(axis);
    }
    out.stats.subsets_tried = 0;
    out.stats.extra["solves"] = 0;
  } else {
    const auto t_detect = std::chrono::steady_clock::now();
    cands = detect_candidates(pre.curve, sketch, params, th, use_mirror, true);
    out.stats.extra["detect_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_detect).count();
    out.stats.extra["control_points"] = static_cast<double>(pre.curve.control_points.size());
    SoftTerms st;
    st.planarity_weight = params.planarity_weight;
    st.tangent_weight = params.tangent_weight;
    st.min_edge = 1e-6 * th.delta;
    PlaneFit plane;
    if (params.planarity) {
      plane = fit_plane(pre.curve.control_points, th.proximity, params.angle);
      if (plane.planar) st.plane_normal = plane.normal;
    }
    const SearchResult sr = greedy_search(pre.curve, cands, st, params.lambda, th.reuse);
    enforced.assign(cands.size(), false);
    if (sr.best.feasible) {
      result = sr.best.bound.curve;
      result.control_points = sr.best.solve.control_points;
      for (std::size_t s = 0; s < sr.best.subset.size(); ++s) {
        const int i = sr.best.subset[s];
        enforced[i] = true;
        if (cands[i].kind == TargetKind::closure) continue;
        placed.push_back({i, sr.best.bound.control_index[s] / 3.0});
      }
      if (std::any_of(sr.best.subset.begin(), sr.best.subset.end(),
                      [&](int i) { return cands[i].kind == TargetKind::closure; })) {
        result.control_points.back() = result.control_points.front();
        result.closed = true;
      }
    } else {
      result = pre.curve;  // singular system even without constraints: keep the fit
    }
    out.stats.subsets_tried = sr.subsets_tried;
    out.stats.iterations = sr.levels;
    out.stats.extra["solves"] = sr.subsets_tried;
    out.stats.extra["pruned_subsets"] = sr.pruned;
    out.stats.extra["fidelity"] = sr.best.feasible ? sr.best.solve.fidelity : 0.0;
    out.stats.extra["energy"] = sr.best.feasible ? sr.best.energy : 0.0;
    if (params.planarity && plane.normal.allFinite()) {
      Constraint pc{plane.axis >= 0 ? ConstraintKind::axis_plane : ConstraintKind::planar,
                    {stroke_ref},
                    plane.normal,
                    params.planarity_weight,
                    false,
                    plane.planar,
                    plane_residual(result.control_points, plane.normal)};
      if (plane.axis >= 0)
        pc.references.push_back({ConstraintRef::Kind::axis, static_cast<std::uint64_t>(plane.axis), 0.0});
      soft.push_back(pc);
    }
    // Tangent alignment (eq. 3.8): residual = angle left at the intersection.
    for (std::size_t i = 0; i < cands.size(); ++i) {
      if (!cands[i].tangent) continue;
      double t = cands[i].t_stroke;
      for (const Placed& p : placed)
        if (p.candidate == static_cast<int>(i)) t = p.t;
      Constraint tc{ConstraintKind::tangent,
                    {stroke_ref, {ConstraintRef::Kind::curve, cands[i].curve, cands[i].t_curve}},
                    *cands[i].tangent, params.tangent_weight, false, static_cast<bool>(enforced[i]),
                    line_angle(tangent(result, std::min(t, result.t_max())), *cands[i].tangent)};
      soft.push_back(tc);
    }
  }

  // On-surface projection as a post-process (thesis §3.3.5).
  if (params.on_surface && !sketch.network.patches().empty() && result.kind == CurveKind::bezier) {
    std::vector<CurveId> hits;
    for (const Placed& p : placed)
      if (cands[p.candidate].kind == TargetKind::curve || cands[p.candidate].kind == TargetKind::node)
        hits.push_back(cands[p.candidate].curve);
    const auto proj =
        project_on_surface(sketch.network, result.control_points, tangent(result, 0.0),
                           tangent(result, result.t_max()), hits, th.surface, params.angle);
    if (proj) {
      const std::vector<Vec3> before = result.control_points;
      result.control_points = proj->control_points;
      for (const Placed& p : placed)  // intersections stay exact
        result.control_points[static_cast<std::size_t>(std::lround(3 * p.t))] = cands[p.candidate].target;
      if (result.closed) result.control_points.back() = result.control_points.front();
      double moved = 0.0;
      for (std::size_t i = 0; i < before.size(); ++i)
        moved = std::max(moved, (before[i] - result.control_points[i]).norm());
      soft.push_back({ConstraintKind::on_surface, {stroke_ref}, Vec3::Zero(), 1.0, false, true, 0.0});
      out.stats.extra["on_surface_patch"] = static_cast<double>(proj->patch);
      out.stats.extra["on_surface_moved"] = moved;
    }
  }

  // The edit: the curve, its mirrored copy, and the nodes.
  NetworkCurve nc;
  nc.id = new_id;
  nc.curve = result;
  nc.layer = stroke.layer == Layer::automatic ? Layer::free : stroke.layer;
  nc.source_stroke = stroke.id;
  nc.keypoints = default_keypoints(result);
  out.edit.curves_added.push_back(nc);
  bool copy = false;
  if (use_mirror && params.mirror == MirrorMode::workspace) {
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
  std::vector<Node> replaced;
  for (const Placed& p : placed) {
    const Candidate& c = cands[p.candidate];
    const double t = clamp_t(p.t, result);
    const bool on_plane = c.kind == TargetKind::mirror;
    if (c.kind == TargetKind::node) {
      auto it = std::find_if(replaced.begin(), replaced.end(), [&](const Node& n) { return n.id == c.node; });
      if (it == replaced.end()) {
        replaced.push_back(sketch.network.nodes().at(c.node));
        it = replaced.end() - 1;
      }
      it->incidences.push_back({new_id, t});
      if (copy && (mirror_point(ws, c.target) - c.target).norm() < 1e-9) it->incidences.push_back({new_id + 1, t});
      continue;
    }
    Node n;
    n.id = next_node++;
    n.position = c.target;
    n.incidences.push_back({new_id, t});
    if (c.kind == TargetKind::curve)
      n.incidences.push_back({c.curve, clamp_t(c.t_curve, sketch.network.curves().at(c.curve).curve)});
    if (copy && on_plane) n.incidences.push_back({new_id + 1, t});
    out.edit.nodes_added.push_back(n);
  }
  // The copy meets the mirror images of what the stroke met (mirrored twins
  // of existing curves), where such curves exist.
  if (copy) {
    for (const Placed& p : placed) {
      const Candidate& c = cands[p.candidate];
      if (c.kind != TargetKind::curve && c.kind != TargetKind::node) continue;
      const Vec3 q = mirror_point(ws, c.target);
      if ((q - c.target).norm() < 1e-9) continue;
      Node n;
      n.id = next_node++;
      n.position = q;
      n.incidences.push_back({new_id + 1, clamp_t(p.t, result)});
      for (const CurveHit& h : sketch.network.curves_near(q, 1e-7))
        if (std::none_of(n.incidences.begin(), n.incidences.end(),
                         [&](const NodeIncidence& i) { return i.curve == h.curve; }))
          n.incidences.push_back({h.curve, h.t});
      if (n.incidences.size() > 1) out.edit.nodes_added.push_back(n);
      else --next_node;
    }
  }
  out.edit.nodes_replaced = std::move(replaced);

  // Every candidate, enforced or rejected, with its final distance.
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const Candidate& c = cands[i];
    Constraint k;
    k.kind = kind_of(c.kind);
    k.references.push_back({ConstraintRef::Kind::stroke, stroke.id, c.t_stroke});
    switch (c.kind) {
      case TargetKind::curve: k.references.push_back({ConstraintRef::Kind::curve, c.curve, c.t_curve}); break;
      case TargetKind::node: k.references.push_back({ConstraintRef::Kind::node, c.node, 0.0}); break;
      case TargetKind::grid: k.references.push_back({ConstraintRef::Kind::grid, 0, 0.0}); break;
      case TargetKind::mirror: k.references.push_back({ConstraintRef::Kind::mirror, 0, 0.0}); break;
      case TargetKind::closure: k.references.push_back({ConstraintRef::Kind::stroke, stroke.id, 1.0}); break;
    }
    k.target = c.kind == TargetKind::closure ? Vec3::Zero() : c.target;
    k.weight = c.weight;
    k.hard = true;
    k.enforced = enforced[i];
    if (c.kind == TargetKind::closure)
      k.residual = (result.control_points.back() - result.control_points.front()).norm();
    else
      k.residual = closest_point(result, c.target).distance;
    out.constraints.push_back(k);
  }
  for (Constraint& c : soft) out.constraints.push_back(std::move(c));

  int rejected = 0;
  for (bool e : enforced) rejected += !e;
  out.stats.extra["candidates"] = static_cast<double>(cands.size());
  out.stats.extra["rejected"] = rejected;
  out.stats.extra["time_ms"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace sketchlab::cassie
