#include "line_inference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>

#include "curve_crossing.hpp"
#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::analytic {

namespace {

double gauss(double d, double sigma) { return std::exp(-(d * d) / (sigma * sigma)); }

// Nearest point of a scaffold line to a ray (clamped to a segment's extent).
Vec3 line_point_near_ray(const ScaffoldLine& l, const Ray& ray) {
  const Vec3 u = l.direction();
  const LineLineHit h = closest_line_line(l.a, u, ray.origin, ray.direction);
  double s = h.s;
  if (!l.guide) s = std::clamp(s, 0.0, (l.b - l.a).norm());
  return l.a + s * u;
}

Vec3 point_of(const PointConstraint& pc, const Scaffold& s, const Ray& ray) {
  if (pc.type == PointConstraint::Type::on_line)
    return line_point_near_ray(s.lines[static_cast<std::size_t>(pc.line)], ray);
  return pc.p;
}

std::vector<int> lines_at(const PointConstraint& pc, const Scaffold& s) {
  switch (pc.type) {
    case PointConstraint::Type::vertex:
      return s.vertices[static_cast<std::size_t>(pc.vertex)].lines;
    case PointConstraint::Type::intersection:
      return {pc.line, pc.line2};
    case PointConstraint::Type::on_line:
      return {pc.line};
    case PointConstraint::Type::curve_intersection:
      return {};
  }
  return {};
}

// `other` is the stroke's other endpoint pixel: the stroke's image line runs
// through both.
std::vector<PointConstraint> collect_points(const Scaffold& s, const Camera& cam, const StrokeEnd& end,
                                            const Vec2& other, double radius, const AnalyticParams& p) {
  std::vector<PointConstraint> out;
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    const auto q = cam.project(s.vertices[v].p);
    if (q && (*q - end.pixel).norm() <= radius) {
      PointConstraint pc;
      pc.type = PointConstraint::Type::vertex;
      pc.p = s.vertices[v].p;
      pc.vertex = static_cast<int>(v);
      pc.f = p.f_vertex;
      out.push_back(pc);
    }
  }
  std::vector<int> near;
  for (std::size_t li = 0; li < s.lines.size(); ++li) {
    const Vec3 x = line_point_near_ray(s.lines[li], end.ray);
    const auto q = cam.project(x);
    if (q && (*q - end.pixel).norm() <= radius) {
      near.push_back(static_cast<int>(li));
      PointConstraint pc;
      pc.type = PointConstraint::Type::on_line;
      pc.line = static_cast<int>(li);
      pc.f = p.f_on_line;
      out.push_back(pc);
    }
  }
  // Guideline / line intersections (Figure 7b, c), skipping those that are
  // already vertices.
  std::vector<Vec3> seen;
  for (std::size_t i = 0; i < near.size(); ++i) {
    for (std::size_t j = i + 1; j < near.size(); ++j) {
      const ScaffoldLine& a = s.lines[static_cast<std::size_t>(near[i])];
      const ScaffoldLine& b = s.lines[static_cast<std::size_t>(near[j])];
      const std::optional<Vec3> crossing = scaffold_crossing(s, a, b);
      if (!crossing) continue;
      const Vec3 x = *crossing;
      bool dup = false;
      for (const PointConstraint& pc : out)
        if (pc.type == PointConstraint::Type::vertex && (pc.p - x).norm() <= 10 * s.tolerance) dup = true;
      for (const Vec3& y : seen)
        if ((y - x).norm() <= 10 * s.tolerance) dup = true;
      if (dup) continue;
      const auto q = cam.project(x);
      if (!q || (*q - end.pixel).norm() > radius) continue;
      seen.push_back(x);
      PointConstraint pc;
      pc.type = PointConstraint::Type::intersection;
      pc.p = x;
      pc.line = near[i];
      pc.line2 = near[j];
      pc.f = p.f_intersection;
      out.push_back(pc);
    }
  }
  // Line/curve intersections (Figure 7c): where the stroke's image line
  // crosses a curve's projection within the radius, the curve's 3D point
  // there. Crossings at a vertex (e.g. a curve end) are that vertex already.
  for (std::size_t ci = 0; ci < s.curves.size(); ++ci) {
    for (const CurveCrossing& x : curve_line_crossings(s.curves[ci].curve, cam, other, end.pixel, end.pixel, radius)) {
      bool dup = false;
      for (const PointConstraint& pc : out)
        if (pc.type != PointConstraint::Type::on_line && (pc.p - x.point).norm() <= 10 * s.tolerance) dup = true;
      if (dup) continue;
      PointConstraint pc;
      pc.type = PointConstraint::Type::curve_intersection;
      pc.p = x.point;
      pc.curve = static_cast<int>(ci);
      pc.curve_t = x.t;
      pc.f = p.f_curve_intersection;
      out.push_back(pc);
    }
  }
  return out;
}

}  // namespace

double Triplet::weight() const {
  return direction.f * distance.f;  // times f(C°), applied by the caller
}

void stroke_ends(const Camera& camera, const Stroke2d& stroke, StrokeEnd ends[2]) {
  ends[0].pixel = stroke.points.front();
  ends[0].delta = stroke.delta.front();
  ends[1].pixel = stroke.points.back();
  ends[1].delta = stroke.delta.back();
  for (int e = 0; e < 2; ++e) ends[e].ray = camera.ray(ends[e].pixel);
}

LineCandidates collect_line_candidates(const Scaffold& s, const Camera& cam, const Stroke2d& stroke,
                                       const StrokeEnd ends[2], const AnalyticParams& p) {
  LineCandidates c;
  for (int e = 0; e < 2; ++e)
    c.points[e] = collect_points(s, cam, ends[e], ends[1 - e].pixel, p.collect_factor * ends[e].delta, p);
  // Vertices near the stroke: lines through them (Figure 7e, f).
  std::vector<int> through;
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    const auto q = cam.project(s.vertices[v].p);
    if (!q) continue;
    const PolylineHit h = nearest_on_polyline(stroke.points, *q);
    if (h.distance <= p.collect_factor * stroke.delta[static_cast<std::size_t>(h.index)])
      through.push_back(static_cast<int>(v));
  }
  for (int e = 0; e < 2; ++e) {
    const int o = 1 - e;
    std::vector<DistanceConstraint> dists;
    for (std::size_t k = 0; k < c.points[o].size(); ++k) {
      DistanceConstraint dc;
      dc.type = c.points[o][k].type == PointConstraint::Type::on_line ? DistanceConstraint::Type::on_line
                                                                       : DistanceConstraint::Type::point;
      dc.point = static_cast<int>(k);
      dc.f = p.f_dist_point;
      dists.push_back(dc);
    }
    DistanceConstraint free;
    free.f = p.f_dist_free;
    dists.push_back(free);
    for (std::size_t k = 0; k < c.points[e].size(); ++k) {
      const PointConstraint& pc = c.points[e][k];
      std::vector<DirectionConstraint> dirs;
      for (const Vec3& d : s.vanishing) {
        DirectionConstraint dc;
        dc.type = DirectionConstraint::Type::vanishing;
        dc.d = d;
        dc.f = p.f_vanishing;
        dirs.push_back(dc);
      }
      for (int v : through) {
        if (pc.type == PointConstraint::Type::vertex && pc.vertex == v) continue;
        DirectionConstraint dc;
        dc.type = DirectionConstraint::Type::through_vertex;
        dc.vertex = v;
        dc.f = p.f_through;
        dirs.push_back(dc);
      }
      const std::vector<int> at = lines_at(pc, s);
      for (std::size_t i = 0; i < at.size(); ++i) {
        DirectionConstraint dc;
        dc.type = DirectionConstraint::Type::perpendicular;
        dc.line = at[i];
        dc.f = p.f_perpendicular;
        dirs.push_back(dc);
        for (std::size_t j = i + 1; j < at.size(); ++j) {
          const Vec3 n = s.lines[static_cast<std::size_t>(at[i])].direction().cross(
              s.lines[static_cast<std::size_t>(at[j])].direction());
          if (n.norm() < 1e-6) continue;
          DirectionConstraint pair;
          pair.type = DirectionConstraint::Type::perpendicular_pair;
          pair.d = n.normalized();
          pair.line = at[i];
          pair.line2 = at[j];
          pair.f = p.f_perpendicular;
          dirs.push_back(pair);
        }
      }
      for (const DirectionConstraint& dc : dirs)
        for (const DistanceConstraint& tc : dists) {
          Triplet t;
          t.origin = e;
          t.point = static_cast<int>(k);
          t.direction = dc;
          t.distance = tc;
          c.triplets.push_back(t);
        }
    }
  }
  return c;
}

std::optional<std::pair<Vec3, Vec3>> evaluate_triplet(const Triplet& t, const LineCandidates& c,
                                                      const Scaffold& s, const Camera& cam,
                                                      const StrokeEnd ends[2]) {
  const int e = t.origin, o = 1 - t.origin;
  const Vec3 p = point_of(c.points[e][static_cast<std::size_t>(t.point)], s, ends[e].ray);
  Vec3 d;
  switch (t.direction.type) {
    case DirectionConstraint::Type::vanishing:
    case DirectionConstraint::Type::perpendicular_pair:
      d = t.direction.d;
      break;
    case DirectionConstraint::Type::through_vertex: {
      const Vec3 q = s.vertices[static_cast<std::size_t>(t.direction.vertex)].p;
      if ((q - p).norm() <= 10 * s.tolerance) return std::nullopt;
      d = (q - p).normalized();
      break;
    }
    case DirectionConstraint::Type::perpendicular: {
      // The perpendicular to the line that lies in the plane through p and the
      // other endpoint's ray: its projection passes through that endpoint.
      const Vec3 n = (ends[o].ray.origin - p).cross(ends[o].ray.direction);
      const Vec3 m = n.cross(s.lines[static_cast<std::size_t>(t.direction.line)].direction());
      if (!(m.norm() > 1e-12 * (1.0 + n.norm()))) return std::nullopt;
      d = m.normalized();
      break;
    }
  }
  double len = 0.0;
  switch (t.distance.type) {
    case DistanceConstraint::Type::point: {
      const Vec3 q = c.points[o][static_cast<std::size_t>(t.distance.point)].p;
      len = (q - p).dot(d);
      if ((p + len * d - q).norm() > s.tolerance) return std::nullopt;
      break;
    }
    case DistanceConstraint::Type::on_line: {
      const ScaffoldLine& l =
          s.lines[static_cast<std::size_t>(c.points[o][static_cast<std::size_t>(t.distance.point)].line)];
      const LineLineHit h = closest_line_line(p, d, l.a, l.direction());
      if (h.parallel || h.distance > s.tolerance || !within_line(l, h.t, s.tolerance))
        return std::nullopt;
      len = h.s;
      break;
    }
    case DistanceConstraint::Type::free: {
      const LineLineHit h = closest_line_line(p, d, ends[o].ray.origin, ends[o].ray.direction);
      if (h.parallel || !(h.t > 0)) return std::nullopt;
      len = h.s;
      break;
    }
  }
  if (!(std::abs(len) > 1e-6 * s.extent) || !std::isfinite(len)) return std::nullopt;
  const Vec3 q = p + len * d;
  // A nearest point on a line (Figure 7d) positions an end only where the
  // segment crosses that line. On a segment lying along the line (drawn over
  // it), the nearest point is wherever the stroke ends, i.e. Figure 7's
  // "nearest point along the projected direction": as Cᵗ it is the free
  // distance constraint (enumerated once as such), and as C° with a known
  // point for Cᵗ it is the triplet {that point, Cᵈ, free} seen from the other
  // end. Counting those again would give a free end the weight of a snapped
  // one in eq. 1's sum (and the more lines lie along the segment, the more).
  const auto along = [&](const PointConstraint& pc) {
    return pc.type == PointConstraint::Type::on_line &&
           lies_on_line(s.lines[static_cast<std::size_t>(pc.line)], p, q, s.tolerance);
  };
  if (t.distance.type != DistanceConstraint::Type::free &&
      (along(c.points[e][static_cast<std::size_t>(t.point)]) ||
       along(c.points[o][static_cast<std::size_t>(t.distance.point)])))
    return std::nullopt;
  if (!cam.project(q) || !cam.project(p)) return std::nullopt;
  if (e == 0) return std::make_pair(p, q);
  return std::make_pair(q, p);
}

double endpoint_score(const Camera& cam, const std::pair<Vec3, Vec3>& seg, const StrokeEnd ends[2]) {
  const auto a = cam.project(seg.first), b = cam.project(seg.second);
  if (!a || !b) return 0.0;
  return gauss((*a - ends[0].pixel).norm(), ends[0].delta) * gauss((*b - ends[1].pixel).norm(), ends[1].delta);
}

double direction_prior(const Scaffold& s, const Vec3& d, const AnalyticParams& p) {
  int n = 0;
  for (const auto& [e, k] : s.direction_classes) n += k;
  if (n == 0) return 0.0;
  const double r_d = 1.0 - std::cos(p.direction_spread);
  double gd = 0.0;
  // Directions are unsigned: |d·d_j|.
  for (const auto& [e, k] : s.direction_classes) gd += k * gauss(1.0 - std::abs(d.dot(e)), r_d);
  return gd / n;
}

double geometry_prior(const Scaffold& s, const std::pair<Vec3, Vec3>& seg, const AnalyticParams& p) {
  int n = 0;
  for (const auto& [l, k] : s.length_classes) n += k;
  if (n == 0) return 1.0;
  const double r_l = s.length_sum / n;
  const double len = (seg.second - seg.first).norm();
  double gl = 0.0;
  for (const auto& [l, k] : s.length_classes) gl += k * gauss(len - l, r_l);
  return 1.0 + gl / n + direction_prior(s, (seg.second - seg.first) / len, p);
}

namespace {

struct Scored {
  std::pair<Vec3, Vec3> seg;
  int signature = 0;  // lowest triplet index giving this segment
  std::vector<int> members;
  double sum_c = 0.0, fitness = 0.0;
};

// Unique segments for one (possibly perturbed) stroke, with F evaluated for
// every group that can still reach the top two (G <= 3 bounds F by 3·S·ΣC).
std::vector<Scored> score_all(const LineCandidates& c, const std::vector<double>& weights,
                              const Scaffold& s, const Camera& cam, const StrokeEnd ends[2],
                              const AnalyticParams& p, bool members) {
  struct Item {
    std::uint64_t key;
    int index;
  };
  std::vector<Item> items;
  std::vector<std::pair<Vec3, Vec3>> segs(c.triplets.size());
  items.reserve(c.triplets.size());
  const double q = 1e-6 * s.extent;
  for (std::size_t i = 0; i < c.triplets.size(); ++i) {
    const auto seg = evaluate_triplet(c.triplets[i], c, s, cam, ends);
    if (!seg) continue;
    // FNV-1a over the quantised endpoints: equal segments share a key.
    std::uint64_t h = 1469598103934665603ULL;
    for (int k = 0; k < 6; ++k) {
      const double v = k < 3 ? seg->first[k] : seg->second[k - 3];
      h = (h ^ static_cast<std::uint64_t>(std::llround(v / q))) * 1099511628211ULL;
    }
    segs[i] = *seg;
    items.push_back({h, static_cast<int>(i)});
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    return a.key != b.key ? a.key < b.key : a.index < b.index;
  });
  std::vector<Scored> groups;
  for (std::size_t i = 0; i < items.size();) {
    Scored g;
    g.signature = items[i].index;  // lowest index: items are sorted by index within a key
    g.seg = segs[static_cast<std::size_t>(g.signature)];
    std::size_t j = i;
    for (; j < items.size() && items[j].key == items[i].key; ++j) {
      if (members) g.members.push_back(items[j].index);
      g.sum_c += weights[static_cast<std::size_t>(items[j].index)];
    }
    // S·ΣC for now; G below.
    g.fitness = endpoint_score(cam, g.seg, ends) * g.sum_c;
    if (g.fitness > 0) groups.push_back(std::move(g));
    i = j;
  }
  std::sort(groups.begin(), groups.end(), [](const Scored& a, const Scored& b) {
    return a.fitness != b.fitness ? a.fitness > b.fitness : a.signature < b.signature;
  });
  double best = 0.0, second = 0.0;
  for (Scored& g : groups) {
    if (3.0 * g.fitness < second) {
      g.fitness = 0.0;  // cannot reach the top two
      continue;
    }
    g.fitness *= geometry_prior(s, g.seg, p);
    if (g.fitness > best) {
      second = best;
      best = g.fitness;
    } else if (g.fitness > second) {
      second = g.fitness;
    }
  }
  std::stable_sort(groups.begin(), groups.end(), [](const Scored& a, const Scored& b) {
    return a.fitness != b.fitness ? a.fitness > b.fitness : a.signature < b.signature;
  });
  return groups;
}

}  // namespace

LineInference infer_line(const Scaffold& s, const Camera& cam, const Stroke2d& stroke,
                         const AnalyticParams& p, std::uint64_t seed) {
  LineInference out;
  StrokeEnd ends[2];
  stroke_ends(cam, stroke, ends);
  out.candidates = collect_line_candidates(s, cam, stroke, ends, p);
  out.combinations = static_cast<int>(out.candidates.triplets.size());
  // A triplet whose distance constraint is a scaffold point or line only
  // defines a segment when the three constraints are consistent, which does
  // not depend on where exactly the stroke ends fall (parameterised points
  // move along their line): test once on the stroke itself and keep the
  // combinations fixed for the perturbed strokes (§3.1 "for efficiency").
  {
    std::vector<Triplet> kept;
    for (const Triplet& t : out.candidates.triplets) {
      check_budget();  // issue 17: the per-event time budget
      if (t.distance.type == DistanceConstraint::Type::free || evaluate_triplet(t, out.candidates, s, cam, ends))
        kept.push_back(t);
    }
    out.candidates.triplets = std::move(kept);
  }
  const LineCandidates& c = out.candidates;
  out.consistent = static_cast<int>(c.triplets.size());
  if (c.triplets.empty()) return out;
  std::vector<double> weights(c.triplets.size());
  for (std::size_t i = 0; i < c.triplets.size(); ++i) {
    const Triplet& t = c.triplets[i];
    weights[i] = c.points[t.origin][static_cast<std::size_t>(t.point)].f * t.weight();
  }
  // Unique segments of the drawn stroke, each fully scored.
  std::vector<Scored> g0 = score_all(c, weights, s, cam, ends, p, true);
  out.unique_segments = static_cast<int>(g0.size());
  if (g0.empty()) return out;
  for (Scored& g : g0)
    if (!(g.fitness > 0)) g.fitness = endpoint_score(cam, g.seg, ends) * g.sum_c * geometry_prior(s, g.seg, p);
  std::stable_sort(g0.begin(), g0.end(), [](const Scored& a, const Scored& b) {
    return a.fitness != b.fitness ? a.fitness > b.fitness : a.signature < b.signature;
  });
  // §3.1: the stroke is one sample of the strokes that could have been
  // drawn. The constraint combinations (and the segments they define on the
  // drawn stroke) are held fixed; only S changes for strokes whose endpoints
  // are perturbed by an isotropic Gaussian matching eq. 3's kernel
  // exp(-d²/δ²) (deviation δ/√2 per axis). The most frequent winner is chosen.
  std::vector<Vec2> pa(g0.size()), pb(g0.size());
  std::vector<double> gc(g0.size());
  for (std::size_t i = 0; i < g0.size(); ++i) {
    pa[i] = cam.project(g0[i].seg.first).value_or(Vec2(1e300, 1e300));
    pb[i] = cam.project(g0[i].seg.second).value_or(Vec2(1e300, 1e300));
    const double sc = endpoint_score(cam, g0[i].seg, ends);
    gc[i] = sc > 0 ? g0[i].fitness / sc : g0[i].sum_c * geometry_prior(s, g0[i].seg, p);
  }
  std::vector<int> votes(g0.size(), 0);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, p.perturbation_deviation);
  const int samples = std::max(1, p.perturbation_samples);
  for (int k = 0; k < samples; ++k) {
    check_budget();  // issue 17: the per-event time budget
    Vec2 ea = ends[0].pixel, eb = ends[1].pixel;
    if (k > 0) {
      ea += ends[0].delta * Vec2(normal(rng), normal(rng));
      eb += ends[1].delta * Vec2(normal(rng), normal(rng));
    }
    int win = -1;
    double top = 0.0;
    for (std::size_t i = 0; i < g0.size(); ++i) {
      const double f = gauss((pa[i] - ea).norm(), ends[0].delta) * gauss((pb[i] - eb).norm(), ends[1].delta) * gc[i];
      if (f > top) {
        top = f;
        win = static_cast<int>(i);
      }
    }
    if (win >= 0) ++votes[static_cast<std::size_t>(win)];
  }
  // Most votes; ties go to the higher fitness on the drawn stroke (g0 order).
  std::size_t bi = 0;
  for (std::size_t i = 1; i < g0.size(); ++i)
    if (votes[i] > votes[bi]) bi = i;
  Scored* best = &g0[bi];
  const int most = votes[bi];
  auto to_choice = [&](const Scored& g) {
    LineChoice ch;
    ch.segment = g.seg;
    ch.triplet = c.triplets[static_cast<std::size_t>(g.signature)];
    for (int m : g.members) ch.satisfied.push_back(c.triplets[static_cast<std::size_t>(m)]);
    ch.fitness = g.fitness;
    return ch;
  };
  out.best = to_choice(*best);
  out.agreement = static_cast<double>(std::max(most, 0)) / samples;
  for (const Scored& g : g0)
    if (&g != best && g.fitness > 0) {
      out.runner_up = to_choice(g);
      out.confidence = g.fitness / best->fitness;
      break;
    }
  return out;
}

std::optional<std::pair<Vec3, Vec3>> ground_plane_segment(const Camera& cam, const StrokeEnd ends[2],
                                                          const Vec3& up, const Vec3& origin) {
  Vec3 pts[2];
  const Vec3 n = up.normalized();
  for (int e = 0; e < 2; ++e) {
    const double den = n.dot(ends[e].ray.direction);
    if (std::abs(den) < 1e-12) return std::nullopt;
    const double t = n.dot(origin - ends[e].ray.origin) / den;
    if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
    pts[e] = ends[e].ray.origin + t * ends[e].ray.direction;
  }
  if (!((pts[1] - pts[0]).norm() > 0) || !cam.project(pts[0]) || !cam.project(pts[1])) return std::nullopt;
  return std::make_pair(pts[0], pts[1]);
}

std::vector<Constraint> describe_triplet(const Triplet& t, const LineCandidates& c, const Scaffold& s,
                                         StrokeId stroke, const std::pair<Vec3, Vec3>& seg, bool enforced) {
  std::vector<Constraint> out;
  const Vec3 ends[2] = {seg.first, seg.second};
  auto curve_ref = [&](int line) {
    ConstraintRef r;
    r.kind = ConstraintRef::Kind::curve;
    r.id = s.lines[static_cast<std::size_t>(line)].id;
    return r;
  };
  auto stroke_ref = [&](int end) {
    ConstraintRef r;
    r.kind = ConstraintRef::Kind::stroke;
    r.id = stroke;
    r.parameter = end;
    return r;
  };
  auto point = [&](const PointConstraint& pc, int end, double f) {
    Constraint k;
    k.kind = pc.type == PointConstraint::Type::vertex         ? ConstraintKind::coincident_point
             : pc.type == PointConstraint::Type::intersection ? ConstraintKind::intersection
                                                              : ConstraintKind::point_on_curve;
    k.references.push_back(stroke_ref(end));
    if (pc.type == PointConstraint::Type::curve_intersection) {
      ConstraintRef r;
      r.kind = ConstraintRef::Kind::curve;
      r.id = s.curves[static_cast<std::size_t>(pc.curve)].id;
      r.parameter = pc.curve_t;
      k.references.push_back(r);
    } else if (pc.type == PointConstraint::Type::vertex) {
      for (int l : s.vertices[static_cast<std::size_t>(pc.vertex)].lines) k.references.push_back(curve_ref(l));
    } else {
      k.references.push_back(curve_ref(pc.line));
      if (pc.line2 >= 0) k.references.push_back(curve_ref(pc.line2));
    }
    k.target = ends[end];
    k.weight = f;
    k.hard = true;
    k.enforced = enforced;
    return k;
  };
  const PointConstraint& pc = c.points[t.origin][static_cast<std::size_t>(t.point)];
  out.push_back(point(pc, t.origin, pc.f));
  Constraint d;
  d.references.push_back(stroke_ref(t.origin));
  d.target = (seg.second - seg.first).normalized();
  d.weight = t.direction.f;
  d.hard = true;
  d.enforced = enforced;
  switch (t.direction.type) {
    case DirectionConstraint::Type::vanishing:
      d.kind = ConstraintKind::parallel;
      break;
    case DirectionConstraint::Type::through_vertex:
      d.kind = ConstraintKind::coincident_point;
      d.target = s.vertices[static_cast<std::size_t>(t.direction.vertex)].p;
      break;
    case DirectionConstraint::Type::perpendicular:
    case DirectionConstraint::Type::perpendicular_pair:
      d.kind = ConstraintKind::perpendicular;
      d.references.push_back(curve_ref(t.direction.line));
      if (t.direction.line2 >= 0) d.references.push_back(curve_ref(t.direction.line2));
      break;
  }
  out.push_back(d);
  if (t.distance.type != DistanceConstraint::Type::free) {
    const PointConstraint& q = c.points[1 - t.origin][static_cast<std::size_t>(t.distance.point)];
    out.push_back(point(q, 1 - t.origin, t.distance.f));
  }
  return out;
}

}  // namespace sketchlab::analytic
