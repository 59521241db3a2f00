#include "line_beautify.hpp"

#include <algorithm>
#include <cmath>

namespace sketchlab::cassie {
namespace {

// Parameter of p on the line a + u (b − a).
double along(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double l2 = d.squaredNorm();
  return l2 > 0 ? (p - a).dot(d) / l2 : 0.0;
}

Vec3 project_on_line(const Vec3& p, const Vec3& o, const Vec3& through) {
  const Vec3 d = through - o;
  const double l2 = d.squaredNorm();
  return l2 > 0 ? Vec3(o + (p - o).dot(d) / l2 * d) : o;
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double u = std::clamp(along(p, a, b), 0.0, 1.0);
  return (a + u * (b - a) - p).norm();
}

}  // namespace

LineResult beautify_line(const Vec3& a0, const Vec3& b0, const std::vector<Candidate>& cands,
                         double snap, double keep, double angle, bool axis_snap) {
  LineResult r{a0, b0, {}, {}, -1};
  // The constraints used: the first and the one farthest from it.
  std::vector<int> use;
  if (!cands.empty()) {
    use.push_back(0);
    int far = -1;
    double far_d = -1.0;
    for (int i = 1; i < static_cast<int>(cands.size()); ++i) {
      const double d = (cands[i].target - cands[0].target).norm();
      if (d > far_d) far_d = d, far = i;
    }
    if (far >= 0) {
      if (far_d >= keep) use.push_back(far);
      else if (!is_intersection(cands[0]) && is_intersection(cands[far])) use[0] = far;
    }
  }
  r.used = use;
  Vec3 a = a0, b = b0;
  // Match to ends by position along the line.
  int ca = -1, cb = -1;
  if (use.size() == 2) {
    const bool first_at_a = along(cands[use[0]].target, a0, b0) <= along(cands[use[1]].target, a0, b0);
    ca = first_at_a ? use[0] : use[1];
    cb = first_at_a ? use[1] : use[0];
  } else if (use.size() == 1) {
    (along(cands[use[0]].target, a0, b0) <= 0.5 ? ca : cb) = use[0];
  }
  Vec3 pivot = a0;
  bool pivot_set = false;
  if (ca >= 0) {
    const Vec3 p = cands[ca].target;
    const bool snaps = (p - a).norm() <= snap || along(p, a0, b0) < 0.0;
    a = snaps ? p : project_on_line(a, p, b);
    pivot = snaps ? a : p;
    pivot_set = true;
  }
  if (cb >= 0) {
    const Vec3 q = cands[cb].target;
    const bool snaps = (q - b).norm() <= snap || along(q, a0, b0) > 1.0;
    b = snaps ? q : project_on_line(b, a, q);
    if (!pivot_set) pivot = snaps ? b : q;
  }
  // Axis snap with at most one constraint.
  const double len = (b - a).norm();
  if (axis_snap && use.size() <= 1 && len > 0) {
    const Vec3 d = (b - a) / len;
    for (int k = 0; k < 3; ++k) {
      if (std::abs(d[k]) < std::cos(angle)) continue;
      const Vec3 axis = d[k] >= 0 ? Vec3::Unit(k) : Vec3(-Vec3::Unit(k));
      // Rotate about the pivot, keeping the distances to it along the line.
      const double sa = (a - pivot).dot(d), sb = (b - pivot).dot(d);
      const Vec3 na = pivot + sa * axis, nb = pivot + sb * axis;
      const double moved = std::max((na - a).norm(), (nb - b).norm());
      if (moved < snap) {
        a = na;
        b = nb;
        r.axis = k;
      }
      break;
    }
  }
  r.a = a;
  r.b = b;
  for (int i : use)
    if (distance_to_segment(cands[i].target, a, b) <= keep) r.enforced.push_back(i);
  return r;
}

}  // namespace sketchlab::cassie
