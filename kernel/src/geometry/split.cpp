#include "sketchlab/geometry/split.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab {
namespace {

constexpr double kJointEps = 1e-12;

void require_curve(const Curve& curve, const char* where) {
  require_segments(curve, where);
  if (curve.sharp.size() != static_cast<std::size_t>(curve.segment_count()) + 1) {
    throw std::invalid_argument(std::string(where) + ": curve has " +
                                std::to_string(curve.sharp.size()) +
                                " sharp flags; expected one per joint (K+1)");
  }
}

// Nearest joint index if t is within kJointEps of one, else -1.
int joint_at(double t) {
  const double r = std::round(t);
  return std::abs(t - r) <= kJointEps ? static_cast<int>(r) : -1;
}

}  // namespace

std::pair<Curve, int> insert_joint(const Curve& curve, double t) {
  require_curve(curve, "insert_joint");
  if (!std::isfinite(t) || t < -kJointEps || t > curve.t_max() + kJointEps) {
    throw std::invalid_argument("insert_joint: t = " + std::to_string(t) + " outside [0, " +
                                std::to_string(curve.t_max()) + "]");
  }
  const int j = joint_at(t);
  if (j >= 0) return {curve, j};
  const auto [k, u] = locate(curve, t);
  const auto [l, r] = bezier_subdivide(segment_points(curve, k), u);
  Curve out;
  out.kind = curve.kind;
  out.closed = curve.closed;
  const auto& cp = curve.control_points;
  const std::size_t first = 3 * static_cast<std::size_t>(k);
  out.control_points.reserve(cp.size() + 3);
  out.control_points.insert(out.control_points.end(), cp.begin(), cp.begin() + first);
  out.control_points.insert(out.control_points.end(), l.begin(), l.end());
  out.control_points.insert(out.control_points.end(), r.begin() + 1, r.end());
  out.control_points.insert(out.control_points.end(), cp.begin() + first + 4, cp.end());
  out.sharp = curve.sharp;
  out.sharp.insert(out.sharp.begin() + k + 1, false);
  return {out, k + 1};
}

std::pair<Curve, Curve> split(const Curve& curve, double t) {
  require_curve(curve, "split");
  if (!std::isfinite(t) || t <= kJointEps || t >= curve.t_max() - kJointEps) {
    throw std::invalid_argument("split: t = " + std::to_string(t) +
                                " must lie strictly inside (0, " +
                                std::to_string(curve.t_max()) + ")");
  }
  const auto [c, j] = insert_joint(curve, t);
  const std::size_t cut = 3 * static_cast<std::size_t>(j);
  Curve left, right;
  left.kind = right.kind = curve.kind;
  left.control_points.assign(c.control_points.begin(), c.control_points.begin() + cut + 1);
  right.control_points.assign(c.control_points.begin() + cut, c.control_points.end());
  left.sharp.assign(c.sharp.begin(), c.sharp.begin() + j + 1);
  right.sharp.assign(c.sharp.begin() + j, c.sharp.end());
  return {left, right};
}

Curve sub_curve(const Curve& curve, double t0, double t1) {
  require_curve(curve, "sub_curve");
  if (!std::isfinite(t0) || !std::isfinite(t1)) {
    throw std::invalid_argument("sub_curve: parameters must be finite");
  }
  const double tm = curve.t_max();
  t0 = std::clamp(t0, 0.0, tm);
  t1 = std::clamp(t1, 0.0, tm);
  if (!(t1 - t0 > kJointEps)) {
    throw std::invalid_argument("sub_curve: need t0 < t1 inside [0, " + std::to_string(tm) +
                                "], got t0 = " + std::to_string(t0) +
                                ", t1 = " + std::to_string(t1));
  }
  Curve c = curve;
  if (t1 < tm - kJointEps) c = split(c, t1).first;
  // Parameters below t1 are unchanged by cutting at t1.
  if (t0 > kJointEps) c = split(c, t0).second;
  if (c.control_points.front() != c.control_points.back() || t0 > kJointEps ||
      t1 < tm - kJointEps) {
    c.closed = false;
  }
  return c;
}

}  // namespace sketchlab
