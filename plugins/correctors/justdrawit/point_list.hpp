#pragma once
// JustDrawIt stores strokes and curves as plain point lists (§4
// "Representation"): 2D lists in pixels, 3D lists in metres. These helpers
// work on both (P = Vec2 or Vec3).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::justdrawit {

using Points2 = std::vector<Vec2>;
using Points3 = std::vector<Vec3>;

// Cumulative arclength at each point (first 0).
template <class P>
std::vector<double> cumulative(const std::vector<P>& pts) {
  std::vector<double> s(pts.size(), 0.0);
  for (std::size_t i = 1; i < pts.size(); ++i) s[i] = s[i - 1] + (pts[i] - pts[i - 1]).norm();
  return s;
}

template <class P>
double length(const std::vector<P>& pts) {
  double l = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) l += (pts[i] - pts[i - 1]).norm();
  return l;
}

// Point at arclength s (clamped to [0, length]); `cum` is cumulative(pts).
template <class P>
P point_at(const std::vector<P>& pts, const std::vector<double>& cum, double s) {
  if (pts.size() == 1 || s <= 0) return pts.front();
  if (s >= cum.back()) return pts.back();
  const auto it = std::upper_bound(cum.begin(), cum.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - cum.begin());
  const double seg = cum[i] - cum[i - 1];
  const double u = seg > 0 ? (s - cum[i - 1]) / seg : 0.0;
  return pts[i - 1] + u * (pts[i] - pts[i - 1]);
}

// Drops points closer than `eps` to their predecessor (zero-length steps
// have no tangent).
template <class P>
std::vector<P> dedupe(const std::vector<P>& pts, double eps) {
  std::vector<P> out;
  for (const P& p : pts)
    if (out.empty() || (p - out.back()).norm() > eps) out.push_back(p);
  if (out.size() == 1 && pts.size() > 1) out.push_back(pts.back());
  return out;
}

// Evenly spaced resampling with spacing at most `spacing` (>= 2 points,
// ends kept).
template <class P>
std::vector<P> resample(const std::vector<P>& pts, double spacing) {
  if (pts.size() < 2) return pts;
  const std::vector<double> cum = cumulative(pts);
  const double l = cum.back();
  if (!(l > 0) || !(spacing > 0)) return {pts.front(), pts.back()};
  const int n = std::max(2, static_cast<int>(std::ceil(l / spacing)) + 1);
  std::vector<P> out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) out.push_back(point_at(pts, cum, l * i / (n - 1)));
  return out;
}

// One round of smoothing on [first, last]: each point moves `amount` (the
// paper's 0.2, §4.5) towards the average of its neighbours. Ends stay unless
// the list is closed.
template <class P>
void smooth_round(std::vector<P>& pts, std::size_t first, std::size_t last, bool closed,
                  double amount = 0.2) {
  const std::size_t n = pts.size();
  if (n < 3) return;
  last = std::min(last, n - 1);
  const std::vector<P> old = pts;
  for (std::size_t i = first; i <= last; ++i) {
    std::size_t a, b;
    if (i == 0 || i == n - 1) {
      if (!closed) continue;
      a = i == 0 ? n - 1 : i - 1;
      b = i == n - 1 ? 0 : i + 1;
    } else {
      a = i - 1;
      b = i + 1;
    }
    pts[i] = old[i] + amount * (0.5 * (old[a] + old[b]) - old[i]);
  }
}

template <class P>
void smooth(std::vector<P>& pts, int rounds, bool closed = false) {
  for (int r = 0; r < rounds; ++r) smooth_round(pts, 0, pts.size() - 1, closed);
}

template <class P>
struct Projection {
  std::size_t index = 0;  // segment [index, index+1]
  double u = 0.0;         // in [0,1] along that segment
  double s = 0.0;         // arclength of the projection
  P point;
  double distance = std::numeric_limits<double>::infinity();
  bool at_start = false, at_end = false;  // projects onto an end (off the list)
};

// Closest point of a polyline to p. `cum` is cumulative(pts).
template <class P>
Projection<P> project(const std::vector<P>& pts, const std::vector<double>& cum, const P& p) {
  Projection<P> best;
  if (pts.empty()) return best;
  if (pts.size() == 1) {
    best.point = pts[0];
    best.distance = (p - pts[0]).norm();
    best.at_start = best.at_end = true;
    return best;
  }
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const P e = pts[i + 1] - pts[i];
    const double ee = e.squaredNorm();
    double u = ee > 0 ? (p - pts[i]).dot(e) / ee : 0.0;
    u = std::clamp(u, 0.0, 1.0);
    const P q = pts[i] + u * e;
    const double dist = (p - q).norm();
    if (dist < best.distance) {
      best.index = i;
      best.u = u;
      best.point = q;
      best.distance = dist;
      best.s = cum[i] + u * (cum[i + 1] - cum[i]);
    }
  }
  const double eps = 1e-9 * std::max(1.0, cum.back());
  best.at_start = best.s <= eps;
  best.at_end = best.s >= cum.back() - eps;
  return best;
}

// Unit tangent at arclength s, from the chord over [s - w, s + w] (a window
// rather than one segment, so sample noise does not swing it).
template <class P>
P tangent_at(const std::vector<P>& pts, const std::vector<double>& cum, double s, double w) {
  const double a = std::max(0.0, s - w), b = std::min(cum.back(), s + w);
  P t = point_at(pts, cum, b) - point_at(pts, cum, a);
  if (t.norm() < 1e-12 && pts.size() >= 2) t = pts.back() - pts.front();
  const double n = t.norm();
  return n > 0 ? P(t / n) : P(P::Zero());
}

template <class P>
std::vector<P> reversed(std::vector<P> pts) {
  std::reverse(pts.begin(), pts.end());
  return pts;
}

// Sub-list between arclengths a < b (end points interpolated).
template <class P>
std::vector<P> slice(const std::vector<P>& pts, const std::vector<double>& cum, double a, double b) {
  std::vector<P> out;
  a = std::clamp(a, 0.0, cum.back());
  b = std::clamp(b, 0.0, cum.back());
  if (b < a) return out;
  out.push_back(point_at(pts, cum, a));
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (cum[i] > a && cum[i] < b) out.push_back(pts[i]);
  const P e = point_at(pts, cum, b);
  if ((e - out.back()).norm() > 0 || out.size() == 1) out.push_back(e);
  return out;
}

// Index of the point nearest arclength s; `cum` is cumulative(pts).
inline std::size_t index_at(const std::vector<double>& cum, double s) {
  const auto it = std::lower_bound(cum.begin(), cum.end(), s);
  std::size_t i = static_cast<std::size_t>(it - cum.begin());
  if (i >= cum.size()) return cum.size() - 1;
  if (i > 0 && s - cum[i - 1] < cum[i] - s) --i;
  return i;
}

// Per-point values `v` interpolated linearly at arclength s (clamped).
inline double interp(const std::vector<double>& cum, const std::vector<double>& v, double s) {
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

// Centroid of the points (zero for none).
inline Vec3 mean(const Points3& pts) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : pts) c += p;
  return pts.empty() ? c : Vec3(c / static_cast<double>(pts.size()));
}

inline double clamp_angle(double cosine) { return std::acos(std::clamp(cosine, -1.0, 1.0)); }

}  // namespace sketchlab::justdrawit
