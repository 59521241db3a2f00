#include "multi_view.hpp"

#include <Eigen/SVD>
#include <stdexcept>

#include "sketchlab/draw_plane.hpp"
#include "sketchlab/geometry/split.hpp"

namespace sketchlab::synthetic {

Vec4 placed_draw_plane(const Curve& curve, const Vec3& eye) {
  const auto& cp = curve.control_points;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& q : cp) mean += q;
  mean /= double(cp.size());
  Eigen::MatrixXd centred(cp.size(), 3);
  for (std::size_t i = 0; i < cp.size(); ++i) centred.row(Eigen::Index(i)) = (cp[i] - mean).transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinV);
  const Eigen::Vector3d sv = svd.singularValues();
  const double extent = sv[0];
  if (!(extent > 0.0)) throw std::invalid_argument("synthetic: a draw plane needs a curve with extent");
  const double tol = 1e-9 * extent;
  if (sv[1] <= tol) {  // a line: the plane through it facing the eye
    const Vec3 dir = svd.matrixV().col(0);
    Vec3 n = eye - mean;
    n -= n.dot(dir) * dir;
    if (!(n.norm() > tol)) throw std::invalid_argument("synthetic: a line seen end-on has no facing draw plane");
    return plane_through(mean, n.normalized());
  }
  if (sv[2] > tol) throw std::invalid_argument("synthetic: a JustDrawIt draw plane needs a planar curve");
  return plane_through(mean, svd.matrixV().col(2));
}

namespace {

// `head` then `tail`, which starts where `head` ends; open.
Curve concatenated(Curve head, const Curve& tail) {
  head.control_points.insert(head.control_points.end(), tail.control_points.begin() + 1, tail.control_points.end());
  head.sharp.insert(head.sharp.end(), tail.sharp.begin() + 1, tail.sharp.end());
  head.closed = false;
  return head;
}

}  // namespace

Curve loop_from(const Curve& loop, double t) {
  if (!loop.closed) throw std::invalid_argument("synthetic: loop_from needs a closed curve");
  const auto [before, after] = split(loop, t);
  Curve out = concatenated(after, before);
  out.closed = true;
  return out;
}

Curve closing_loop(const Curve& loop) {
  const Curve from = loop_from(loop, loop_start);
  return concatenated(from, sub_curve(from, 0.0, closing_overlap * from.t_max()));
}

std::vector<PlannedStroke> justdrawit_strokes(const GroundTruthNetwork& plan, const std::optional<Vec3>& eye) {
  std::vector<PlannedStroke> out;
  std::vector<std::optional<Vec4>> planes(plan.curves.size());
  if (eye)
    for (std::size_t i = 0; i < plan.curves.size(); ++i) planes[i] = placed_draw_plane(plan.curves[i].curve, *eye);
  for (std::size_t i = 0; i < plan.curves.size(); ++i) {
    const GroundTruthCurve& gc = plan.curves[i];
    if (gc.curve.closed) {
      out.push_back({closing_loop(gc.curve), gc.layer, i, 0, planes[i]});
      continue;
    }
    const double t = gc.curve.t_max();
    out.push_back({sub_curve(gc.curve, 0.0, 0.6 * t), gc.layer, i, 0, planes[i]});
    out.push_back({sub_curve(gc.curve, 0.45 * t, t), gc.layer, i, 0, planes[i]});
  }
  // Oversketches stay inside an open curve: §4.2's oversketch has both ends
  // merging with the curve and no overhang; a stroke reaching past both ends
  // is none of its types and would make a new curve.
  for (std::size_t i = 0; i < plan.curves.size(); ++i) {
    const Curve& c = plan.curves[i].curve;
    out.push_back({c.closed ? c : sub_curve(c, 0.1 * c.t_max(), 0.9 * c.t_max()), plan.curves[i].layer, i, 1, planes[i]});
  }
  return out;
}

}  // namespace sketchlab::synthetic
