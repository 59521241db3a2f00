#include "cassie_corrector.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "anchor_binding.hpp"
#include "brush_detection.hpp"
#include "cassie_edit.hpp"
#include "constraint_oracle.hpp"
#include "input_density.hpp"
#include "line_beautify.hpp"
#include "mirror_plane.hpp"
#include "node_snap.hpp"
#include "on_surface.hpp"
#include "plane_fit.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "stroke_ends.hpp"
#include "subset_search.hpp"
#include "target_correction.hpp"

namespace sketchlab::cassie {
namespace {

double line_angle(const Vec3& a, const Vec3& b) {
  const double c = std::clamp(std::abs(a.normalized().dot(b.normalized())), 0.0, 1.0);
  return std::acos(c);
}

// Everything one stage hands to the next.
struct Context {
  const Stroke& stroke;
  const Sketch& sketch;
  const CassieParams& params;
  Thresholds th;
  bool use_mirror = false;
  ConstraintRef stroke_ref;
  CorrectionStats stats;
  const std::vector<Vec3>* applied = nullptr;  // the reference's decision (constraint_oracle.hpp), or none
};

// With an oracle and oracle_positions, the matched constraints at the
// reference's own target positions.
void oracle_positions(const Context& cx, std::vector<Candidate>& cands) {
  if (cx.applied && cx.params.oracle_positions)
    take_oracle_positions(cands, *cx.applied, cx.th.oracle, cx.sketch.network);
}

// Which constraints the reference applied, counted in the statistics; all
// true without an oracle.
std::vector<bool> oracle_choice(Context& cx, const std::vector<Candidate>& cands) {
  if (!cx.applied) return std::vector<bool>(cands.size(), true);
  std::vector<bool> matched = oracle_matches(cands, *cx.applied, cx.th.oracle);
  cx.stats.extra["oracle"] = 1;
  cx.stats.extra["oracle_matched"] = static_cast<double>(std::count(matched.begin(), matched.end(), true));
  return matched;
}

std::vector<Candidate> detect(Context& cx) {
  DetectionStats ds;
  auto cands = detect_constraints(cx.stroke, cx.sketch, cx.th, cx.params.brush_step, cx.use_mirror, ds);
  cx.stats.extra["brush_queries"] = ds.brush_queries;
  cx.stats.extra["curve_contacts"] = ds.curve_contacts;
  return cands;
}

// Item 5: a poly-Bézier with too many segments or a degenerate control
// polygon is not constrained.
bool solver_skipped(const Curve& c, const CassieParams& p, double delta) {
  if (p.max_solver_segments > 0 && c.segment_count() > p.max_solver_segments) return true;
  for (std::size_t i = 0; i + 1 < c.control_points.size(); ++i)
    if (!c.control_points[i].allFinite() || !((c.control_points[i + 1] - c.control_points[i]).norm() > 1e-9 * delta))
      return true;
  return false;
}

// Item 17 and Appendix A: lines.
CorrectedStroke correct_line(Context& cx, const Curve& line) {
  CorrectedStroke cs;
  cs.constraints = detect(cx);
  oracle_positions(cx, cs.constraints);
  const Vec3 a0 = line.control_points.front(), b0 = line.control_points.back();
  // With an oracle, the line's rules see only the constraints it applied.
  const std::vector<bool> allowed = oracle_choice(cx, cs.constraints);
  std::vector<Candidate> offered;
  std::vector<int> index;
  for (std::size_t i = 0; i < cs.constraints.size(); ++i)
    if (allowed[i]) offered.push_back(cs.constraints[i]), index.push_back(static_cast<int>(i));
  LineResult lr = beautify_line(a0, b0, offered, cx.th.proximity, cx.th.line_keep, cx.params.angle,
                                cx.params.line_axis_snap);
  for (int& i : lr.enforced) i = index[static_cast<std::size_t>(i)];
  if (!((lr.b - lr.a).norm() > 1e-9) || !lr.a.allFinite() || !lr.b.allFinite()) lr = LineResult{a0, b0, {}, {}, -1};
  cs.curve = make_line(lr.a, lr.b);
  place_on_stroke(cs.constraints, cs.curve);
  cs.enforced.assign(cs.constraints.size(), false);
  for (int i : lr.enforced) {
    cs.enforced[i] = true;
    cs.placed.push_back({i, cs.constraints[i].t_stroke});
  }
  cs.soft.push_back({ConstraintKind::straight, {cx.stroke_ref}, (lr.b - lr.a).normalized(), 1.0, false, true, 0.0});
  if (lr.axis >= 0)
    cs.soft.push_back({ConstraintKind::parallel,
                       {cx.stroke_ref, {ConstraintRef::Kind::axis, static_cast<std::uint64_t>(lr.axis), 0.0}},
                       Vec3::Unit(lr.axis), 1.0, false, true, 0.0});
  return cs;
}

// Items 13–14: the search's energy settings.
SearchSettings search_settings(const CassieParams& p, const Thresholds& th) {
  SearchSettings st;
  st.lambda = p.lambda;
  st.fidelity = p.fidelity == FidelityNorm::cassie_app ? FidelityScale{p.position_scale * th.delta, 0.5} : FidelityScale{};
  st.connectivity_over_detected = p.connectivity == ConnectivityTotal::thesis;
  st.tangent_weight = p.tangent_weight;
  st.planarity_weight = p.planarity ? p.planarity_weight : 0.0;
  st.planar_distance = th.proximity;
  st.planar_test_snapped = p.planarity_test == PlanarityTest::snapped;
  st.axis_angle = p.angle;
  st.min_edge = 1e-6 * th.delta;
  return st;
}

// Item 10: closure, a hard constraint in every subset, unless both ends are
// bound; with an end-tangent term when the end tangents agree.
void set_closure(const Curve& fitted, const Binding& binding, double closure_distance, SearchSettings& st) {
  const int last = static_cast<int>(binding.curve.control_points.size()) - 1;
  bool start_bound = false, end_bound = false;
  for (int a : binding.anchor) start_bound |= a == 0, end_bound |= a == last;
  const Vec3 e0 = fitted.control_points.front(), e1 = fitted.control_points.back();
  if (fitted.segment_count() > 1 && (e0 - e1).norm() <= closure_distance && !(start_bound && end_bound)) {
    st.closure = true;
    const Vec3 d0 = tangent(fitted, 0.0), d1 = tangent(fitted, fitted.t_max());
    if (std::abs(d0.dot(d1)) > 0.5) st.closure_tangent = (d0 + (d0.dot(d1) >= 0 ? d1 : Vec3(-d1))).normalized();
  }
}

// The reference's subset instead of item 15's search: every bound
// constraint it applied.
SearchResult oracle_subset(Context& cx, const Binding& binding, const std::vector<Candidate>& cands,
                           const SearchSettings& st) {
  const std::vector<bool> matched = oracle_choice(cx, cands);
  std::vector<int> subset;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (matched[i] && binding.anchor[i] >= 0) subset.push_back(static_cast<int>(i));
  SearchResult sr;
  sr.best = evaluate_subset(binding, cands, subset, st);
  sr.subsets_tried = 1;
  return sr;
}

// The best subset's curve (item 15: only a non-finite solve keeps the fit).
void apply_solution(Context& cx, const Curve& fitted, const Binding& binding, const SearchSettings& st,
                    const SearchResult& sr, CorrectedStroke& cs) {
  cx.stats.subsets_tried = sr.subsets_tried;
  cx.stats.iterations = sr.levels;
  cx.stats.extra["solves"] = sr.subsets_tried;
  if (!sr.best.feasible) {
    cs.curve = fitted;
    return;
  }
  cs.curve = binding.curve;
  cs.curve.control_points = sr.best.solve.control_points;
  for (int i : sr.best.subset) cs.enforced[i] = true;
  if (st.closure) {
    cs.curve.control_points.back() = cs.curve.control_points.front();
    cs.curve.closed = true;
    cs.closure_enforced = true;
  }
  cx.stats.extra["fidelity"] = sr.best.solve.fidelity;
  cx.stats.extra["energy"] = sr.best.energy;
}

// Item 16: dangling ends beyond the first/last enforced intersection or
// plane; anchors shift with the removed segments, those cut away are
// no longer enforced.
void trim_ends(const CassieParams& p, const Thresholds& th, const std::vector<Candidate>& cands,
               std::vector<int>& anchor, CorrectedStroke& cs) {
  if (!p.trim_dangling) return;
  std::vector<int> joints;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (cs.enforced[i] && cands[i].kind != TargetKind::grid) joints.push_back(anchor[i] / 3);
  const int k_before = cs.curve.segment_count();
  const int removed = trim_dangling(cs.curve, joints, p.trim_fraction, th.trim);
  const int k_after = cs.curve.segment_count();
  if (k_after == k_before) return;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    if (anchor[i] < 0) continue;
    anchor[i] -= 3 * removed;
    if (anchor[i] < 0 || anchor[i] > 3 * k_after) anchor[i] = -1, cs.enforced[i] = false;
  }
}

// Soft terms (item 14), reported with what they left.
void add_soft_terms(const Context& cx, const SearchResult& sr, const std::vector<Candidate>& cands,
                    CorrectedStroke& cs) {
  const CassieParams& p = cx.params;
  if (p.planarity && sr.best.plane_normal) {
    Constraint pc{sr.best.plane_axis >= 0 ? ConstraintKind::axis_plane : ConstraintKind::planar,
                  {cx.stroke_ref}, *sr.best.plane_normal, p.planarity_weight, false, true,
                  plane_residual(cs.curve.control_points, *sr.best.plane_normal)};
    if (sr.best.plane_axis >= 0)
      pc.references.push_back({ConstraintRef::Kind::axis, static_cast<std::uint64_t>(sr.best.plane_axis), 0.0});
    cs.soft.push_back(pc);
  }
  for (const Placement& pl : cs.placed) {
    const Candidate& c = cands[pl.constraint];
    if (!c.tangent) continue;
    ConstraintRef other = c.kind == TargetKind::mirror ? ConstraintRef{ConstraintRef::Kind::mirror, 0, 0.0}
                                                       : ConstraintRef{ConstraintRef::Kind::curve, c.curve, c.t_curve};
    cs.soft.push_back({ConstraintKind::tangent, {cx.stroke_ref, other}, *c.tangent, p.tangent_weight, false, true,
                       line_angle(tangent(cs.curve, std::min(pl.t, cs.curve.t_max())), *c.tangent)});
  }
}

// Items 8–16: a poly-Bézier.
CorrectedStroke correct_bezier(Context& cx, const Curve& fitted_in) {
  const CassieParams& p = cx.params;
  const Thresholds& th = cx.th;
  const Network& net = cx.sketch.network;
  CorrectedStroke cs;
  std::vector<Candidate> cands = detect(cx);
  correct_targets(cands, fitted_in, net, th.correction, p.correction_points, p.correction_keeps_target);  // item 8
  if (p.corrected_node_snap)  // item 8: `GetConstraint` at the corrected target too
    for (Candidate& c : cands) snap_to_node(c, net, th);
  oracle_positions(cx, cands);
  place_on_stroke(cands, fitted_in);
  std::stable_sort(cands.begin(), cands.end(),
                   [](const Candidate& a, const Candidate& b) { return a.t_stroke < b.t_stroke; });
  const Curve fitted = p.overlap_cut ? cut_overlaps(fitted_in, cands, net, th.overlap, p.angle) : fitted_in;  // item 9
  assign_weights(cands, fitted, net, cx.sketch.workspace, p, th);  // item 11
  const Binding binding = bind_to_anchors(fitted, cands, th.reuse);  // item 12

  SearchSettings st = search_settings(p, th);
  set_closure(fitted, binding, th.closure, st);
  cs.closure_considered = st.closure;
  const SearchResult sr =  // items 13–15, or the reference's own subset
      cx.applied ? oracle_subset(cx, binding, cands, st) : greedy_search(binding, cands, st);
  cs.enforced.assign(cands.size(), false);
  apply_solution(cx, fitted, binding, st, sr, cs);
  std::vector<int> anchor = binding.anchor;
  trim_ends(p, th, cands, anchor, cs);
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (cs.enforced[i]) cs.placed.push_back({static_cast<int>(i), anchor[i] / 3.0});
  add_soft_terms(cx, sr, cands, cs);
  cs.constraints = std::move(cands);
  return cs;
}

// Item 18: the whole stroke onto the mirror plane.
void project_on_mirror(Context& cx, CorrectedStroke& cs) {
  if (!cx.use_mirror) return;
  std::vector<Vec3> hits;
  for (const Placement& pl : cs.placed)
    if (is_intersection(cs.constraints[pl.constraint])) hits.push_back(cs.constraints[pl.constraint].target);
  if (project_onto_mirror(cs.curve, cx.sketch.workspace, hits, cx.th.mirror, cx.th.on_plane, cx.params.angle)) {
    cs.mirror_copy = false;
    cx.stats.extra["mirror_projected"] = 1;
  }
}

// Item 20: onto the patches.
void project_on_patches(Context& cx, CorrectedStroke& cs) {
  if (!cx.params.on_surface || cx.sketch.network.patches().empty() || cs.curve.kind != CurveKind::bezier) return;
  std::vector<int> anchors;
  std::vector<CurveId> hits;
  for (const Placement& pl : cs.placed) {
    anchors.push_back(static_cast<int>(std::lround(3 * pl.t)));
    if (is_intersection(cs.constraints[pl.constraint])) hits.push_back(cs.constraints[pl.constraint].curve);
  }
  std::vector<Vec3> brush;  // item 6: a curve in contact is the main collider, not the patch
  if (cx.params.surface_touch == SurfaceTouch::brush)
    for (const Sample& s : cx.stroke.samples)
      if (cx.sketch.network.curves_near(s.position, cx.th.contact).empty()) brush.push_back(s.position);
  // Item 20: "the whole stroke only if the patch spans it", read from the hand (surface_span).
  const SurfaceBrush hand{cx.params.surface_touch == SurfaceTouch::brush ? &brush : nullptr,
                          {cx.stroke.samples.front().position, cx.stroke.samples.back().position}, cx.th.brush,
                          cx.params.surface_span};
  const auto proj = project_on_surface(cx.sketch.network, cs.curve.control_points, anchors, hits, cx.th.surface, hand);
  if (!proj) return;
  double moved = 0.0;
  for (std::size_t i = 0; i < proj->control_points.size(); ++i)
    moved = std::max(moved, (proj->control_points[i] - cs.curve.control_points[i]).norm());
  cs.curve.control_points = proj->control_points;
  for (const Placement& pl : cs.placed)  // enforced intersections stay exact
    cs.curve.control_points[static_cast<std::size_t>(std::lround(3 * pl.t))] = cs.constraints[pl.constraint].target;
  if (cs.curve.closed) cs.curve.control_points.back() = cs.curve.control_points.front();
  cs.soft.push_back({ConstraintKind::on_surface, {cx.stroke_ref}, Vec3::Zero(), 1.0, false, proj->whole, 0.0});
  cx.stats.extra["on_surface_patch"] = static_cast<double>(proj->patch);
  cx.stats.extra["on_surface_moved"] = moved;
}

}  // namespace

Correction correct_stroke(const Stroke& stroke, const Sketch& sketch, const CassieParams& params,
                          const std::vector<Vec3>* applied) {
  const auto start = std::chrono::steady_clock::now();
  Correction out;
  const double scale = stroke.workspace_scale > 0 ? stroke.workspace_scale : 1.0;
  Preprocessed pre;
  try {  // items 1–4 (the stroke copied only when densified)
    pre = params.input_spacing_factor > 0
              ? preprocess_stroke(densify_stroke(stroke, params.input_spacing_factor * params.delta / scale),
                                  params.preprocess)
              : preprocess_stroke(stroke, params.preprocess);
  } catch (const std::exception& e) {
    out.error = e.what();
    return out;
  }
  const Workspace& ws = sketch.workspace;
  Context cx{stroke, sketch, params, thresholds(params, scale), false,
             {ConstraintRef::Kind::stroke, stroke.id, 0.0}, {}, applied};
  cx.use_mirror = params.mirror != MirrorMode::off && ws.mirror_enabled && ws.mirror_normal.norm() > 0;
  cx.stats.extra["hook_cut_start"] = pre.hook_cut[0];
  cx.stats.extra["hook_cut_end"] = pre.hook_cut[1];

  CorrectedStroke cs;
  if (pre.is_line) {
    cs = correct_line(cx, pre.curve);
  } else if (solver_skipped(pre.curve, params, cx.th.delta)) {
    cs.curve = pre.curve;  // item 5: unconstrained, nothing logged (item 21)
    cx.stats.extra["solver_skipped"] = 1;
  } else {
    cs = correct_bezier(cx, pre.curve);
  }
  cx.stats.extra["control_points"] = static_cast<double>(cs.curve.control_points.size());
  project_on_mirror(cx, cs);
  project_on_patches(cx, cs);
  out = build_correction(stroke, sketch, cs, cx.use_mirror && params.mirror == MirrorMode::workspace);
  for (const auto& [k, v] : cx.stats.extra) out.stats.extra[k] = v;
  out.stats.subsets_tried = cx.stats.subsets_tried;
  out.stats.iterations = cx.stats.iterations;
  out.stats.extra["time_ms"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace sketchlab::cassie
