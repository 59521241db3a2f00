#include "stroke_ends.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/geometry/split.hpp"

namespace sketchlab::cassie {
namespace {

bool runs_along(const Candidate& c, const Curve& stroke, const Network& net, double angle) {
  const Vec3 a = tangent(stroke, c.t_stroke);
  const Vec3 b = tangent(net.curves().at(c.curve).curve, c.t_curve);
  return std::abs(a.dot(b)) >= std::cos(angle);
}

}  // namespace

Curve cut_overlaps(const Curve& fitted, std::vector<Candidate>& cands, const Network& net, double reach,
                   double angle) {
  Curve c = fitted;
  if (cands.empty()) return c;
  double t0 = 0.0, t1 = c.t_max();
  const Candidate& first = cands.front();
  const Candidate& last = cands.back();
  const double margin = 1e-9;
  if (is_intersection(first) && (first.target - c.control_points.front()).norm() <= reach &&
      first.t_stroke > margin && runs_along(first, c, net, angle))
    t0 = first.t_stroke;
  if (is_intersection(last) && (last.target - c.control_points.back()).norm() <= reach &&
      last.t_stroke < c.t_max() - margin && runs_along(last, c, net, angle))
    t1 = last.t_stroke;
  if (t0 == 0.0 && t1 == c.t_max()) return c;
  if (!(t1 - t0 > 1e-6)) return c;  // both cuts would consume the stroke
  c = sub_curve(c, t0, t1);
  std::vector<Candidate> kept;
  for (Candidate& k : cands) {
    if (k.t_stroke < t0 - margin || k.t_stroke > t1 + margin) continue;
    const ClosestPoint cp = closest_point(c, k.target);
    k.t_stroke = cp.t;
    k.distance = cp.distance;
    kept.push_back(k);
  }
  cands = std::move(kept);
  return c;
}

int trim_dangling(Curve& curve, const std::vector<int>& joints, double fraction, double length) {
  if (joints.empty() || curve.closed) return 0;
  const int k_count = curve.segment_count();
  const int first = *std::min_element(joints.begin(), joints.end());
  const int last = *std::max_element(joints.begin(), joints.end());
  const double total = arclength(curve);
  const double limit = std::min(fraction * total, length);
  int lo = 0, hi = k_count;
  if (first > 0 && arclength(curve, 0.0, first) < limit) lo = first;
  if (last < k_count && arclength(curve, last, k_count) < limit) hi = last;
  if (hi - lo < 1 || (lo == 0 && hi == k_count)) return 0;
  curve = sub_curve(curve, lo, hi);
  return lo;
}

}  // namespace sketchlab::cassie
