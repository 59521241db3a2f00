#include "justdrawit_corrector.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "camera.hpp"
#include "choice.hpp"
#include "default_normals.hpp"
#include "drawing_surface.hpp"
#include "network_curves.hpp"
#include "promotion.hpp"
#include "scratch.hpp"
#include "stroke_curve_analysis.hpp"

namespace sketchlab::justdrawit {

namespace {

struct SceneItem {
  CurveId id = 0;
  Points3 pts3;
  Projected proj;
  Vec3 centroid = Vec3::Zero();
  double z_min = 0, z_max = 0;
};

struct Scene {
  std::vector<SceneItem> items;  // curves not culled, ascending id
  double Z_min = 0, Z_max = 0;   // eye depth range of the whole network
};

struct Ctx {
  const JdiParams& p;
  const Camera& cam;
  double d;
  std::optional<Plane> draw_plane;  // visible draw plane
};

std::size_t index_at(const std::vector<double>& cum, double s) {
  const auto it = std::lower_bound(cum.begin(), cum.end(), s);
  std::size_t i = static_cast<std::size_t>(it - cum.begin());
  if (i >= cum.size()) return cum.size() - 1;
  if (i > 0 && s - cum[i - 1] < cum[i] - s) --i;
  return i;
}

double interp(const std::vector<double>& cum, const std::vector<double>& v, double s) {
  if (v.size() == 1) return v[0];
  s = std::clamp(s, 0.0, cum.back());
  const auto it = std::upper_bound(cum.begin(), cum.end(), s);
  if (it == cum.end()) return v.back();
  const std::size_t i = static_cast<std::size_t>(it - cum.begin());
  if (i == 0) return v.front();
  const double seg = cum[i] - cum[i - 1];
  const double u = seg > 0 ? (s - cum[i - 1]) / seg : 0.0;
  return (1 - u) * v[i - 1] + u * v[i];
}

Points2 pixels(const Stroke& stroke) {
  Points2 out;
  out.reserve(stroke.samples.size());
  for (const Sample& s : stroke.samples) out.emplace_back(s.position.x(), s.position.y());
  return out;
}

Vec3 mean(const Points3& pts) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : pts) c += p;
  return pts.empty() ? c : Vec3(c / static_cast<double>(pts.size()));
}

// §4.5 bounding-box culling: curves whose projected box lies far outside the
// stroke's box are not analysed. The margin is 8d, not the paper's d: a join
// (eq. 2) reaches curve ends up to 8d away, and a d margin would cull them.
Scene build_scene(const Network& net, const Camera& cam, const Points2& stroke, double d,
                  bool cull) {
  Scene sc;
  Vec2 lo = stroke.front(), hi = stroke.front();
  for (const Vec2& p : stroke) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool first = true;
  for (const auto& [id, nc] : net.curves()) {
    const auto& cp = nc.curve.control_points;
    if (cp.empty()) continue;
    Box3 box;
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (const Vec3& q : cp) {
      box.extend(q);
      const double z = cam.eye_depth(q);
      zmin = std::min(zmin, z);
      zmax = std::max(zmax, z);
    }
    sc.Z_min = first ? zmin : std::min(sc.Z_min, zmin);
    sc.Z_max = first ? zmax : std::max(sc.Z_max, zmax);
    first = false;
    if (cull) {
      Vec2 blo(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
      Vec2 bhi = -blo;
      bool all = true;
      for (int c = 0; c < 8 && all; ++c) {
        Vec2 px;
        all = cam.to_pixel(box.corner(static_cast<Box3::CornerType>(c)), px);
        blo = blo.cwiseMin(px);
        bhi = bhi.cwiseMax(px);
      }
      const double m = 8 * d;
      if (all && (blo.x() > hi.x() + m || blo.y() > hi.y() + m || bhi.x() < lo.x() - m ||
                  bhi.y() < lo.y() - m))
        continue;
    }
    SceneItem it;
    it.id = id;
    it.pts3 = curve_points(nc.curve, 0.1 * d * cam.world_per_pixel(box.center()));
    Points2 p2;
    p2.reserve(it.pts3.size());
    bool visible = it.pts3.size() >= 2;
    for (const Vec3& q : it.pts3) {
      Vec2 px;
      if (!cam.to_pixel(q, px)) {
        visible = false;
        break;
      }
      p2.push_back(px);
    }
    if (!visible) continue;
    it.proj = make_projected(std::move(p2), nc.curve.closed);
    if (!(it.proj.length() > 0)) continue;
    it.centroid = mean(it.pts3);
    it.z_min = std::numeric_limits<double>::infinity();
    it.z_max = -it.z_min;
    for (const Vec3& q : it.pts3) {
      const double z = cam.eye_depth(q);
      it.z_min = std::min(it.z_min, z);
      it.z_max = std::max(it.z_max, z);
    }
    sc.items.push_back(std::move(it));
  }
  return sc;
}

EndMatch flipped(EndMatch m, double length) {
  m.dir = -m.dir;
  m.curve_at_s0 = length - m.curve_at_s0;
  m.curve_at_s1 = length - m.curve_at_s1;
  m.curve_s = length - m.curve_s;
  m.at_curve_start = !m.at_curve_start;
  return m;
}

SceneItem reversed_item(SceneItem it) {
  it.pts3 = reversed(it.pts3);
  it.proj = make_projected(reversed(it.proj.pts), it.proj.closed);
  return it;
}

double merge_mid_curve(const EndMatch& m) { return 0.5 * (m.curve_at_s0 + m.curve_at_s1); }
double merge_mid_stroke(const EndMatch& m) { return 0.5 * (m.stroke_s0 + m.stroke_s1); }
double attach_curve_s(const EndMatch& m) { return m.kind == EndKind::merge ? merge_mid_curve(m) : m.curve_s; }
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

struct Built {
  Points3 pts;
  bool closed = false;
  std::vector<double> objectives;  // one per join
  std::string error;
};

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
    const double s = has_s ? attach_curve_s(m.start) : attach_curve_s(m.end);
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
    double a = merge_mid_curve(m.start), b = merge_mid_curve(m.end);
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
    const std::size_t ks = index_at(c2cum, attach_curve_s(m.start));
    const std::size_t ms = index_at(cum, attach_stroke_s(m.start));
    const std::size_t ke = index_at(c2cum, attach_curve_s(m.end));
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
  } else if (has_s) {
    // extend / partial over-sketch from the start: curve[..k] + H + stroke[m..].
    const std::size_t ks = index_at(c2cum, attach_curve_s(m.start));
    const std::size_t ms = index_at(cum, attach_stroke_s(m.start));
    const Splice p1 = splice(c3, ks, s3, ms, radius, mg_s, spacing, tw);
    out.pts = p1.pts;
    joins = {{p1.join_begin, p1.join_end}};
    out.objectives = {p1.objective};
  } else {
    // From the end: stroke[..m] + H + curve[k..].
    const std::size_t ke = index_at(c2cum, attach_curve_s(m.end));
    const std::size_t me = index_at(cum, attach_stroke_s(m.end));
    const Splice p1 = splice(s3, me, c3, ke, radius, mg_e, spacing, tw);
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
  const Splice p1 = splice(a.pts3, index_at(a.proj.cum, attach_curve_s(ms)), *lifted,
                           index_at(cum, attach_stroke_s(ms)), radius, ms.kind == EndKind::merge,
                           spacing, 0.5 * d3);
  const Splice p2 = splice(p1.pts, after_splice(p1, index_at(cum, attach_stroke_s(me))), b.pts3,
                           index_at(b.proj.cum, attach_curve_s(me)), radius,
                           me.kind == EndKind::merge, spacing, 0.5 * d3);
  out.pts = p2.pts;
  out.objectives = {p1.objective, p2.objective};
  smooth_joins(out.pts, {{p1.join_begin, p1.join_end}, {p2.join_begin, p2.join_end}}, radius,
               spacing, join_rounds(ctx.p, cand.q), false);
  return out;
}

const NetworkCurve* resolve_curve(const Network& net, std::int64_t id, CurveId last) {
  if (id > 0) return net.find_curve(static_cast<CurveId>(id));
  return last ? net.find_curve(last) : nullptr;
}

// The draw plane placed from curves (§5.1), or the explicit one.
Plane draw_plane_from(const JdiParams& p, const Network& net, CurveId last) {
  if (p.plane_from == PlaneFrom::explicit_plane) return {p.plane_origin, p.plane_normal};
  const NetworkCurve* c1 = resolve_curve(net, p.plane_curve, last);
  if (!c1) return {p.plane_origin, p.plane_normal};
  const Points3 a = curve_points(c1->curve, 1e-3);
  const auto ca = cumulative(a);
  const double sa = p.plane_at * ca.back();
  const Vec3 pa = point_at(a, ca, sa), ta = tangent_at(a, ca, sa, 0.02 * ca.back());
  if (p.plane_from == PlaneFrom::two_points) {
    const NetworkCurve* c2 = resolve_curve(net, p.plane_curve2, 0);
    if (!c2) return plane_at_point(pa, ta);
    const Points3 b = curve_points(c2->curve, 1e-3);
    const auto cb = cumulative(b);
    const double sb = p.plane_at2 * cb.back();
    return plane_through_two_points(pa, ta, point_at(b, cb, sb), tangent_at(b, cb, sb, 0.02 * cb.back()));
  }
  if (p.plane_from == PlaneFrom::curve_tangent) return plane_at_point(pa, ta);
  const PlaneFit fit = fit_plane(a);
  const auto normals = default_normals(a, c1->curve.closed, {}, 0.01 * (a.empty() ? 1.0 : length(a)),
                                       fit.normal);
  const Vec3 n = normals[index_at(ca, sa)];
  return plane_at_point(pa, p.plane_from == PlaneFrom::curve_normal ? n : Vec3(ta.cross(n)));
}

// The latest two guide-layer 2D strokes before `id` (left then right).
std::vector<const Stroke*> guide_strokes(const Sketch& sketch, StrokeId id) {
  std::vector<const Stroke*> out;
  for (auto it = sketch.strokes.rbegin(); it != sketch.strokes.rend() && out.size() < 2; ++it)
    if (it->first < id && it->second.layer == Layer::guide && it->second.is_2d())
      out.insert(out.begin(), &it->second);
  return out;
}

// §5.1: depth for a new curve from the active drawing surface.
std::optional<Points3> place_new(const Points2& s2, const Stroke& stroke, const Sketch& sketch,
                                 const Network& net, CurveId last, const Ctx& ctx,
                                 std::string& surface_used) {
  const Plane view_plane = ctx.cam.film_plane(ctx.p.plane_origin);
  const std::vector<double> zeros(s2.size(), 0.0);
  if (ctx.draw_plane) {
    surface_used = "draw_plane";
    if (auto pts = lift(ctx.cam, *ctx.draw_plane, s2, zeros, 0)) return pts;
  } else if (ctx.p.surface == SurfaceKind::extrusion) {
    if (const NetworkCurve* c = resolve_curve(net, ctx.p.extrusion_curve, last)) {
      const Points3 pts = curve_points(c->curve, 1e-3);
      Box3 box;
      for (const Vec3& q : pts) box.extend(q);
      const TriangleMesh mesh = extrusion_surface(pts, ctx.p.extrusion_direction,
                                                  std::max(1.0, 4 * box.diagonal().norm()));
      const Plane ref = ctx.cam.film_plane(mean(pts));
      if (auto z = surface_depths(ctx.cam, ref, s2, mesh)) {
        surface_used = "extrusion";
        return lift(ctx.cam, ref, s2, *z, 0);
      }
    }
  } else if (ctx.p.surface == SurfaceKind::inflation) {
    const auto guides = guide_strokes(sketch, stroke.id);
    if (guides.size() == 2) {
      std::vector<Points3> sides;
      Vec3 towards = -ctx.cam.forward();
      for (const Stroke* g : guides) {
        const Camera gc(*g->view);
        const Points2 g2 = resample(dedupe(pixels(*g), 1e-9), 0.1 * ctx.d);
        if (g2.size() < 2) break;
        const Scene all = build_scene(net, gc, g2, ctx.d, false);
        std::vector<SceneCurve> curves;
        for (const SceneItem& it : all.items) curves.push_back({it.pts3, it.proj.pts});
        auto t = temporary_curve(gc, g2, curves, gc.film_plane(ctx.p.plane_origin), ctx.d);
        if (!t) break;
        sides.push_back(std::move(*t));
        towards = -gc.forward();
      }
      if (sides.size() == 2) {
        const TriangleMesh mesh = inflation_surface(sides[0], sides[1], towards);
        const Plane ref = ctx.cam.film_plane(0.5 * (mean(sides[0]) + mean(sides[1])));
        if (auto z = surface_depths(ctx.cam, ref, s2, mesh)) {
          surface_used = "inflation";
          return lift(ctx.cam, ref, s2, *z, 0);
        }
      }
    }
  }
  surface_used = "view_plane";
  return lift(ctx.cam, view_plane, s2, zeros, 0);
}

// Default normals (§6) sampled along the curve, with pins at nodes.
std::vector<CurveNormal> export_normals(const Points3& pts, bool closed, CurveId id,
                                        const Network& net, const std::vector<Node>& nodes,
                                        const Vec3& fallback) {
  std::vector<NormalPin> pins;
  for (const Node& n : nodes) {
    const NodeIncidence* mine = nullptr;
    const NodeIncidence* other = nullptr;
    for (const NodeIncidence& inc : n.incidences) {
      if (inc.curve == id && !mine) mine = &inc;
      else if (inc.curve != id && !other) other = &inc;
    }
    if (!mine || !other) continue;
    const NetworkCurve* oc = net.find_curve(other->curve);
    if (!oc) continue;
    const Points3 op = curve_points(oc->curve, 1e-3);
    const auto ia = static_cast<std::size_t>(std::clamp(std::lround(mine->t), 0L, static_cast<long>(pts.size()) - 1));
    const auto oc_cum = cumulative(op);
    const auto pr = project(op, oc_cum, n.position);
    pins.push_back({ia, pin_normal(pts, ia, op, pr.index)});
  }
  Box3 box;
  for (const Vec3& q : pts) box.extend(q);
  const auto normals = default_normals(pts, closed, pins, 0.01 * box.diagonal().norm(), fallback);
  std::vector<CurveNormal> out;
  const std::size_t step = std::max<std::size_t>(1, pts.size() / 64);
  for (std::size_t i = 0; i < pts.size(); i += step) out.push_back({static_cast<double>(i), normals[i]});
  if ((pts.size() - 1) % step != 0) out.push_back({static_cast<double>(pts.size() - 1), normals.back()});
  return out;
}

struct Outcome {
  Edit edit;
  std::vector<Constraint> constraints;
  CorrectionStats stats;
  std::string error;
};

CurveId last_edited_curve(const std::vector<HistoryEntry>& done, std::size_t count) {
  for (std::size_t k = count; k-- > 0;) {
    const HistoryEntry& e = done[k];
    if (e.action != "stroke") continue;
    for (const HistoryStep& s : e.steps) {
      if (!s.forward.curves_replaced.empty()) return s.forward.curves_replaced.front().id;
      if (!s.forward.curves_added.empty()) return s.forward.curves_added.front().id;
    }
    return 0;
  }
  return 0;
}

// The analysis, choice and application for a prepared stroke on `net`.
Outcome process(const Points2& s2, const Stroke& stroke, const Sketch& sketch, const Network& net,
                CurveId last, const Ctx& ctx) {
  Outcome o;
  const double d = ctx.d;
  const Scene scene = build_scene(net, ctx.cam, s2, d, true);
  const auto cum = cumulative(s2);
  std::vector<Candidate> cands;
  struct Ends {
    EndMatch s, e;
  };
  std::vector<Ends> ends(scene.items.size());
  for (std::size_t i = 0; i < scene.items.size(); ++i) {
    const SceneItem& it = scene.items[i];
    // Nothing behind a visible draw plane (§4.3).
    if (ctx.draw_plane) {
      bool behind = true;
      for (const Vec3& q : it.pts3) {
        const auto z = plane_depth(ctx.cam, *ctx.draw_plane, q);
        if (!z || *z <= 0) {
          behind = false;
          break;
        }
      }
      if (behind) continue;
    }
    ends[i].s = classify_end(s2, cum, it.proj, false, d);
    ends[i].e = classify_end(s2, cum, it.proj, true, d);
    const auto m = match_type(ends[i].s, ends[i].e, it.proj, d);
    if (!m) continue;
    Candidate c;
    c.curve = it.id;
    c.match = *m;
    c.decision = m->type == MatchType::oversketch       ? Decision::oversketch
                 : m->type == MatchType::extend         ? Decision::extend
                 : m->type == MatchType::extend_close   ? Decision::extend_close
                                                        : Decision::partial_oversketch;
    const bool join = m->start.kind == EndKind::join || m->end.kind == EndKind::join;
    c.q_m = m->q_m;
    c.q_d = depth_score(it.z_min, it.z_max, scene.Z_min, scene.Z_max, m->type == MatchType::oversketch, join);
    c.q = final_score(c.q_d, c.q_m);
    cands.push_back(c);
  }
  // Combining two curves (§4.3 (2)): the stroke leaves one curve's end and
  // enters another's.
  auto attaches = [](const EndMatch& m) {
    return m.kind == EndKind::join || (m.kind == EndKind::merge && m.overhang);
  };
  for (std::size_t i = 0; i < scene.items.size(); ++i) {
    if (!attaches(ends[i].s) || scene.items[i].proj.closed) continue;
    for (std::size_t j = 0; j < scene.items.size(); ++j) {
      if (j == i || !attaches(ends[j].e) || scene.items[j].proj.closed) continue;
      Candidate c;
      c.decision = Decision::combine;
      c.curve = scene.items[i].id;
      c.curve2 = scene.items[j].id;
      c.match.start = ends[i].s;
      c.match.end = ends[j].e;
      c.q_m = 0.5 * (ends[i].s.score + ends[j].e.score);
      const auto qd = [&](const SceneItem& it, const EndMatch& m) {
        return depth_score(it.z_min, it.z_max, scene.Z_min, scene.Z_max, false, m.kind == EndKind::join);
      };
      c.q_d = 0.5 * (qd(scene.items[i], ends[i].s) + qd(scene.items[j], ends[j].e));
      c.q = final_score(c.q_d, c.q_m);
      cands.push_back(c);
    }
  }
  std::optional<EndMatch> self = closes_on_itself(s2, d);
  if (self) {
    Candidate c;
    c.decision = Decision::new_closed_curve;
    c.self = *self;
    c.q_m = self->score;
    c.q = final_score(0, c.q_m);
    cands.push_back(c);
  }
  const int chosen = choose(cands, last);
  o.stats.extra["candidates"] = static_cast<double>(cands.size());
  o.stats.extra["curves_analysed"] = static_cast<double>(scene.items.size());
  // Runners-up by score.
  std::vector<int> order(cands.size());
  for (std::size_t i = 0; i < cands.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cands[a].q < cands[b].q; });
  int rank = 0;
  for (int i : order) {
    if (i == chosen || rank >= 3) continue;
    ++rank;
    const std::string k = "runner_up_" + std::to_string(rank) + "_";
    o.stats.extra[k + "decision"] = static_cast<double>(cands[i].decision);
    o.stats.extra[k + "score"] = cands[i].q;
    o.stats.extra[k + "curve"] = static_cast<double>(cands[i].curve);
  }

  const SceneItem* item_a = nullptr;
  const SceneItem* item_b = nullptr;
  auto find_item = [&](CurveId id) -> const SceneItem* {
    for (const SceneItem& it : scene.items)
      if (it.id == id) return &it;
    return nullptr;
  };
  Built built;
  Decision decision = Decision::new_curve;
  double score = 0;
  std::string surface_used;
  if (chosen >= 0 && cands[chosen].decision != Decision::new_closed_curve) {
    const Candidate& c = cands[chosen];
    decision = c.decision;
    score = c.q;
    item_a = find_item(c.curve);
    if (c.decision == Decision::combine) {
      item_b = find_item(c.curve2);
      built = apply_combine(c, *item_a, *item_b, s2, ctx);
    } else {
      built = apply_single(c, *item_a, s2, ctx);
    }
  }
  if (chosen < 0 || cands[chosen].decision == Decision::new_closed_curve || !built.error.empty()) {
    if (!built.error.empty()) o.stats.extra["fallback_to_new_curve"] = 1;
    item_a = item_b = nullptr;
    auto placed = place_new(s2, stroke, sketch, net, last, ctx, surface_used);
    if (!placed) {
      o.error = "stroke " + std::to_string(stroke.id) + ": no drawing surface under the stroke";
      return o;
    }
    built = Built{};
    built.pts = std::move(*placed);
    decision = Decision::new_curve;
    if (chosen >= 0 && cands[chosen].decision == Decision::new_closed_curve) {
      const Candidate& c = cands[chosen];
      decision = Decision::new_closed_curve;
      score = c.q;
      const Vec3 mid = mean(built.pts);
      const double d3 = d * ctx.cam.world_per_pixel(mid);
      const double k0 = c.self.kind == EndKind::merge ? merge_mid_stroke(c.self) : c.self.stroke_s;
      const double m0 = c.self.kind == EndKind::merge ? merge_mid_curve(c.self) : c.self.curve_s;
      const Splice sp = close_splice(built.pts, index_at(cum, k0), index_at(cum, m0),
                                     d3 * (1 + 3 * std::clamp(c.q, 0.0, 1.0)),
                                     c.self.kind == EndKind::merge, 0.1 * d3, 0.5 * d3);
      built.pts = sp.pts;
      built.closed = true;
      built.objectives = {sp.objective};
      smooth_joins(built.pts, {{sp.join_begin, sp.join_end}}, d3, 0.1 * d3, join_rounds(ctx.p, c.q), true);
    }
  }
  o.stats.extra["decision"] = static_cast<double>(decision);
  o.stats.extra["score"] = score;
  if (item_a) o.stats.extra["curve"] = static_cast<double>(item_a->id);

  // The edit: a new curve, or the replacement of one curve (and removal of
  // the second when two are combined).
  NetworkCurve nc;
  nc.curve = polyline_curve(built.pts, built.closed);
  nc.layer = stroke.layer == Layer::automatic ? Layer::free : stroke.layer;
  nc.source_stroke = stroke.id;
  if (item_a) {
    const NetworkCurve* old = net.find_curve(item_a->id);
    nc.id = old->id;
    nc.layer = old->layer;
  } else {
    nc.id = net.next_curve_id();
  }
  nc.keypoints = default_keypoints(nc.curve);
  const Points3 final_pts = curve_points(nc.curve, 1.0);
  std::vector<Node> kept_nodes;
  if (item_a) {
    // Nodes on the edited curves follow the new curve when still on it
    // (within d3), else lose that incidence; patches on them are dropped.
    const double d3 = d * ctx.cam.world_per_pixel(item_a->centroid);
    const auto fcum = cumulative(final_pts);
    std::set<NodeId> seen;
    for (CurveId cid : {item_a->id, item_b ? item_b->id : CurveId{0}}) {
      if (!cid) continue;
      for (PatchId pid : net.patches_on(cid))
        if (std::find(o.edit.patches_removed.begin(), o.edit.patches_removed.end(), pid) ==
            o.edit.patches_removed.end())
          o.edit.patches_removed.push_back(pid);
    }
    for (const auto& [nid, node] : net.nodes()) {
      bool touches = false;
      for (const NodeIncidence& inc : node.incidences)
        touches = touches || inc.curve == item_a->id || (item_b && inc.curve == item_b->id);
      if (!touches) continue;
      Node n = node;
      n.incidences.clear();
      bool on_new = false;
      for (const NodeIncidence& inc : node.incidences) {
        if (item_b && inc.curve == item_b->id) continue;
        if (inc.curve == item_a->id) {
          if (on_new) continue;
          const auto pr = project(final_pts, fcum, node.position);
          if (pr.distance > d3) continue;
          on_new = true;
          n.incidences.push_back({nc.id, static_cast<double>(pr.index) + pr.u});
          continue;
        }
        n.incidences.push_back(inc);
      }
      if (n.incidences.empty()) o.edit.nodes_removed.push_back(nid);
      else {
        o.edit.nodes_replaced.push_back(n);
        kept_nodes.push_back(n);
      }
    }
    std::sort(o.edit.patches_removed.begin(), o.edit.patches_removed.end());
  }
  if (ctx.p.normals) {
    const Vec3 fallback = -ctx.cam.forward();
    nc.normals = export_normals(final_pts, nc.curve.closed, nc.id, net, kept_nodes, fallback);
  }
  if (item_a) o.edit.curves_replaced.push_back(nc);
  else o.edit.curves_added.push_back(nc);
  if (item_b) o.edit.curves_removed.push_back(item_b->id);

  // What was considered: the joins (tangent continuity, objective as the
  // residual angle), closure, and the drawing surface.
  const std::vector<CurveId> targets{item_a ? item_a->id : CurveId{0}, item_b ? item_b->id : CurveId{0}};
  for (std::size_t j = 0; j < built.objectives.size(); ++j) {
    Constraint c;
    c.kind = ConstraintKind::tangent;
    c.references.push_back({ConstraintRef::Kind::stroke, stroke.id, 0.0});
    const CurveId t = decision == Decision::combine && j == 1 ? targets[1] : targets[0];
    c.references.push_back({ConstraintRef::Kind::curve, t ? t : nc.id, 0.0});
    c.enforced = true;
    c.residual = built.objectives[j];
    o.constraints.push_back(c);
  }
  if (nc.curve.closed) {
    Constraint c;
    c.kind = ConstraintKind::closure;
    c.references.push_back({ConstraintRef::Kind::curve, nc.id, 0.0});
    c.enforced = true;
    c.residual = (nc.curve.control_points.front() - nc.curve.control_points.back()).norm();
    o.constraints.push_back(c);
  }
  if (!surface_used.empty()) {
    Constraint c;
    c.kind = ConstraintKind::on_surface;
    c.references.push_back({ConstraintRef::Kind::stroke, stroke.id, 0.0});
    c.enforced = true;
    o.constraints.push_back(c);
    o.stats.extra["surface"] = surface_used == "view_plane"   ? 0
                               : surface_used == "draw_plane" ? 1
                               : surface_used == "extrusion"  ? 2
                                                              : 3;
  }
  return o;
}

}  // namespace

Points2 prepare_stroke(const Stroke& stroke, const JdiParams& p) {
  Points2 pts = dedupe(pixels(stroke), 1e-9);
  if (pts.size() < 2 || !(length(pts) > 1e-6)) return pts;
  // §4.5: at least 10 samples per d, then N rounds of smoothing.
  pts = resample(pts, 0.1 * p.d);
  smooth(pts, p.smoothing);
  if (p.scratch) {
    pts = unfold_stroke(pts, p.d);
    if (pts.size() >= 2 && length(pts) > 1e-6) pts = resample(pts, 0.1 * p.d);
  }
  return pts;
}

Correction justdrawit_correct(const Stroke& stroke, const Sketch& sketch, const JdiParams& p) {
  Correction out;
  if (!stroke.is_2d()) {
    out.error = "stroke " + std::to_string(stroke.id) +
                ": JustDrawIt needs 2D strokes (pixels plus a View); this stroke is 3D";
    return out;
  }
  const Camera cam(*stroke.view);
  Points2 s2 = prepare_stroke(stroke, p);
  if (s2.size() < 2 || !(length(s2) > 1e-6)) {
    out.error = "stroke " + std::to_string(stroke.id) + " has zero length";
    return out;
  }
  if (p.surface == SurfaceKind::inflation && stroke.layer == Layer::guide) {
    // Guide strokes only define the inflation surface (§5.1).
    out.stats.extra["guide"] = 1;
    return out;
  }
  std::optional<Plane> draw_plane;
  const auto& done = sketch.history.done;

  // §4.1 / §4.3 (4): a stroke overlapping the previous stroke(s) by > 90 % is
  // blended with them; the result replaces what they did.
  std::size_t keep = done.size();
  std::vector<Points2> chain;
  while (keep > 0 && chain.size() < 8) {
    const HistoryEntry& e = done[keep - 1];
    if (e.action != "stroke" || !e.stroke) break;
    const auto it = sketch.strokes.find(*e.stroke);
    if (it == sketch.strokes.end() || !it->second.is_2d() || !(*it->second.view == *stroke.view))
      break;
    Points2 prev = prepare_stroke(it->second, p);
    if (prev.size() < 2 || overlap_fraction(s2, prev, p.d) <= 0.9) break;
    chain.push_back(std::move(prev));
    --keep;
  }
  const CurveId last = last_edited_curve(done, keep);
  Network base;
  const Network* net = &sketch.network;
  if (!chain.empty()) {
    base = sketch.network;
    for (std::size_t k = done.size(); k-- > keep;)
      for (auto st = done[k].steps.rbegin(); st != done[k].steps.rend(); ++st) base.apply(st->inverse);
    std::vector<Points2> sections(chain.rbegin(), chain.rend());
    sections.push_back(s2);
    s2 = resample(blend_sections(std::move(sections), p.d), 0.1 * p.d);
    net = &base;
  }
  if (stroke.draw_plane) {
    const Vec4& pl = *stroke.draw_plane;
    draw_plane = Plane{pl[3] * pl.head<3>(), pl.head<3>().normalized()};
  } else if (p.surface == SurfaceKind::draw_plane) {
    draw_plane = draw_plane_from(p, *net, last);
  }
  const Ctx ctx{p, cam, p.d, draw_plane};
  Outcome o = process(s2, stroke, sketch, *net, last, ctx);
  if (!o.error.empty()) {
    out.error = o.error;
    return out;
  }
  o.stats.extra["blended_strokes"] = static_cast<double>(chain.size());
  if (!chain.empty()) {
    Network next = base;
    next.apply(o.edit);
    o.edit = edit_between(sketch.network, next);
  }
  out.edit = std::move(o.edit);
  out.constraints = std::move(o.constraints);
  out.stats = std::move(o.stats);
  return out;
}

}  // namespace sketchlab::justdrawit
