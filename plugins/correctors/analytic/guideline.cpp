#include "guideline.hpp"

#include <cmath>

#include "line_inference.hpp"

namespace sketchlab::analytic {

namespace {

double border_distance(const Camera& cam, const Vec2& q) {
  const Vec4& vp = cam.view().viewport;
  return std::min({q.x() - vp[0], vp[0] + vp[2] - q.x(), q.y() - vp[1], vp[1] + vp[3] - q.y()});
}

bool on_screen(const Camera& cam, const Vec2& q) { return border_distance(cam, q) >= 0; }

}  // namespace

std::vector<Vec3> known_points_near(const Scaffold& s, const Camera& cam, const Vec2& pixel, double radius) {
  std::vector<std::pair<double, Vec3>> found;
  for (const ScaffoldVertex& v : s.vertices) {
    const auto q = cam.project(v.p);
    if (q && (*q - pixel).norm() <= radius) found.push_back({(*q - pixel).norm(), v.p});
  }
  for (std::size_t i = 0; i < s.lines.size(); ++i)
    for (std::size_t j = i + 1; j < s.lines.size(); ++j) {
      const ScaffoldLine& a = s.lines[i];
      const ScaffoldLine& b = s.lines[j];
      const std::optional<Vec3> x = scaffold_crossing(s, a, b);
      if (!x) continue;
      const auto q = cam.project(*x);
      if (q && (*q - pixel).norm() <= radius) found.push_back({(*q - pixel).norm(), *x});
    }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec3> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

std::optional<Guideline> detect_guideline(const Scaffold& s, const Camera& cam, const Stroke2d& stroke,
                                          const AnalyticParams& p, bool forced) {
  if (stroke.points.size() < 2) return std::nullopt;
  const Vec2 a = stroke.points.front(), b = stroke.points.back();
  const double chord = (b - a).norm();
  if (!(chord > 0)) return std::nullopt;
  const double dev = chord_deviation(stroke.points);
  if (dev > p.straightness * chord || dev > p.delta_max * cam.dpi()) return std::nullopt;
  const std::vector<Vec3> starts =
      known_points_near(s, cam, a, p.collect_factor * stroke.delta.front());
  if (starts.empty()) return std::nullopt;
  const Vec3 origin = starts.front();
  const auto o2 = cam.project(origin);
  if (!o2) return std::nullopt;
  const Vec2 sdir = (b - *o2).normalized();
  const double end_radius = p.collect_factor * stroke.delta.back();
  std::optional<Guideline> best;
  double best_score = -1e300;
  // The stroke as the segment {known point, this direction, free end} of
  // §3.1: S (eq. 3) with the far end the point of the direction's 3D line
  // nearest the end's ray, times G (eq. 4) without its length term (a
  // vanishing line is a direction, §2.2: its stroke's length is arbitrary);
  // C (eq. 5) is the same for every direction.
  const StrokeEnd ends[2] = {{a, stroke.delta.front(), cam.ray(a)}, {b, stroke.delta.back(), cam.ray(b)}};
  auto fitness = [&](const Vec3& d3) {
    const LineLineHit h = closest_line_line(origin, d3, ends[1].ray.origin, ends[1].ray.direction);
    if (h.parallel) return 0.0;
    const std::pair<Vec3, Vec3> seg{origin, origin + h.s * d3};
    return endpoint_score(cam, seg, ends) * (1.0 + direction_prior(s, d3, p));
  };
  auto test = [&](const Vec3& d3, bool image_parallel) {
    const auto vp = cam.vanishing_point(d3);
    // The image direction of +d3 at the origin. It points toward the
    // vanishing point only when d3 points away from the eye: taking vp − o
    // for it stored guidelines drawn toward the eye reversed.
    const auto q = cam.project(origin + 1e-3 * s.extent * d3);
    if (!q) return;
    Vec2 dir2 = *q - *o2;
    if (!(dir2.norm() > 1e-9)) return;
    dir2.normalize();
    double c = dir2.dot(sdir);
    Vec3 oriented = d3;
    if (c < 0) {
      c = -c;
      oriented = -d3;
    }
    // Toward an on-screen vanishing point only (§2.2: the stroke runs from
    // the known point to it); toward one off screen either way.
    if (vp && on_screen(cam, *vp) && (*vp - *o2).dot(sdir) < 0) return;
    const double angle = std::acos(std::min(1.0, c));
    // Its end is a sample within δ of the intended one (§3.1, eq. 3), so a
    // short guideline may leave its vanishing line by up to guideline_reach·δ
    // at its end where the angle test alone would reject it.
    const double off = std::abs(dir2.x() * (b - *o2).y() - dir2.y() * (b - *o2).x());
    if (angle > p.guideline_angle && off > p.guideline_reach * stroke.delta.back()) return;
    // Among directions that pass, the smallest angle (choice), or with
    // guideline_fitness the best F = S·G (§3.1): directions whose images
    // nearly coincide at the known point are told apart by how many segments
    // already run along them (eq. 4) rather than by the pen's error.
    const double score = p.guideline_fitness ? fitness(oriented) : -angle;
    if (score < best_score) return;
    if (!forced) {
      const bool reaches_vp = vp && on_screen(cam, *vp) && (b - *vp).norm() <= end_radius;
      const bool reaches_edge = (!vp || !on_screen(cam, *vp)) && border_distance(cam, b) <= end_radius;
      if (!reaches_vp && !reaches_edge) return;
    }
    best_score = score;
    best = Guideline{origin, oriented.normalized(), image_parallel};
  };
  for (const Vec3& d : s.vanishing) test(d, false);
  if (!best) {
    test(cam.right(), true);
    test(cam.up(), true);
  }
  return best;
}

std::vector<TickTransfer> detect_tick(const Scaffold& s, const Camera& cam, const Stroke2d& stroke,
                                      const AnalyticParams& p) {
  std::vector<TickTransfer> out;
  if (stroke.points.size() < 2 || stroke.length > p.tick_length * cam.dpi()) return out;
  const Vec2 a = stroke.points.front(), b = stroke.points.back();
  // A short stroke from one known point to another is a segment between
  // them (§3.1, Figure 7a, b: a foreshortened edge can be shorter than a
  // tick), not a tick-mark, which is drawn across a guideline (§2.3) with
  // at most the one point it marks under it.
  const auto at_a = known_points_near(s, cam, a, p.collect_factor * stroke.delta.front());
  const auto at_b = known_points_near(s, cam, b, p.collect_factor * stroke.delta.back());
  if (!at_a.empty() && !at_b.empty() && (at_a.front() - at_b.front()).norm() > s.tolerance) return out;
  // The guideline the tick crosses: its 2D projection meets the tick within
  // tick_reach·δ beyond either end (§3.1, eq. 3: a stroke's ends are samples
  // within δ of the intended ones, and the guideline's projection runs from
  // the known point it snapped to, up to 2δ from where its stroke began).
  const double chord = (b - a).norm();
  if (!(chord > 0)) return out;
  const double reach_a = p.tick_reach * stroke.delta.front() / chord;
  const double reach_b = p.tick_reach * stroke.delta.back() / chord;
  int guide = -1;
  Vec2 cross = Vec2::Zero();
  double best = 1e300;
  for (std::size_t i = 0; i < s.lines.size(); ++i) {
    const ScaffoldLine& l = s.lines[i];
    if (!l.guide) continue;
    const auto p0 = cam.project(l.a);
    const auto p1 = cam.project(l.b);
    if (!p0 || !p1) continue;
    const Vec2 d = *p1 - *p0;
    auto side = [&](const Vec2& q) { return d.x() * (q.y() - p0->y()) - d.y() * (q.x() - p0->x()); };
    const double sa = side(a), sb = side(b);
    if (sa == sb) continue;  // parallel
    const double t = sa / (sa - sb);
    if (!(t >= -reach_a && t <= 1.0 + reach_b)) continue;
    const Vec2 x = a + t * (b - a);
    const double along = (x - *p0).dot(d) / d.squaredNorm();
    if (along < 0 || along > 1) continue;
    const double mid = std::abs(t - 0.5);
    if (mid < best) {
      best = mid;
      guide = static_cast<int>(i);
      cross = x;
    }
  }
  if (guide < 0) return out;
  const ScaffoldLine& g = s.lines[static_cast<std::size_t>(guide)];
  const Ray ray = cam.ray(cross);
  const LineLineHit h = closest_line_line(g.a, g.direction(), ray.origin, ray.direction);
  Vec3 x = g.a + h.s * g.direction();
  // Snap to nearby scaffold points on the guideline (§2.3).
  for (const Vec3& k : known_points_near(s, cam, cross, p.collect_factor * p.delta_min * cam.dpi())) {
    const double t = (k - g.a).dot(g.direction());
    if ((g.a + t * g.direction() - k).norm() <= s.tolerance) {
      x = k;
      break;
    }
  }
  out.push_back({guide, x});
  // Transfer the distance A from each intersection point along the other
  // guideline, both ways.
  for (std::size_t i = 0; i < s.lines.size(); ++i) {
    if (static_cast<int>(i) == guide || !s.lines[i].guide) continue;
    const ScaffoldLine& o = s.lines[i];
    const LineLineHit q = closest_line_line(g.a, g.direction(), o.a, o.direction());
    if (q.parallel || q.distance > s.tolerance) continue;
    const Vec3 y = g.a + q.s * g.direction();
    const double A = (x - y).norm();
    if (!(A > s.tolerance)) continue;
    out.push_back({static_cast<int>(i), y + A * o.direction()});
    out.push_back({static_cast<int>(i), y - A * o.direction()});
  }
  return out;
}

}  // namespace sketchlab::analytic
