#include "stroke_analysis.hpp"

#include <cmath>

#include "curve_inference.hpp"
#include "ellipse_snap.hpp"
#include "guideline.hpp"
#include "line_inference.hpp"
#include "stroke_2d.hpp"
#include "sketchlab/camera.hpp"
#include "sketchlab/network_curve.hpp"

namespace sketchlab::analytic {

namespace {

ConstraintRef stroke_ref(StrokeId id, double t) {
  ConstraintRef r;
  r.kind = ConstraintRef::Kind::stroke;
  r.id = id;
  r.parameter = t;
  return r;
}

std::vector<Constraint> describe_curve(const CurveInference& ci, const CurveChoice& ch, const Scaffold& s,
                                       StrokeId id, const AnalyticParams& p, bool enforced) {
  std::vector<Constraint> out;
  const CurveCombination& c = ch.combination;
  for (std::size_t j = 0; j < c.points.size(); ++j) {
    const CurvePoint& cp = ci.points[static_cast<std::size_t>(c.points[j])];
    Constraint k;
    k.kind = ConstraintKind::coincident_point;
    k.references.push_back(stroke_ref(id, static_cast<double>(j)));
    k.target = cp.p;
    k.weight = c.tangents[j] >= 0 ? p.f_tangent_point : p.f_point;
    k.hard = true;
    k.enforced = enforced;
    out.push_back(k);
    if (c.tangents[j] >= 0) {
      Constraint t = k;
      t.kind = ConstraintKind::tangent;
      ConstraintRef r;
      r.kind = ConstraintRef::Kind::curve;
      r.id = s.lines[static_cast<std::size_t>(cp.lines[static_cast<std::size_t>(c.tangents[j])])].id;
      t.references.push_back(r);
      t.target = cp.directions[static_cast<std::size_t>(c.tangents[j])];
      out.push_back(t);
    }
  }
  if (c.planar) {
    Constraint k;
    k.kind = ConstraintKind::planar;
    k.references.push_back(stroke_ref(id, 0));
    k.weight = p.f_planar;
    k.hard = true;
    k.enforced = enforced;
    out.push_back(k);
  }
  if (c.symmetric) {
    Constraint k;
    k.kind = ConstraintKind::symmetry;
    k.references.push_back(stroke_ref(id, 0));
    const auto& a = ci.points[static_cast<std::size_t>(c.points.front())].p;
    const auto& b = ci.points[static_cast<std::size_t>(c.points.back())].p;
    k.target = (b - a).normalized();
    k.weight = p.f_symmetric;
    k.hard = true;
    k.enforced = enforced;
    out.push_back(k);
  }
  return out;
}

}  // namespace

StrokeOutcome analyse_stroke(const Stroke& stroke, const Scaffold& s, const Sketch& sketch,
                             const AnalyticParams& p, bool aids) {
  StrokeOutcome out;
  const Camera cam(*stroke.view);
  const Stroke2d s2 = make_stroke_2d(stroke, cam.dpi(), p);
  if (s2.points.size() < 2 || !(s2.length > 1e-6)) {
    out.reason = "stroke has fewer than two distinct samples";
    out.stats["free"] = 1;
    return out;
  }
  if (s2.hooks_cut) out.stats["hook_cut"] = 1;
  const Vec3 up = sketch.workspace.up.normalized();
  if (aids && !s.vertices.empty()) {
    if (const auto g = detect_guideline(s, cam, s2, p, stroke.layer == Layer::guide)) {
      double len = 2.0 * s.extent;
      while (len > 1e-9 && !cam.project(g->origin + len * g->direction)) len *= 0.5;
      out.kind = StrokeOutcome::Kind::guideline;
      out.added.push_back(make_network_curve(0, make_line(g->origin, g->origin + len * g->direction),
                                             Layer::guide, stroke.id));
      out.stats["guideline"] = 1;
      out.stats["image_parallel"] = g->image_parallel ? 1 : 0;
      return out;
    }
    const std::vector<TickTransfer> ticks = detect_tick(s, cam, s2, p);
    if (!ticks.empty()) {
      out.kind = StrokeOutcome::Kind::tick;
      std::map<CurveId, NetworkCurve> changed;
      for (const TickTransfer& t : ticks) {
        const ScaffoldLine& l = s.lines[static_cast<std::size_t>(t.guide)];
        auto it = changed.find(l.id);
        if (it == changed.end()) it = changed.emplace(l.id, *sketch.network.find_curve(l.id)).first;
        Keypoint k;
        k.kind = Keypoint::Kind::tick;
        k.t = std::clamp((t.position - l.a).dot(l.direction()) / (l.b - l.a).norm(), 0.0, 1.0);
        k.position = t.position;
        it->second.keypoints.push_back(k);
      }
      for (auto& [id, nc] : changed) out.replaced.push_back(nc);
      out.stats["tick"] = 1;
      out.stats["ticks_added"] = static_cast<double>(ticks.size());
      return out;
    }
  }
  if (stroke.layer == Layer::guide) {
    out.reason = "guide stroke does not start at a known point along a known direction";
    out.stats["free"] = 1;
    return out;
  }
  const double chord = (s2.points.back() - s2.points.front()).norm();
  const double dev = chord_deviation(s2.points);
  const bool straight = chord > 0 && dev <= p.straightness * chord && dev <= p.delta_max * cam.dpi();
  // §2: the first stroke is assumed to lie in the ground plane, whatever its
  // wobble; leaving it free makes a later stroke (e.g. a diagonal) the first.
  const bool first_ground = p.first_stroke_ground && chord > 0 && s.segment_count() == 0;
  if (straight || first_ground) {
    StrokeEnd ends[2];
    stroke_ends(cam, s2, ends);
    if (s.segment_count() == 0) {
      // §2: the first stroke lies in the ground plane.
      const Vec3 origin = sketch.workspace.grid_origin;
      if (const auto seg = ground_plane_segment(cam, ends, up, origin)) {
        out.kind = StrokeOutcome::Kind::line;
        out.added.push_back(
            make_network_curve(0, make_line(seg->first, seg->second), Layer::scaffold, stroke.id));
        Constraint k;
        k.kind = ConstraintKind::axis_plane;
        k.references.push_back(stroke_ref(stroke.id, 0));
        k.target = up;
        k.hard = true;
        k.enforced = true;
        out.constraints.push_back(k);
        out.stats["line"] = 1;
        out.stats["ground_plane"] = 1;
        out.stats["confidence"] = 0;
        out.stats["combinations"] = 1;
        return out;
      }
      out.reason = "first stroke does not meet the ground plane in front of the camera";
      out.stats["free"] = 1;
      return out;
    }
    const LineInference li = infer_line(s, cam, s2, p, p.seed ^ (stroke.id * 0x9E3779B97F4A7C15ULL));
    out.stats["combinations"] = li.combinations;
    out.stats["unique_segments"] = li.unique_segments;
    out.stats["consistent_combinations"] = li.consistent;
    if (!li.best) {
      out.reason = "no constraint triplet defines a segment near the stroke";
      out.stats["free"] = 1;
      return out;
    }
    out.kind = StrokeOutcome::Kind::line;
    out.added.push_back(make_network_curve(0, make_line(li.best->segment.first, li.best->segment.second),
                                           Layer::scaffold, stroke.id));
    out.constraints = describe_triplet(li.best->triplet, li.candidates, s, stroke.id, li.best->segment, true);
    if (li.runner_up) {
      auto r = describe_triplet(li.runner_up->triplet, li.candidates, s, stroke.id, li.runner_up->segment, false);
      out.constraints.insert(out.constraints.end(), r.begin(), r.end());
      out.stats["runner_up_fitness"] = li.runner_up->fitness;
    }
    out.stats["line"] = 1;
    out.stats["fitness"] = li.best->fitness;
    out.stats["confidence"] = li.confidence;
    out.stats["agreement"] = li.agreement;
    out.stats["constraint_sets_satisfied"] = static_cast<double>(li.best->satisfied.size());
    return out;
  }
  const CurveInference ci = infer_curve(s, cam, s2, p);
  out.stats["combinations"] = static_cast<double>(ci.combinations);
  out.stats["curves_fitted"] = static_cast<double>(ci.fitted);
  out.stats["g_bound_exceeded"] = static_cast<double>(ci.g_bound_exceeded);
  out.stats["curve_points"] = static_cast<double>(ci.points.size());
  if (!ci.best || !(ci.best->fitness > 0)) {
    out.reason = "no pair of scaffold points near the stroke's ends";
    out.stats["free"] = 1;
    return out;
  }
  Curve curve = ci.best->curve;
  const CurveCombination& cb = ci.best->combination;
  bool snapped = false;
  if (p.ellipse_snap && cb.planar) {
    std::vector<Vec3> joints;
    std::vector<std::optional<Vec3>> tangents;
    for (std::size_t j = 0; j < cb.points.size(); ++j) {
      const CurvePoint& cp = ci.points[static_cast<std::size_t>(cb.points[j])];
      joints.push_back(cp.p);
      tangents.push_back(cb.tangents[j] >= 0 ? std::optional<Vec3>(cp.directions[static_cast<std::size_t>(cb.tangents[j])])
                                             : std::nullopt);
    }
    // The plane normal from the fitted (planar) curve's control polygon.
    Vec3 n = Vec3::Zero();
    const Vec3 o = curve.control_points.front();
    for (std::size_t i = 1; i + 1 < curve.control_points.size(); ++i)
      n += (curve.control_points[i] - o).cross(curve.control_points[i + 1] - o);
    if (n.norm() > 0) {
      if (auto e = snap_to_ellipse(curve, n.normalized(), joints, tangents, p.ellipse_tolerance)) {
        curve = *e;
        snapped = true;
      }
    }
  }
  out.kind = StrokeOutcome::Kind::curve;
  out.added.push_back(make_network_curve(0, curve, Layer::shape, stroke.id));
  out.constraints = describe_curve(ci, *ci.best, s, stroke.id, p, true);
  if (snapped) {
    Constraint k;
    k.kind = ConstraintKind::arc;
    k.references.push_back(stroke_ref(stroke.id, 0));
    k.hard = true;
    k.enforced = true;
    out.constraints.push_back(k);
  }
  if (ci.runner_up) {
    auto r = describe_curve(ci, *ci.runner_up, s, stroke.id, p, false);
    out.constraints.insert(out.constraints.end(), r.begin(), r.end());
    out.stats["runner_up_fitness"] = ci.runner_up->fitness;
  }
  out.stats["curve"] = 1;
  out.stats["fitness"] = ci.best->fitness;
  out.stats["confidence"] = ci.confidence;
  out.stats["planar"] = cb.planar ? 1 : 0;
  out.stats["symmetric"] = cb.symmetric ? 1 : 0;
  out.stats["ellipse_snap"] = snapped ? 1 : 0;
  return out;
}

}  // namespace sketchlab::analytic
