#include "apply_decision.hpp"

#include <algorithm>
#include <cmath>

#include "promotion.hpp"

namespace sketchlab::justdrawit {

namespace {

EndMatch flipped(EndMatch m, double length) {
  m.dir = -m.dir;
  m.curve_at_s0 = length - m.curve_at_s0;
  m.curve_at_s1 = length - m.curve_at_s1;
  m.curve_s = length - m.curve_s;
  m.at_curve_start = !m.at_curve_start;
  return m;
}

double merge_mid_stroke(const EndMatch& m) { return 0.5 * (m.stroke_s0 + m.stroke_s1); }
double attach_curve_s(const Projected& c, const EndMatch& m) {
  return m.kind == EndKind::merge ? merge_middle(c, m) : m.curve_s;
}
double attach_stroke_s(const EndMatch& m) { return m.kind == EndKind::merge ? merge_mid_stroke(m) : m.stroke_s; }

// Depths (relative to `plane`) at the curve's points.
std::optional<std::vector<double>> curve_depths(const Camera& cam, const Plane& plane,
                                                const Points3& pts) {
  std::vector<double> z(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto v = plane_depth(cam, plane, pts[i]);
    if (!v) return std::nullopt;
    z[i] = *v;
  }
  return z;
}

// §4.4.1 for one attached stroke end: the stroke points that overlap the
// curve take its depth; returns the extrapolation slope (depth change per
// pixel walking on past the anchored part).
double anchor_end(const EndMatch& m, bool at_end, const Points2& s2, const std::vector<double>& cum,
                  const Projected& c2, const std::vector<double>& zc, double d,
                  std::vector<std::optional<double>>& known) {
  const std::size_t n = s2.size();
  const double lc = c2.length();
  if (m.kind == EndKind::join) {
    const double win = std::min(3 * d, lc);
    const double slope = m.at_curve_start ? depth_slope(c2.cum, zc, win, 0.0)
                                          : depth_slope(c2.cum, zc, lc - win, lc);
    known[index_at(cum, m.stroke_s)] = interp(c2.cum, zc, m.curve_s) + slope * m.d_j;
    return slope;
  }
  std::vector<std::size_t> anchored;
  double last = -1;
  bool started = false;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = at_end ? n - 1 - k : k;
    const bool in_region = cum[i] >= m.stroke_s0 - 1e-9 && cum[i] <= m.stroke_s1 + 1e-9;
    const auto pr = project(c2.pts, c2.cum, s2[i]);
    const bool off = !c2.closed && (pr.at_start || pr.at_end);
    if (!started) {
      if (!in_region) continue;
      started = true;
    } else if (!in_region) {
      // Walking on along the curve (dir is +1 here: forward from the start,
      // backward from the end) while it stays near and does not fold back.
      const int sgn = at_end ? -1 : 1;
      if (pr.distance >= 1.5 * d || off || (!c2.closed && sgn * (pr.s - last) < -0.5 * d)) break;
    }
    known[i] = interp(c2.cum, zc, pr.s);
    anchored.push_back(i);
    last = pr.s;
  }
  if (anchored.size() < 2) return 0.0;
  // Average depth change per pixel over the last 3d of the anchored part.
  const std::size_t tip = anchored.back();
  std::size_t back = anchored.front();
  for (auto it = anchored.rbegin(); it != anchored.rend(); ++it) {
    back = *it;
    if (std::abs(cum[tip] - cum[*it]) >= 3 * d) break;
  }
  const double span = std::abs(cum[tip] - cum[back]);
  return span > 0 ? (*known[tip] - *known[back]) / span : 0.0;
}

void smooth_joins(Points3& pts, const std::vector<std::pair<std::size_t, std::size_t>>& joins,
                  double margin3, double spacing, int rounds, bool closed) {
  const std::size_t margin = static_cast<std::size_t>(std::ceil(margin3 / std::max(spacing, 1e-12)));
  for (const auto& [a, b] : joins) smooth_join(pts, a, b, margin, rounds, closed);
}

int join_rounds(const JdiParams& p, double q) {
  return 1 + p.smoothing + static_cast<int>(std::lround(40 * std::clamp(q, 0.0, 1.0)));
}

// Index in a splice result of tail index t (tail kept from s.m on).
std::size_t after_splice(const Splice& s, std::size_t t) {
  return t >= s.m ? s.join_end + (t - s.m) : s.join_end;
}

}  // namespace

Built apply_single(const Candidate& cand, SceneItem item, const Points2& s2, const Ctx& ctx) {
  Built out;
  const double d = ctx.d;
  CurveMatch m = cand.match;
  const int dir = m.start.kind != EndKind::none ? m.start.dir : m.end.dir;
  const bool flip = dir < 0;
  const double l2 = item.proj.length();
  if (flip) {
    item = reversed_item(std::move(item));
    if (m.start.kind != EndKind::none) m.start = flipped(m.start, l2);
    if (m.end.kind != EndKind::none) m.end = flipped(m.end, l2);
  }
  const auto cum = cumulative(s2);
  const bool has_s = m.start.kind != EndKind::none, has_e = m.end.kind != EndKind::none;
  // Reference plane: the film plane through the curve, or the visible draw
  // plane moved to the attached curve point (§4.4.1).
  Plane plane = ctx.cam.film_plane(item.centroid);
  if (ctx.draw_plane) {
    const double s = attach_curve_s(item.proj, has_s ? m.start : m.end);
    plane = {item.pts3[index_at(item.proj.cum, s)], ctx.draw_plane->normal};
  }
  auto zc = curve_depths(ctx.cam, plane, item.pts3);
  if (!zc && ctx.draw_plane) {
    plane = ctx.cam.film_plane(item.centroid);
    zc = curve_depths(ctx.cam, plane, item.pts3);
  }
  if (!zc) {
    out.error = "curve " + std::to_string(item.id) + " cannot be given depths in this view";
    return out;
  }
  std::vector<std::optional<double>> known(s2.size());
  double slope_after = 0, slope_before = 0;
  if (m.type == MatchType::oversketch) {
    bool monotone = true;
    std::vector<double> cs(s2.size());
    for (std::size_t i = 0; i < s2.size(); ++i) {
      cs[i] = project(item.proj.pts, item.proj.cum, s2[i]).s;
      if (!item.proj.closed && i > 0 && cs[i] < cs[i - 1] - d) monotone = false;
    }
    // Folding over with respect to the curve: use arclength instead of the
    // closest point (§4.4.1).
    const double a = m.start.curve_at_s0, b = m.end.curve_at_s1;
    const double sa = m.start.stroke_s0, sb = m.end.stroke_s1;
    for (std::size_t i = 0; i < s2.size(); ++i) {
      double s = cs[i];
      if (!monotone && sb > sa) s = a + (b - a) * std::clamp((cum[i] - sa) / (sb - sa), 0.0, 1.0);
      known[i] = interp(item.proj.cum, *zc, s);
    }
  } else {
    if (has_s) slope_after = anchor_end(m.start, false, s2, cum, item.proj, *zc, d, known);
    if (has_e) slope_before = anchor_end(m.end, true, s2, cum, item.proj, *zc, d, known);
    if (has_s && has_e) slope_after = slope_before = 0;
  }
  if (ctx.draw_plane) slope_after = slope_before = 0;  // off the curve: on the draw plane
  const std::vector<double> z = fill_depths(cum, known, slope_before, slope_after);
  const auto lifted = lift(ctx.cam, plane, s2, z, 2 + ctx.p.smoothing);
  if (!lifted) {
    out.error = "the stroke's rays miss the reference plane";
    return out;
  }
  const Points3& s3 = *lifted;
  const double d3 = d * ctx.cam.world_per_pixel(item.centroid);
  const double spacing = 0.1 * d3;
  const double radius = d3 * (1 + 3 * std::clamp(cand.q, 0.0, 1.0));  // §4.4.2: d to 4d
  const double tw = 0.5 * d3;
  const int rounds = join_rounds(ctx.p, cand.q);
  const bool mg_s = m.start.kind == EndKind::merge, mg_e = m.end.kind == EndKind::merge;
  std::vector<std::pair<std::size_t, std::size_t>> joins;
  const Points3& c3 = item.pts3;
  const auto& c2cum = item.proj.cum;

  if (m.type == MatchType::oversketch) {
    Points3 base = c3;
    std::vector<double> bcum = c2cum;
    double a = merge_middle(item.proj, m.start), b = merge_middle(item.proj, m.end);
    if (item.proj.closed) {
      // Rotate the loop so its seam lies in the middle of the part the
      // stroke does not touch; then it is an open over-sketch.
      const double l = c2cum.back();
      const double untouched = std::fmod(a - b + 2 * l, l);
      const double seam = std::fmod(b + 0.5 * untouched, l);
      const std::size_t si = index_at(c2cum, seam);
      Points3 ring(c3.begin(), c3.end() - 1);
      Points2 ring2(item.proj.pts.begin(), item.proj.pts.end() - 1);
      base.assign(ring.begin() + static_cast<std::ptrdiff_t>(si), ring.end());
      base.insert(base.end(), ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(si) + 1);
      Points2 b2(ring2.begin() + static_cast<std::ptrdiff_t>(si), ring2.end());
      b2.insert(b2.end(), ring2.begin(), ring2.begin() + static_cast<std::ptrdiff_t>(si) + 1);
      bcum = cumulative(b2);
      const double s0 = c2cum[si];
      a = std::fmod(a - s0 + 2 * l, l);
      b = std::fmod(b - s0 + 2 * l, l);
      a = std::min(a, bcum.back());
      b = std::min(b, bcum.back());
    }
    const std::size_t ks = index_at(bcum, a), ke = index_at(bcum, b);
    const std::size_t ms = index_at(cum, merge_mid_stroke(m.start));
    const std::size_t me = index_at(cum, merge_mid_stroke(m.end));
    const Splice p1 = splice(base, ks, s3, ms, radius, true, spacing, tw);
    const Splice p2 = splice(p1.pts, after_splice(p1, me), base, std::max(ke, ks), radius, true, spacing, tw);
    out.pts = p2.pts;
    out.closed = item.proj.closed;
    joins = {{p1.join_begin, p1.join_end}, {p2.join_begin, p2.join_end}};
    out.objectives = {p1.objective, p2.objective};
  } else if (m.type == MatchType::extend_close) {
    const std::size_t ks = index_at(c2cum, attach_curve_s(item.proj, m.start));
    const std::size_t ms = index_at(cum, attach_stroke_s(m.start));
    const std::size_t ke = index_at(c2cum, attach_curve_s(item.proj, m.end));
    const std::size_t me = index_at(cum, attach_stroke_s(m.end));
    const Splice p1 = splice(c3, ks, s3, ms, radius, mg_s, spacing, tw);
    const Splice p2 = close_splice(p1.pts, after_splice(p1, me), std::min(ke, p1.join_begin), radius,
                                   mg_e, spacing, tw);
    out.pts = p2.pts;
    out.closed = true;
    const std::size_t shift = p2.m;
    joins = {{p1.join_begin >= shift ? p1.join_begin - shift : 0, p1.join_end >= shift ? p1.join_end - shift : 0},
             {p2.join_begin, p2.join_end}};
    out.objectives = {p1.objective, p2.objective};
  } else {
    // extend / partial over-sketch from one end. From the start:
    // curve[..k] + H + stroke[m..]; from the end: stroke[..m] + H + curve[k..].
    const EndMatch& e = has_s ? m.start : m.end;
    const std::size_t k = index_at(c2cum, attach_curve_s(item.proj, e));
    const std::size_t ms = index_at(cum, attach_stroke_s(e));
    const Splice p1 = has_s ? splice(c3, k, s3, ms, radius, mg_s, spacing, tw)
                            : splice(s3, ms, c3, k, radius, mg_e, spacing, tw);
    out.pts = p1.pts;
    joins = {{p1.join_begin, p1.join_end}};
    out.objectives = {p1.objective};
  }
  smooth_joins(out.pts, joins, radius, spacing, rounds, out.closed);
  if (flip) out.pts = reversed(out.pts);
  return out;
}

Built apply_combine(const Candidate& cand, SceneItem a, SceneItem b, const Points2& s2, const Ctx& ctx) {
  Built out;
  const double d = ctx.d;
  EndMatch ms = cand.match.start, me = cand.match.end;
  // Orient a so the stroke leaves its end, b so the stroke enters its start.
  if (ms.dir < 0) {
    const double l = a.proj.length();
    a = reversed_item(std::move(a));
    ms = flipped(ms, l);
  }
  if (me.dir < 0) {
    const double l = b.proj.length();
    b = reversed_item(std::move(b));
    me = flipped(me, l);
  }
  const auto cum = cumulative(s2);
  const Plane plane = ctx.draw_plane ? Plane{a.pts3.back(), ctx.draw_plane->normal}
                                     : ctx.cam.film_plane(0.5 * (a.centroid + b.centroid));
  const auto za = curve_depths(ctx.cam, plane, a.pts3), zb = curve_depths(ctx.cam, plane, b.pts3);
  if (!za || !zb) {
    out.error = "curves cannot be given depths in this view";
    return out;
  }
  std::vector<std::optional<double>> known(s2.size());
  anchor_end(ms, false, s2, cum, a.proj, *za, d, known);
  anchor_end(me, true, s2, cum, b.proj, *zb, d, known);
  const auto lifted = lift(ctx.cam, plane, s2, fill_depths(cum, known, 0, 0), 2 + ctx.p.smoothing);
  if (!lifted) {
    out.error = "the stroke's rays miss the reference plane";
    return out;
  }
  const double d3 = d * ctx.cam.world_per_pixel(0.5 * (a.centroid + b.centroid));
  const double spacing = 0.1 * d3, radius = d3 * (1 + 3 * std::clamp(cand.q, 0.0, 1.0));
  const Splice p1 = splice(a.pts3, index_at(a.proj.cum, attach_curve_s(a.proj, ms)), *lifted,
                           index_at(cum, attach_stroke_s(ms)), radius, ms.kind == EndKind::merge,
                           spacing, 0.5 * d3);
  const Splice p2 = splice(p1.pts, after_splice(p1, index_at(cum, attach_stroke_s(me))), b.pts3,
                           index_at(b.proj.cum, attach_curve_s(b.proj, me)), radius,
                           me.kind == EndKind::merge, spacing, 0.5 * d3);
  out.pts = p2.pts;
  out.objectives = {p1.objective, p2.objective};
  smooth_joins(out.pts, {{p1.join_begin, p1.join_end}, {p2.join_begin, p2.join_end}}, radius,
               spacing, join_rounds(ctx.p, cand.q), false);
  return out;
}

void close_new_curve(Built& built, const Candidate& c, const std::vector<double>& cum, const Ctx& ctx) {
  const double d = ctx.d;
  const Vec3 mid = mean(built.pts);
  const double d3 = d * ctx.cam.world_per_pixel(mid);
  const double k0 = c.self.kind == EndKind::merge ? merge_mid_stroke(c.self) : c.self.stroke_s;
  // The stroke's head is open (no seam to wrap across).
  const double m0 = c.self.kind == EndKind::merge ? 0.5 * (c.self.curve_at_s0 + c.self.curve_at_s1) : c.self.curve_s;
  const Splice sp = close_splice(built.pts, index_at(cum, k0), index_at(cum, m0),
                                 d3 * (1 + 3 * std::clamp(c.q, 0.0, 1.0)),
                                 c.self.kind == EndKind::merge, 0.1 * d3, 0.5 * d3);
  built.pts = sp.pts;
  built.closed = true;
  built.objectives = {sp.objective};
  smooth_joins(built.pts, {{sp.join_begin, sp.join_end}}, d3, 0.1 * d3, join_rounds(ctx.p, c.q), true);
}

}  // namespace sketchlab::justdrawit
