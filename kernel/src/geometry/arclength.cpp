#include "sketchlab/geometry/arclength.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab {
namespace {

// 7-point Gauss–Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 7> kGlNodes = {
    -0.9491079123427585, -0.7415311855993945, -0.4058451513773972, 0.0,
    0.4058451513773972,  0.7415311855993945,  0.9491079123427585};
constexpr std::array<double, 7> kGlWeights = {
    0.1294849661688697, 0.2797053914892766, 0.3818300505051189, 0.4179591836734694,
    0.3818300505051189, 0.2797053914892766, 0.1294849661688697};

double gauss_legendre(const std::array<Vec3, 4>& p, double a, double b) {
  const double half = 0.5 * (b - a);
  const double mid = 0.5 * (a + b);
  double sum = 0.0;
  for (std::size_t i = 0; i < kGlNodes.size(); ++i) {
    sum += kGlWeights[i] * bezier_derivative(p, mid + half * kGlNodes[i]).norm();
  }
  return sum * half;
}

// Adaptive quadrature: accept an interval when the 7-point rule agrees with
// the sum over its halves within the (halved per level) tolerance. A length
// that overflows (coordinates near 1e300) never agrees: it is returned as
// is, not refined 2^40 times.
double adaptive(const std::array<Vec3, 4>& p, double a, double b, double whole, double tol,
                int depth) {
  const double m = 0.5 * (a + b);
  const double left = gauss_legendre(p, a, m);
  const double right = gauss_legendre(p, m, b);
  if (depth >= 40 || !std::isfinite(left + right) || std::abs(left + right - whole) <= tol) return left + right;
  return adaptive(p, a, m, left, 0.5 * tol, depth + 1) +
         adaptive(p, m, b, right, 0.5 * tol, depth + 1);
}

// Arclength of one segment between local parameters a <= b.
double segment_length(const std::array<Vec3, 4>& p, double a, double b) {
  if (b <= a) return 0.0;
  const double whole = gauss_legendre(p, a, b);
  const double scale = (p[1] - p[0]).norm() + (p[2] - p[1]).norm() + (p[3] - p[2]).norm();
  // Relative tolerance 1e-9 of the control polygon length (an upper bound
  // of the segment length), with an absolute floor for degenerate segments.
  const double tol = std::max(1e-10 * scale, 1e-300);
  return adaptive(p, a, b, whole, tol, 0);
}

std::vector<double> cumulative_segment_lengths(const Curve& curve) {
  const int k_count = curve.segment_count();
  std::vector<double> cum(static_cast<std::size_t>(k_count) + 1, 0.0);
  for (int k = 0; k < k_count; ++k) {
    cum[k + 1] = cum[k] + segment_length(segment_points(curve, k), 0.0, 1.0);
  }
  return cum;
}

// Local parameter u in segment p where the length from 0 equals s (0 <= s <=
// seg_len). Newton on L(u) - s with L' = |B'(u)|, guarded by bisection.
double invert_segment(const std::array<Vec3, 4>& p, double s, double seg_len) {
  if (s <= 0.0) return 0.0;
  if (s >= seg_len) return 1.0;
  double lo = 0.0, hi = 1.0;
  double u = s / seg_len;
  double len_u = segment_length(p, 0.0, u);
  for (int it = 0; it < 100; ++it) {
    const double f = len_u - s;
    if (std::abs(f) <= 1e-13 * std::max(seg_len, 1e-300)) break;
    if (f > 0.0) hi = u; else lo = u;
    const double d = bezier_derivative(p, u).norm();
    double next = d > 0.0 ? u - f / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo < 1e-15) break;
    // Incremental length keeps each Newton step cheap.
    len_u = next > u ? len_u + segment_length(p, u, next) : len_u - segment_length(p, next, u);
    u = next;
  }
  return u;
}

double parameter_at(const Curve& curve, const std::vector<double>& cum, double s) {
  const int k_count = curve.segment_count();
  const double total = cum.back();
  if (!(s > 0.0)) return 0.0;  // also maps NaN to 0
  if (s >= total) return static_cast<double>(k_count);
  int k = static_cast<int>(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin()) - 1;
  k = std::clamp(k, 0, k_count - 1);
  const double u = invert_segment(segment_points(curve, k), s - cum[k], cum[k + 1] - cum[k]);
  return static_cast<double>(k) + u;
}

}  // namespace

double arclength(const Curve& curve, double t0, double t1) {
  require_segments(curve, "arclength");
  if (!std::isfinite(t0) || !std::isfinite(t1)) {
    throw std::invalid_argument("arclength: parameters must be finite");
  }
  if (t1 < t0) {
    throw std::invalid_argument("arclength: need t0 <= t1, got t0 = " + std::to_string(t0) +
                                ", t1 = " + std::to_string(t1));
  }
  const double tm = curve.t_max();
  t0 = std::clamp(t0, 0.0, tm);
  t1 = std::clamp(t1, 0.0, tm);
  if (t1 <= t0) return 0.0;
  const auto [k0, u0] = locate(curve, t0);
  const auto [k1, u1] = locate(curve, t1);
  if (k0 == k1) return segment_length(segment_points(curve, k0), u0, u1);
  double sum = segment_length(segment_points(curve, k0), u0, 1.0);
  for (int k = k0 + 1; k < k1; ++k) sum += segment_length(segment_points(curve, k), 0.0, 1.0);
  sum += segment_length(segment_points(curve, k1), 0.0, u1);
  return sum;
}

double arclength(const Curve& curve) {
  require_segments(curve, "arclength");
  return cumulative_segment_lengths(curve).back();
}

double parameter_at_arclength(const Curve& curve, double s) {
  require_segments(curve, "parameter_at_arclength");
  return parameter_at(curve, cumulative_segment_lengths(curve), s);
}

std::vector<double> arclength_parameters(const Curve& curve, int n) {
  require_segments(curve, "arclength_parameters");
  if (n < 2) {
    throw std::invalid_argument("arclength_parameters: n = " + std::to_string(n) +
                                "; need n >= 2");
  }
  const auto cum = cumulative_segment_lengths(curve);
  const double total = cum.back();
  std::vector<double> ts(static_cast<std::size_t>(n));
  ts.front() = 0.0;
  ts.back() = curve.t_max();
  for (int i = 1; i + 1 < n; ++i) {
    ts[i] = parameter_at(curve, cum, total * static_cast<double>(i) / static_cast<double>(n - 1));
  }
  // Keep the parameters non-decreasing even for degenerate (zero-length) parts.
  for (int i = 1; i < n; ++i) ts[i] = std::max(ts[i], ts[i - 1]);
  return ts;
}

std::vector<Vec3> sample_by_arclength(const Curve& curve, int n) {
  const auto ts = arclength_parameters(curve, n);
  std::vector<Vec3> out;
  out.reserve(ts.size());
  for (double t : ts) out.push_back(evaluate(curve, t));
  return out;
}

namespace {

// Points that sample `curve` every `spacing` metres, ends included (>= 2;
// infinite when its length is).
double points_at_spacing(const Curve& curve, double spacing) {
  require_segments(curve, "sample_with_spacing");
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    throw std::invalid_argument("sample_with_spacing: spacing must be finite and > 0, got " +
                                std::to_string(spacing));
  }
  return std::max(2.0, std::ceil(arclength(curve) / spacing) + 1.0);
}

}  // namespace

std::vector<Vec3> sample_with_spacing(const Curve& curve, double spacing) {
  const double points = points_at_spacing(curve, spacing);
  constexpr double kMaxSamples = 1e7;
  if (!(points <= kMaxSamples)) {
    throw std::invalid_argument("sample_with_spacing: spacing " + std::to_string(spacing) +
                                " m on a curve of length " + std::to_string(arclength(curve)) +
                                " m needs more than 1e7 samples");
  }
  return sample_by_arclength(curve, static_cast<int>(points));
}

std::vector<Vec3> sample_with_spacing(const Curve& curve, double spacing, int max_points) {
  if (max_points < 2)
    throw std::invalid_argument("sample_with_spacing: max_points must be >= 2, got " + std::to_string(max_points));
  const double points = points_at_spacing(curve, spacing);
  return sample_by_arclength(curve, points <= max_points ? static_cast<int>(points) : max_points);
}

}  // namespace sketchlab
