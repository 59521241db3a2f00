#include "candidates.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"

namespace sketchlab::cassie {

Thresholds thresholds(const CassieParams& p, double s) {
  Thresholds t;
  t.delta = scaled_threshold(p.delta, s);
  t.proximity = p.proximity_factor * t.delta;
  t.reuse = p.reuse_factor * t.delta;
  t.mirror = p.mirror_factor * t.delta;
  t.surface = p.surface_factor * t.delta;
  return t;
}

namespace {

struct Hit {
  int sample;
  double distance;
};

// Alternating closest points between the stroke and an existing curve,
// starting from the stroke parameter t0: converges to the closest pair.
void closest_pair(const Curve& stroke, const Curve& other, double t0, double& t_stroke,
                  ClosestPoint& on_other) {
  t_stroke = t0;
  for (int it = 0; it < 4; ++it) {
    on_other = closest_point(other, evaluate(stroke, t_stroke));
    const double t = closest_point(stroke, on_other.point).t;
    if (std::abs(t - t_stroke) < 1e-12) break;
    t_stroke = t;
  }
  on_other = closest_point(other, evaluate(stroke, t_stroke));
}

std::optional<Vec3> aligned_tangent(const Curve& stroke, double ts, const Curve& other, double to,
                                    double angle) {
  const Vec3 a = tangent(stroke, ts), b = tangent(other, to);
  const double c = a.dot(b);
  if (std::abs(c) < std::cos(angle)) return std::nullopt;
  return c >= 0 ? b : Vec3(-b);
}

}  // namespace

std::vector<Candidate> detect_candidates(const Curve& stroke, const Sketch& sketch,
                                         const CassieParams& params, const Thresholds& th,
                                         bool mirror, bool allow_closure) {
  std::vector<Candidate> out;
  const double length = arclength(stroke);
  const double r = th.proximity;
  // The brush tip: the stroke sampled every δ/2 (CASSIE tests the tip sphere
  // every frame; the exported samples are RDP-reduced, so we resample).
  const int n = std::clamp(static_cast<int>(std::ceil(length / (0.5 * th.delta))) + 1, 2, 2000);
  const std::vector<double> ts = arclength_parameters(stroke, n);
  std::vector<Vec3> pts(ts.size());
  for (std::size_t i = 0; i < ts.size(); ++i) pts[i] = evaluate(stroke, ts[i]);
  const Vec3 end0 = stroke.control_points.front(), end1 = stroke.control_points.back();

  // Existing curves: one candidate per run of consecutive samples within r.
  std::map<CurveId, std::vector<Hit>> hits;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i)
    for (const CurveHit& h : sketch.network.curves_near(pts[i], r)) hits[h.curve].push_back({i, h.distance});
  for (const auto& [id, hs] : hits) {
    const Curve& other = sketch.network.curves().at(id).curve;
    std::size_t b = 0;
    while (b < hs.size()) {
      std::size_t e = b + 1;
      while (e < hs.size() && hs[e].sample == hs[e - 1].sample + 1) ++e;
      const auto best = std::min_element(hs.begin() + b, hs.begin() + e,
                                         [](const Hit& x, const Hit& y) { return x.distance < y.distance; });
      Candidate c;
      ClosestPoint cp;
      closest_pair(stroke, other, ts[best->sample], c.t_stroke, cp);
      c.kind = TargetKind::curve;
      c.curve = id;
      c.t_curve = cp.t;
      c.target = cp.point;
      c.weight = params.weight_curve;
      // Snap to an existing intersection within δ (weight 2, CHI eq. 3), else
      // to the other curve's end within δ (its endpoint node in CASSIE).
      const auto nodes = sketch.network.nodes_near(cp.point, th.reuse);
      if (!nodes.empty()) {
        const Node& node = sketch.network.nodes().at(nodes.front().node);
        c.kind = TargetKind::node;
        c.node = node.id;
        c.target = node.position;
        c.weight = params.weight_node;
        for (const NodeIncidence& inc : node.incidences)
          if (inc.curve == id) c.t_curve = inc.t;
      } else {
        const Vec3 o0 = other.control_points.front(), o1 = other.control_points.back();
        const double d0 = (o0 - cp.point).norm(), d1 = (o1 - cp.point).norm();
        if (std::min(d0, d1) <= th.reuse) {
          c.t_curve = d0 <= d1 ? 0.0 : other.t_max();
          c.target = d0 <= d1 ? o0 : o1;
        }
      }
      c.t_stroke = closest_point(stroke, c.target).t;
      c.distance = (evaluate(stroke, c.t_stroke) - c.target).norm();
      if (params.tangents) c.tangent = aligned_tangent(stroke, c.t_stroke, other, c.t_curve, params.angle);
      if (c.distance <= r) out.push_back(c);
      b = e;
    }
  }

  // Grid nodes along the stroke (weight 1) or at an endpoint (1.25).
  if (sketch.workspace.grid_enabled && sketch.workspace.grid_spacing > 0) {
    std::map<std::array<long long, 3>, std::pair<double, Vec3>> grid;
    for (const Vec3& p : pts) {
      const Vec3 g = nearest_grid_point(sketch.workspace, p);
      const double d = (g - p).norm();
      if (d > r) continue;
      const Vec3 k = (g - sketch.workspace.grid_origin) / sketch.workspace.grid_spacing;
      const std::array<long long, 3> key{std::llround(k.x()), std::llround(k.y()), std::llround(k.z())};
      auto it = grid.find(key);
      if (it == grid.end() || d < it->second.first) grid[key] = {d, g};
    }
    for (const auto& [key, dg] : grid) {
      Candidate c;
      c.kind = TargetKind::grid;
      c.target = dg.second;
      c.t_stroke = closest_point(stroke, c.target).t;
      c.distance = (evaluate(stroke, c.t_stroke) - c.target).norm();
      const bool at_end = std::min((end0 - c.target).norm(), (end1 - c.target).norm()) <= r;
      c.weight = at_end ? params.weight_grid_endpoint : params.weight_grid;
      if (c.distance <= r) out.push_back(c);
    }
  }

  // Mirror plane: endpoints within 1.25δ are projected; crossings become
  // intersections with the mirrored copy (weight 1).
  if (mirror && sketch.workspace.mirror_enabled && sketch.workspace.mirror_normal.norm() > 0) {
    const Vec3 nm = sketch.workspace.mirror_normal.normalized();
    const double off = sketch.workspace.mirror_offset / sketch.workspace.mirror_normal.norm();
    auto side = [&](const Vec3& p) { return nm.dot(p) - off; };
    bool near0 = false, near1 = false;
    for (int e = 0; e < 2; ++e) {
      const Vec3 p = e == 0 ? end0 : end1;
      const double d = side(p);
      if (std::abs(d) > th.mirror) continue;
      (e == 0 ? near0 : near1) = true;
      Candidate c;
      c.kind = TargetKind::mirror;
      c.target = p - d * nm;
      c.t_stroke = e == 0 ? 0.0 : stroke.t_max();
      c.distance = std::abs(d);
      c.weight = params.weight_grid;
      out.push_back(c);
    }
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const double a = side(pts[i]), b = side(pts[i + 1]);
      if (a == 0.0 || a * b > 0.0) continue;
      double lo = ts[i], hi = ts[i + 1];
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (side(evaluate(stroke, mid)) * a > 0 ? lo : hi) = mid;
      }
      const double t = 0.5 * (lo + hi);
      const Vec3 p = evaluate(stroke, t);
      if ((near0 && (p - end0).norm() <= th.mirror) || (near1 && (p - end1).norm() <= th.mirror))
        continue;
      Candidate c;
      c.kind = TargetKind::mirror;
      c.target = p - side(p) * nm;
      c.t_stroke = t;
      c.distance = std::abs(side(p));
      c.weight = params.weight_grid;
      out.push_back(c);
    }
  }

  // Keep the closest, drop duplicates of one target, order along the stroke.
  std::stable_sort(out.begin(), out.end(),
                   [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  std::vector<Candidate> kept;
  for (const Candidate& c : out) {
    bool dup = false;
    for (const Candidate& k : kept)
      if ((k.target - c.target).norm() < 1e-9) dup = true;
    if (!dup) kept.push_back(c);
  }
  if (static_cast<int>(kept.size()) > params.max_candidates) kept.resize(params.max_candidates);

  // Closure: the two ends within r_detect of each other (thesis §3.2.3.2).
  if (allow_closure && (end0 - end1).norm() <= r && length > 2 * r) {
    Candidate c;
    c.kind = TargetKind::closure;
    c.distance = (end0 - end1).norm();
    c.t_stroke = 0.0;
    c.weight = params.weight_closure;
    kept.push_back(c);
  }
  std::stable_sort(kept.begin(), kept.end(),
                   [](const Candidate& a, const Candidate& b) { return a.t_stroke < b.t_stroke; });
  return kept;
}

double plane_residual(const std::vector<Vec3>& points, const Vec3& n) {
  if (points.empty()) return 0.0;
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : points) c += p;
  c /= static_cast<double>(points.size());
  double r = 0.0;
  for (const Vec3& p : points) r = std::max(r, std::abs((p - c).dot(n)));
  return r;
}

PlaneFit fit_plane(const std::vector<Vec3>& points, double max_distance, double angle) {
  PlaneFit f;
  if (points.size() < 3) return f;
  for (const Vec3& p : points) f.centroid += p;
  f.centroid /= static_cast<double>(points.size());
  Mat3 cov = Mat3::Zero();
  for (const Vec3& p : points) cov += (p - f.centroid) * (p - f.centroid).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> es(cov);
  // A straight run of control points has no defined plane.
  if (!(es.eigenvalues()[1] > 1e-12 * std::max(es.eigenvalues()[2], 1e-300))) return f;
  f.normal = es.eigenvectors().col(0).normalized();
  f.max_distance = plane_residual(points, f.normal);
  f.planar = f.max_distance <= max_distance;
  for (int a = 0; a < 3; ++a)
    if (std::abs(f.normal[a]) >= std::cos(angle)) {
      f.axis = a;
      f.normal = Vec3::Unit(a);
    }
  return f;
}

}  // namespace sketchlab::cassie
