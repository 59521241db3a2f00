#include "promotion.hpp"

#include <cmath>

namespace sketchlab::justdrawit {

std::vector<double> fill_depths(const std::vector<double>& cum2,
                                const std::vector<std::optional<double>>& known,
                                double slope_before, double slope_after) {
  const std::size_t n = known.size();
  std::vector<double> z(n, 0.0);
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < n; ++i)
    if (known[i]) idx.push_back(i);
  if (idx.empty()) return z;
  for (std::size_t i = 0; i < idx.front(); ++i)
    z[i] = *known[idx.front()] + slope_before * (cum2[idx.front()] - cum2[i]);
  for (std::size_t i = idx.back() + 1; i < n; ++i)
    z[i] = *known[idx.back()] + slope_after * (cum2[i] - cum2[idx.back()]);
  for (std::size_t a = 0; a < idx.size(); ++a) {
    z[idx[a]] = *known[idx[a]];
    if (a + 1 == idx.size()) break;
    const std::size_t i0 = idx[a], i1 = idx[a + 1];
    const double span = cum2[i1] - cum2[i0];
    for (std::size_t i = i0 + 1; i < i1; ++i) {
      const double u = span > 0 ? (cum2[i] - cum2[i0]) / span : 0.5;
      z[i] = (1 - u) * *known[i0] + u * *known[i1];
    }
  }
  return z;
}

double depth_slope(const std::vector<double>& cum2, const std::vector<double>& depth, double from,
                   double to) {
  if (cum2.size() < 2 || std::abs(to - from) < 1e-9) return 0.0;
  const double span = std::abs(to - from);
  return (interp(cum2, depth, to) - interp(cum2, depth, from)) / span;
}

std::optional<Points3> lift(const Camera& cam, const Plane& plane, const Points2& stroke,
                            const std::vector<double>& depth, int rounds) {
  Points3 pts;
  std::vector<Ray> rays;
  pts.reserve(stroke.size());
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    const Ray r = cam.ray(stroke[i]);
    const auto q = intersect(r, plane);
    if (!q) return std::nullopt;
    pts.push_back(*q + depth[i] * r.direction);
    rays.push_back(r);
  }
  // Smooth the 3D points, then put each back on its ray (§4.5): the stroke
  // still projects onto the pixels the user drew.
  for (int k = 0; k < rounds; ++k) {
    smooth_round(pts, 0, pts.size() - 1, false);
    for (std::size_t i = 0; i < pts.size(); ++i)
      pts[i] = rays[i].origin + (pts[i] - rays[i].origin).dot(rays[i].direction) * rays[i].direction;
  }
  return pts;
}

namespace {

Vec3 forward_tangent(const Points3& p, const std::vector<double>& cum, std::size_t i, double w) {
  return tangent_at(p, cum, cum[i], w);
}

std::vector<std::size_t> near_indices(const std::vector<double>& cum, std::size_t i0, double radius,
                                      std::size_t lo, std::size_t hi) {
  // At most ~24 candidates per side keeps the pair search O(600).
  std::vector<std::size_t> all;
  for (std::size_t i = lo; i <= hi; ++i)
    if (std::abs(cum[i] - cum[i0]) <= radius) all.push_back(i);
  if (all.empty()) all.push_back(std::clamp(i0, lo, hi));
  const std::size_t stride = std::max<std::size_t>(1, all.size() / 24);
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < all.size(); k += stride) out.push_back(all[k]);
  if (out.back() != all.back()) out.push_back(all.back());
  return out;
}

struct Pick {
  std::size_t k = 0, m = 0;
  double objective = std::numeric_limits<double>::infinity();
  Vec3 tk, tm;
};

Pick search(const Points3& a, const std::vector<double>& ca, const std::vector<std::size_t>& ks,
            const Points3& b, const std::vector<double>& cb, const std::vector<std::size_t>& ms,
            bool merge, double w, bool same_list) {
  Pick best;
  for (std::size_t k : ks) {
    const Vec3 tk = forward_tangent(a, ca, k, w);
    for (std::size_t m : ms) {
      if (same_list && m + 2 >= k) continue;
      const Vec3 chord = b[m] - a[k];
      const double len = chord.norm();
      if (!(len > 1e-12)) continue;
      const Vec3 v = chord / len;
      const Vec3 tm = forward_tangent(b, cb, m, w);
      const double ac = clamp_angle(tk.dot(v)), as = clamp_angle(tm.dot(v));
      const double ad = 0.5 * std::abs(ac - as), at = ac + as;
      // §4.4.2 objective: 0.8 α_d + 0.2 α_t for a merge, 0.2/0.8 for a join.
      const double f = merge ? 0.8 * ad + 0.2 * at : 0.2 * ad + 0.8 * at;
      if (f < best.objective) best = {k, m, f, tk, tm};
    }
  }
  return best;
}

Points3 hermite3(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1, double spacing) {
  const Vec3 chord = p1 - p0;
  const double len = chord.norm();
  const Vec3 v = len > 0 ? Vec3(chord / len) : Vec3::Zero();
  // Zig-zag (§4.4.2): the tangents sit on opposite sides of the chord.
  const bool zigzag = v.cross(t1).dot(v.cross(t0)) < 0;
  const double scale = (zigzag ? 0.5 : 1.5) * len;
  const Vec3 m0 = scale * t0, m1 = scale * t1;
  const int n = std::max(2, static_cast<int>(std::ceil(len / std::max(spacing, 1e-12))));
  Points3 out;
  for (int i = 1; i < n; ++i) {
    const double t = static_cast<double>(i) / n, t2 = t * t, t3 = t2 * t;
    out.push_back((2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
                  (t3 - t2) * m1);
  }
  return out;
}

}  // namespace

Splice splice(const Points3& head, std::size_t k0, const Points3& tail, std::size_t m0,
              double radius, bool merge, double spacing, double tangent_window) {
  const auto ch = cumulative(head), ct = cumulative(tail);
  k0 = std::min(k0, head.size() - 1);
  m0 = std::min(m0, tail.size() - 1);
  const auto ks = near_indices(ch, k0, radius, 0, head.size() - 1);
  const auto ms = near_indices(ct, m0, radius, 0, tail.size() - 1);
  Pick p = search(head, ch, ks, tail, ct, ms, merge, tangent_window, false);
  if (!std::isfinite(p.objective)) {
    p.k = k0;
    p.m = m0;
    p.objective = 0;
    p.tk = forward_tangent(head, ch, k0, tangent_window);
    p.tm = forward_tangent(tail, ct, m0, tangent_window);
  }
  Splice s;
  s.k = p.k;
  s.m = p.m;
  s.objective = p.objective;
  s.pts.assign(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(p.k) + 1);
  s.join_begin = s.pts.size() - 1;
  if ((tail[p.m] - head[p.k]).norm() > 1e-12) {
    const Points3 h = hermite3(head[p.k], p.tk, tail[p.m], p.tm, spacing);
    s.pts.insert(s.pts.end(), h.begin(), h.end());
    s.join_end = s.pts.size();  // tail[m]
    s.pts.insert(s.pts.end(), tail.begin() + static_cast<std::ptrdiff_t>(p.m), tail.end());
  } else {
    s.join_end = s.join_begin;
    s.pts.insert(s.pts.end(), tail.begin() + static_cast<std::ptrdiff_t>(p.m) + 1, tail.end());
  }
  return s;
}

Splice close_splice(const Points3& pts, std::size_t k0, std::size_t m0, double radius, bool merge,
                    double spacing, double tangent_window) {
  const auto c = cumulative(pts);
  k0 = std::min(k0, pts.size() - 1);
  m0 = std::min(m0, k0);
  const auto ks = near_indices(c, k0, radius, 0, pts.size() - 1);
  const auto ms = near_indices(c, m0, radius, 0, pts.size() - 1);
  Pick p = search(pts, c, ks, pts, c, ms, merge, tangent_window, true);
  if (!std::isfinite(p.objective)) {
    p.k = pts.size() - 1;
    p.m = 0;
    p.objective = 0;
    p.tk = forward_tangent(pts, c, p.k, tangent_window);
    p.tm = forward_tangent(pts, c, p.m, tangent_window);
  }
  Splice s;
  s.k = p.k;
  s.m = p.m;
  s.objective = p.objective;
  s.pts.assign(pts.begin() + static_cast<std::ptrdiff_t>(p.m),
               pts.begin() + static_cast<std::ptrdiff_t>(p.k) + 1);
  s.join_begin = s.pts.size() - 1;
  const Points3 h = hermite3(pts[p.k], p.tk, pts[p.m], p.tm, spacing);
  s.pts.insert(s.pts.end(), h.begin(), h.end());
  s.pts.push_back(s.pts.front());
  s.join_end = s.pts.size() - 1;
  return s;
}

void smooth_join(Points3& pts, std::size_t first, std::size_t last, std::size_t margin, int rounds,
                 bool closed) {
  if (pts.size() < 3) return;
  const std::size_t n = pts.size();
  if (closed) {
    // Smooth cyclically: the seam point is shared by both ends.
    Points3 ring(pts.begin(), pts.end() - 1);
    const std::size_t r = ring.size();
    const std::size_t lo = first + r - std::min(margin, r), hi = last + margin;
    for (int k = 0; k < rounds; ++k) {
      const Points3 old = ring;
      for (std::size_t j = lo; j <= hi && j - lo < r; ++j) {
        const std::size_t i = j % r;
        ring[i] = old[i] + 0.2 * (0.5 * (old[(i + r - 1) % r] + old[(i + 1) % r]) - old[i]);
      }
    }
    ring.push_back(ring.front());
    pts = std::move(ring);
    return;
  }
  const std::size_t lo = first > margin ? first - margin : 0;
  const std::size_t hi = std::min(n - 1, last + margin);
  for (int k = 0; k < rounds; ++k) smooth_round(pts, lo, hi, false);
}

}  // namespace sketchlab::justdrawit
