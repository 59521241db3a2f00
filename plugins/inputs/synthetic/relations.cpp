#include "relations.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"

namespace sketchlab::synthetic {
namespace {

constexpr double joint_snap = 1e-9;
constexpr double angle_tolerance = 1e-9;
constexpr double length_tolerance = 1e-9;  // relative

std::vector<double> ends(const Curve& c) {
  if (c.closed) return {0.0};
  return {0.0, c.t_max()};
}

double snap_to_joint(const Curve& c, double t) {
  const double r = std::round(t);
  if (std::abs(t - r) <= joint_snap) t = r;
  if (c.closed && t >= c.t_max()) t = 0.0;
  return t;
}

bool is_end(const Curve& c, double t) {
  for (double e : ends(c))
    if (std::abs(t - e) <= joint_snap) return true;
  return c.closed && std::abs(t - c.t_max()) <= joint_snap;
}

Vec3 direction(const Curve& line) {
  return (line.control_points.back() - line.control_points.front()).normalized();
}

double line_length(const Curve& line) {
  return (line.control_points.back() - line.control_points.front()).norm();
}

// End of `a` on the interior of `b`.
void end_on_interior(const Curve& a, const Curve& b, double tol, bool swap,
                     std::vector<Contact>& out) {
  for (double ta : ends(a)) {
    const Vec3 p = evaluate(a, ta);
    bool at_end = false;
    for (double tb : ends(b)) at_end = at_end || (evaluate(b, tb) - p).norm() <= tol;
    if (at_end) continue;
    const ClosestPoint cp = closest_point(b, p);
    if (cp.distance > tol) continue;
    const double tb = snap_to_joint(b, cp.t);
    if (is_end(b, tb)) continue;
    out.push_back(swap ? Contact{tb, ta, false} : Contact{ta, tb, false});
  }
}

bool already_found(const std::vector<Contact>& found, double ta, double tb) {
  for (const Contact& c : found)
    if (std::abs(c.ta - ta) <= 1e-6 && std::abs(c.tb - tb) <= 1e-6) return true;
  return false;
}

}  // namespace

double network_scale(const GroundTruthNetwork& net) {
  Box3 box;
  for (const auto& c : net.curves)
    for (const Vec3& p : c.curve.control_points) box.extend(p);
  if (box.isEmpty()) return 1.0;
  const double d = box.diagonal().norm();
  return d > 0.0 ? d : 1.0;
}

std::vector<Contact> contacts(const Curve& a, const Curve& b, double tol) {
  std::vector<Contact> out;
  for (double ta : ends(a))
    for (double tb : ends(b))
      if ((evaluate(a, ta) - evaluate(b, tb)).norm() <= tol) out.push_back({ta, tb, true});
  end_on_interior(a, b, tol, false, out);
  end_on_interior(b, a, tol, true, out);
  if (a.kind == CurveKind::line && b.kind == CurveKind::line) {
    // Closest points of the two segments' supporting lines (t in [0, 1]).
    const Vec3 p = a.control_points.front(), q = b.control_points.front();
    const Vec3 u = a.control_points.back() - p, v = b.control_points.back() - q, w = p - q;
    const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), uw = u.dot(w), vw = v.dot(w);
    const double den = uu * vv - uv * uv;
    if (den > 1e-12 * uu * vv) {
      const double ta = (uv * vw - vv * uw) / den, tb = (uu * vw - uv * uw) / den;
      const double m = joint_snap;
      if (ta > m && ta < 1 - m && tb > m && tb < 1 - m &&
          (evaluate(a, ta) - evaluate(b, tb)).norm() <= tol && !already_found(out, ta, tb))
        out.push_back({ta, tb, false});
    }
  }
  return out;
}

std::vector<GroundTruthRelation> infer_relations(const GroundTruthNetwork& net) {
  const double tol = 1e-9 * network_scale(net);
  const auto& cs = net.curves;
  std::vector<GroundTruthRelation> out;
  std::vector<std::size_t> parallel_reps, length_reps;
  for (std::size_t j = 0; j < cs.size(); ++j) {
    const Curve& cj = cs[j].curve;
    if (cj.kind != CurveKind::line) {
      Eigen::MatrixXd m(static_cast<Eigen::Index>(cj.control_points.size()), 3);
      Vec3 mean = Vec3::Zero();
      for (const Vec3& p : cj.control_points) mean += p;
      mean /= static_cast<double>(cj.control_points.size());
      for (std::size_t k = 0; k < cj.control_points.size(); ++k)
        m.row(static_cast<Eigen::Index>(k)) = (cj.control_points[k] - mean).transpose();
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinV);
      const Vec3 normal = svd.matrixV().col(2);
      double off = 0.0;
      for (const Vec3& p : cj.control_points) off = std::max(off, std::abs(normal.dot(p - mean)));
      if (off <= tol && svd.singularValues()(1) > tol)
        out.push_back({ConstraintKind::planar, {j}, {}});
    }
    for (std::size_t i = 0; i < j; ++i) {
      const Curve& ci = cs[i].curve;
      const auto found = contacts(ci, cj, tol);
      for (const Contact& c : found) {
        out.push_back({c.both_ends ? ConstraintKind::coincident_point : ConstraintKind::intersection,
                       {i, j},
                       {c.ta, c.tb}});
      }
      if (!found.empty() && ci.kind == CurveKind::line && cj.kind == CurveKind::line &&
          std::abs(direction(ci).dot(direction(cj))) <= angle_tolerance)
        out.push_back({ConstraintKind::perpendicular, {i, j}, {}});
    }
    if (cj.kind == CurveKind::line) {
      const Vec3 d = direction(cj);
      auto rep = std::find_if(parallel_reps.begin(), parallel_reps.end(), [&](std::size_t r) {
        return direction(cs[r].curve).cross(d).norm() <= angle_tolerance;
      });
      if (rep == parallel_reps.end())
        parallel_reps.push_back(j);
      else
        out.push_back({ConstraintKind::parallel, {*rep, j}, {}});
      const double len = line_length(cj);
      auto lrep = std::find_if(length_reps.begin(), length_reps.end(), [&](std::size_t r) {
        const double lr = line_length(cs[r].curve);
        return std::abs(lr - len) <= length_tolerance * std::max(lr, len);
      });
      if (lrep == length_reps.end())
        length_reps.push_back(j);
      else
        out.push_back({ConstraintKind::equal_length, {*lrep, j}, {}});
    }
  }
  return out;
}

Curve reversed(const Curve& curve) {
  Curve r = curve;
  std::reverse(r.control_points.begin(), r.control_points.end());
  std::reverse(r.sharp.begin(), r.sharp.end());
  return r;
}

GroundTruthNetwork plan_drawing(const GroundTruthNetwork& net) {
  const double tol = 1e-9 * network_scale(net);
  const std::size_t n = net.curves.size();
  std::vector<double> length(n);
  for (std::size_t i = 0; i < n; ++i) length[i] = arclength(net.curves[i].curve);
  std::vector<std::vector<bool>> touches(n, std::vector<bool>(n, false));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      touches[i][j] = touches[j][i] = !contacts(net.curves[i].curve, net.curves[j].curve, tol).empty();

  std::vector<std::size_t> order;
  std::vector<bool> drawn(n, false);
  for (int group = 0; group < 2; ++group) {
    auto in_group = [&](std::size_t i) {
      return (net.curves[i].layer == Layer::scaffold) == (group == 0);
    };
    while (true) {
      std::size_t best = n;
      bool best_connected = false;
      for (std::size_t i = 0; i < n; ++i) {
        if (drawn[i] || !in_group(i)) continue;
        bool connected = false;
        for (std::size_t k : order) connected = connected || touches[i][k];
        // Connected beats unconnected; then longer; ties keep the lower index.
        if (best == n || (connected && !best_connected) ||
            (connected == best_connected && length[i] > length[best])) {
          best = i;
          best_connected = connected;
        }
      }
      if (best == n) break;
      drawn[best] = true;
      order.push_back(best);
    }
  }

  GroundTruthNetwork out{net.name, {}};
  for (std::size_t idx : order) {
    GroundTruthCurve c = net.curves[idx];
    if (!c.curve.closed && !out.curves.empty()) {
      auto touches_drawing = [&](const Vec3& p) {
        for (const auto& d : out.curves)
          if (closest_point(d.curve, p).distance <= tol) return true;
        return false;
      };
      if (!touches_drawing(c.curve.control_points.front()) &&
          touches_drawing(c.curve.control_points.back()))
        c.curve = reversed(c.curve);
    }
    out.curves.push_back(std::move(c));
  }
  return out;
}

}  // namespace sketchlab::synthetic
