#include "sketchlab/geometry/closest_point.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab {
namespace {

// Polynomial in power basis, c[i] multiplies u^i.
using Poly = std::vector<double>;

double poly_eval(const Poly& c, double u) {
  double v = 0.0;
  for (std::size_t i = c.size(); i-- > 0;) v = v * u + c[i];
  return v;
}

Poly poly_derivative(const Poly& c) {
  Poly d;
  for (std::size_t i = 1; i < c.size(); ++i) d.push_back(static_cast<double>(i) * c[i]);
  return d;
}

// Root of c in [lo, hi] where c(lo) and c(hi) have opposite signs: Newton
// steps kept inside the shrinking bracket, bisection otherwise.
double bracketed_root(const Poly& c, const Poly& dc, double lo, double hi, double flo) {
  double u = 0.5 * (lo + hi);
  for (int it = 0; it < 100 && hi - lo > 1e-16; ++it) {
    const double f = poly_eval(c, u);
    if (f == 0.0) return u;
    if ((f < 0.0) == (flo < 0.0)) lo = u; else hi = u;
    const double d = poly_eval(dc, u);
    double next = d != 0.0 ? u - f / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - u) < 1e-17) break;
    u = next;
  }
  return u;
}

// All real roots of c in [lo, hi], found recursively: the roots of c'
// split the interval into pieces where c is monotone, and each piece with a
// sign change holds exactly one root. Robust for any degree (no closed form,
// no missed roots between coarse samples).
void real_roots(const Poly& c_in, double lo, double hi, std::vector<double>& out) {
  Poly c = c_in;
  while (!c.empty() && c.back() == 0.0) c.pop_back();
  if (c.size() <= 1) return;  // constant: no isolated roots
  if (c.size() == 2) {
    const double r = -c[0] / c[1];
    if (r >= lo && r <= hi) out.push_back(r);
    return;
  }
  const Poly dc = poly_derivative(c);
  std::vector<double> knots{lo};
  real_roots(dc, lo, hi, knots);
  knots.push_back(hi);
  std::sort(knots.begin(), knots.end());
  for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
    const double a = knots[i], b = knots[i + 1];
    const double fa = poly_eval(c, a), fb = poly_eval(c, b);
    if (fa == 0.0) {
      out.push_back(a);
    } else if (b > a && ((fa < 0.0) != (fb < 0.0)) && fb != 0.0) {
      out.push_back(bracketed_root(c, dc, a, b, fa));
    }
  }
  if (poly_eval(c, hi) == 0.0) out.push_back(hi);
}

struct SegmentHit {
  double u = 0.0;
  Vec3 point;
  double dist2 = std::numeric_limits<double>::infinity();
};

// Closest point on one cubic to p. Stationary points of |B(u)-p|^2 are the
// roots of g(u) = (B(u)-p)·B'(u), a quintic; candidates are its roots in
// [0,1], the segment ends and a few uniform samples (a safety net for
// ill-conditioned power-basis coefficients).
SegmentHit closest_on_segment(const std::array<Vec3, 4>& p, const Vec3& q) {
  // Power basis B(u) = a u^3 + b u^2 + c u + d, centred at q for accuracy.
  const Vec3 e = p[0] - q;
  const Vec3 c = 3.0 * (p[1] - p[0]);
  const Vec3 b = 3.0 * (p[2] - 2.0 * p[1] + p[0]);
  const Vec3 a = p[3] - 3.0 * p[2] + 3.0 * p[1] - p[0];
  const Poly g{e.dot(c), c.dot(c) + 2.0 * e.dot(b), 3.0 * b.dot(c) + 3.0 * a.dot(e),
               4.0 * a.dot(c) + 2.0 * b.dot(b), 5.0 * a.dot(b), 3.0 * a.dot(a)};
  std::vector<double> cand;
  real_roots(g, 0.0, 1.0, cand);
  constexpr int kSafetySamples = 8;
  for (int i = 0; i <= kSafetySamples; ++i) cand.push_back(static_cast<double>(i) / kSafetySamples);

  SegmentHit best;
  auto consider = [&](double u) {
    u = std::clamp(u, 0.0, 1.0);
    const Vec3 x = bezier_point(p, u);
    const double d2 = (x - q).squaredNorm();
    if (d2 < best.dist2) best = {u, x, d2};
  };
  for (double u : cand) consider(u);
  // Polish the winner with a few Newton steps on the exact (de Casteljau)
  // geometry; keep the result only if it improves the distance.
  double u = best.u;
  for (int it = 0; it < 8; ++it) {
    const Vec3 x = bezier_point(p, u);
    const Vec3 d1 = bezier_derivative(p, u);
    const Vec3 d2 = 6.0 * ((1.0 - u) * (p[2] - 2.0 * p[1] + p[0]) + u * (p[3] - 2.0 * p[2] + p[1]));
    const double f = (x - q).dot(d1);
    const double df = d1.squaredNorm() + (x - q).dot(d2);
    if (!(df > 0.0)) break;
    const double next = std::clamp(u - f / df, 0.0, 1.0);
    if (std::abs(next - u) < 1e-16) break;
    u = next;
    consider(u);
  }
  return best;
}

}  // namespace

ClosestPoint closest_point(const Curve& curve, const Vec3& p) {
  require_segments(curve, "closest_point");
  if (!p.allFinite()) throw std::invalid_argument("closest_point: query point is not finite");
  ClosestPoint best;
  double best_d2 = std::numeric_limits<double>::infinity();
  int best_k = -1;
  // A Bézier lies in the box of its control points, so the box's distance
  // bounds the segment's from below: visit segments nearest box first and
  // stop when no box can hold a closer point (same result as visiting all,
  // the lowest segment winning ties; long curves cost a few segments).
  const int k_count = curve.segment_count();
  std::vector<std::pair<double, int>> order(static_cast<std::size_t>(k_count));
  for (int k = 0; k < k_count; ++k) {
    const auto seg = segment_points(curve, k);
    Vec3 lo = seg[0], hi = seg[0];
    for (const Vec3& q : seg) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    const Vec3 gap = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
    order[static_cast<std::size_t>(k)] = {gap.squaredNorm(), k};
  }
  std::sort(order.begin(), order.end());
  for (const auto& [box_d2, k] : order) {
    if (box_d2 > best_d2) break;
    const SegmentHit h = closest_on_segment(segment_points(curve, k), p);
    if (h.dist2 < best_d2 || (h.dist2 == best_d2 && k < best_k)) {
      best_d2 = h.dist2;
      best_k = k;
      best.t = static_cast<double>(k) + h.u;
      best.point = h.point;
    }
  }
  best.distance = std::sqrt(best_d2);
  return best;
}

ClosestPoint closest_point_on_polyline(const std::vector<Vec3>& polyline, const Vec3& p) {
  if (polyline.empty()) {
    throw std::invalid_argument("closest_point_on_polyline: polyline has no points");
  }
  if (!p.allFinite()) {
    throw std::invalid_argument("closest_point_on_polyline: query point is not finite");
  }
  ClosestPoint best;
  best.point = polyline.front();
  double best_d2 = (polyline.front() - p).squaredNorm();
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Vec3& a = polyline[i];
    const Vec3 ab = polyline[i + 1] - a;
    const double len2 = ab.squaredNorm();
    const double u = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const Vec3 x = a + u * ab;
    const double d2 = (x - p).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.t = static_cast<double>(i) + u;
      best.point = x;
    }
  }
  best.distance = std::sqrt(best_d2);
  return best;
}

ClosestPoint closest_point_to_polyline(const Curve& curve, const std::vector<Vec3>& polyline) {
  require_segments(curve, "closest_point_to_polyline");
  if (polyline.empty()) {
    throw std::invalid_argument("closest_point_to_polyline: polyline has no points");
  }
  ClosestPoint best;
  best.distance = std::numeric_limits<double>::infinity();
  auto consider = [&](double t) {
    const Vec3 x = evaluate(curve, t);
    const double d = closest_point_on_polyline(polyline, x).distance;
    if (d < best.distance) best = {t, x, d};
  };
  // Minima at a polyline vertex are found exactly.
  for (const Vec3& v : polyline) consider(closest_point(curve, v).t);
  // Minima inside a polyline edge: seed from curve samples, then alternate
  // projections (curve -> polyline -> curve), which never increase the
  // distance and converge to a local minimum of the pair distance.
  constexpr int kSeedsPerSegment = 16;
  const int k_count = curve.segment_count();
  std::vector<double> seeds;
  for (int i = 0; i <= k_count * kSeedsPerSegment; ++i) {
    seeds.push_back(static_cast<double>(i) / kSeedsPerSegment);
  }
  std::vector<std::pair<double, double>> scored;
  for (double t : seeds) {
    scored.emplace_back(closest_point_on_polyline(polyline, evaluate(curve, t)).distance, t);
  }
  std::sort(scored.begin(), scored.end());
  const std::size_t refine = std::min<std::size_t>(scored.size(), 8);
  for (std::size_t s = 0; s < refine; ++s) {
    double t = scored[s].second;
    consider(t);
    for (int it = 0; it < 50; ++it) {
      const Vec3 q = closest_point_on_polyline(polyline, evaluate(curve, t)).point;
      const double next = closest_point(curve, q).t;
      if (std::abs(next - t) < 1e-14) break;
      t = next;
      consider(t);
    }
  }
  return best;
}

}  // namespace sketchlab
