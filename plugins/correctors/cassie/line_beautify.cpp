#include "line_beautify.hpp"

#include <cmath>

namespace sketchlab::cassie {
namespace {

// Axis within `angle` of direction d (unit), or -1.
int near_axis(const Vec3& d, double angle) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(d[k]) >= std::cos(angle)) return k;
  return -1;
}

Vec3 project_on_line(const Vec3& p, const Vec3& o, const Vec3& u) { return o + (p - o).dot(u) * u; }

}  // namespace

LineResult beautify_line(const Vec3& a0, const Vec3& b0, const std::vector<Candidate>& cands,
                         double snap, double angle, bool axis_snap) {
  LineResult r{a0, b0, {}, -1};
  // A.1: the candidates nearest to each end.
  int first = -1, last = -1;
  for (int i = 0; i < static_cast<int>(cands.size()); ++i) {
    if (cands[i].kind == TargetKind::closure) continue;
    if (first < 0 || cands[i].t_stroke < cands[first].t_stroke) first = i;
    if (last < 0 || cands[i].t_stroke > cands[last].t_stroke) last = i;
  }
  if (first >= 0 && last >= 0 && (cands[first].target - cands[last].target).norm() < 1e-9) last = first;
  const double len = (b0 - a0).norm();
  Vec3 a = a0, b = b0;
  if (first >= 0 && last != first) {
    const Vec3 p = cands[first].target, q = cands[last].target;
    const bool na = (p - a0).norm() <= snap, nb = (q - b0).norm() <= snap;
    // A.2: endpoints near a constraint snap to it; the others are projected
    // onto the line through the two constraints.
    const Vec3 u = (q - p).normalized();
    a = na ? p : project_on_line(a0, p, u);
    b = nb ? q : project_on_line(b0, p, u);
    r.enforced = {first, last};
  } else if (first >= 0) {
    const Vec3 p = cands[first].target;
    const double da = (p - a0).norm(), db = (p - b0).norm();
    if (std::min(da, db) <= snap) {
      (da <= db ? a : b) = p;
    } else {
      // Translate so that the segment passes through p.
      const Vec3 u = (b0 - a0) / len;
      const Vec3 shift = p - project_on_line(p, a0, u);
      a = a0 + shift;
      b = b0 + shift;
    }
    r.enforced = {first};
    if (axis_snap && (b - a).norm() > 0) {
      const Vec3 d = (b - a).normalized();
      const int k = near_axis(d, angle);
      if (k >= 0) {
        // Rotate about the constrained point, keeping the length.
        const Vec3 axis = d[k] >= 0 ? Vec3::Unit(k) : Vec3(-Vec3::Unit(k));
        const double sa = (p - a).dot(d), l = (b - a).norm();
        a = p - sa * axis;
        b = a + l * axis;
        r.axis = k;
      }
    }
  } else if (axis_snap && len > 0) {
    const Vec3 d = (b0 - a0) / len;
    const int k = near_axis(d, angle);
    if (k >= 0) {
      const Vec3 axis = d[k] >= 0 ? Vec3::Unit(k) : Vec3(-Vec3::Unit(k));
      const Vec3 mid = 0.5 * (a0 + b0);
      a = mid - 0.5 * len * axis;
      b = mid + 0.5 * len * axis;
      r.axis = k;
    }
  }
  r.a = a;
  r.b = b;
  return r;
}

}  // namespace sketchlab::cassie
