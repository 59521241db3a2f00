#include "multi_view.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::synthetic {
namespace {

// Cubic control points of [u0, u1] ⊂ [0, 1] of one Bézier segment.
std::array<Vec3, 4> segment_piece(std::array<Vec3, 4> p, double u0, double u1) {
  auto split_right = [](const std::array<Vec3, 4>& q, double u) {  // [u, 1]
    const Vec3 a = q[0] + u * (q[1] - q[0]), b = q[1] + u * (q[2] - q[1]), c = q[2] + u * (q[3] - q[2]);
    const Vec3 d = a + u * (b - a), e = b + u * (c - b);
    return std::array<Vec3, 4>{d + u * (e - d), e, c, q[3]};
  };
  auto split_left = [](const std::array<Vec3, 4>& q, double u) {  // [0, u]
    const Vec3 a = q[0] + u * (q[1] - q[0]), b = q[1] + u * (q[2] - q[1]), c = q[2] + u * (q[3] - q[2]);
    const Vec3 d = a + u * (b - a), e = b + u * (c - b);
    return std::array<Vec3, 4>{q[0], a, d, d + u * (e - d)};
  };
  if (u0 > 0.0) p = split_right(p, u0);
  if (u1 < 1.0) p = split_left(p, (u1 - u0) / (1.0 - u0));
  return p;
}

}  // namespace

Curve sub_curve(const Curve& curve, double t0, double t1) {
  if (!(t0 >= 0.0 && t0 < t1 && t1 <= curve.t_max()))
    throw std::invalid_argument("sub_curve: need 0 <= t0 < t1 <= t_max");
  Curve out;
  out.kind = curve.kind;
  const int k0 = std::min(static_cast<int>(std::floor(t0)), curve.segment_count() - 1);
  const int k1 = std::min(static_cast<int>(std::ceil(t1)) - 1, curve.segment_count() - 1);
  for (int k = k0; k <= std::max(k0, k1); ++k) {
    const double u0 = std::max(0.0, t0 - k), u1 = std::min(1.0, t1 - k);
    const auto p = segment_piece(segment_points(curve, k), u0, u1);
    if (out.control_points.empty()) out.control_points.push_back(p[0]);
    out.control_points.insert(out.control_points.end(), p.begin() + 1, p.end());
  }
  out.sharp.assign(static_cast<std::size_t>(out.segment_count()) + 1, false);
  return out;
}

std::vector<PlannedStroke> justdrawit_strokes(const GroundTruthNetwork& plan) {
  std::vector<PlannedStroke> out;
  for (std::size_t i = 0; i < plan.curves.size(); ++i) {
    const GroundTruthCurve& gc = plan.curves[i];
    if (gc.curve.closed) {
      out.push_back({gc.curve, gc.layer, i, 0});
      continue;
    }
    const double t = gc.curve.t_max();
    out.push_back({sub_curve(gc.curve, 0.0, 0.6 * t), gc.layer, i, 0});
    out.push_back({sub_curve(gc.curve, 0.45 * t, t), gc.layer, i, 0});
  }
  for (std::size_t i = 0; i < plan.curves.size(); ++i) out.push_back({plan.curves[i].curve, plan.curves[i].layer, i, 1});
  return out;
}

}  // namespace sketchlab::synthetic
