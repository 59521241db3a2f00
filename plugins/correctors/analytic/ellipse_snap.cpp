#include "ellipse_snap.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::analytic {

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

Vec6 conic_row(const Vec2& q) { return (Vec6() << q.x() * q.x(), q.x() * q.y(), q.y() * q.y(), q.x(), q.y(), 1.0).finished(); }
// Gradient of the conic along a direction t: ∇F·t is linear in the coefficients.
Vec6 gradient_row(const Vec2& q, const Vec2& t) {
  return (Vec6() << 2 * q.x() * t.x(), q.y() * t.x() + q.x() * t.y(), 2 * q.y() * t.y(), t.x(), t.y(), 0.0).finished();
}

}  // namespace

std::optional<Curve> snap_to_ellipse(const Curve& curve, const Vec3& normal, const std::vector<Vec3>& joints,
                                     const std::vector<std::optional<Vec3>>& tangents, double tolerance) {
  if (curve.segment_count() < 1 || joints.size() < 2 || tangents.size() != joints.size()) return std::nullopt;
  const Vec3 n = normal.normalized();
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  const int samples = 24 * curve.segment_count();
  std::vector<Vec3> pts;
  for (int i = 0; i <= samples; ++i) pts.push_back(evaluate(curve, curve.t_max() * i / samples));
  Vec3 o = Vec3::Zero();
  for (const Vec3& p : pts) o += p;
  o /= static_cast<double>(pts.size());
  double size = 0.0;
  for (const Vec3& p : pts) size = std::max(size, (p - o).norm());
  if (!(size > 0)) return std::nullopt;
  for (const Vec3& p : pts)
    if (std::abs(n.dot(p - o)) > 1e-6 * size) return std::nullopt;
  auto to2 = [&](const Vec3& p) { return Vec2((p - o).dot(e1) / size, (p - o).dot(e2) / size); };
  auto to3 = [&](const Vec2& q) { return Vec3(o + size * (q.x() * e1 + q.y() * e2)); };

  // Hard conditions K a = 0, least squares |D a| over the null space of K.
  std::vector<Vec6> hard;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    hard.push_back(conic_row(to2(joints[j])));
    if (tangents[j]) {
      const Vec2 t(tangents[j]->dot(e1), tangents[j]->dot(e2));
      hard.push_back(gradient_row(to2(joints[j]), t.normalized()));
    }
  }
  Eigen::MatrixXd K(static_cast<Eigen::Index>(hard.size()), 6);
  for (std::size_t i = 0; i < hard.size(); ++i) K.row(static_cast<Eigen::Index>(i)) = hard[i].transpose();
  Eigen::JacobiSVD<Eigen::MatrixXd> ks(K, Eigen::ComputeFullV);
  int rank = 0;
  for (Eigen::Index i = 0; i < ks.singularValues().size(); ++i)
    if (ks.singularValues()[i] > 1e-10 * ks.singularValues()[0]) ++rank;
  if (rank >= 6) return std::nullopt;
  const Eigen::MatrixXd N = ks.matrixV().rightCols(6 - rank);
  Eigen::MatrixXd D(static_cast<Eigen::Index>(pts.size()), 6);
  for (std::size_t i = 0; i < pts.size(); ++i) D.row(static_cast<Eigen::Index>(i)) = conic_row(to2(pts[i])).transpose();
  Eigen::JacobiSVD<Eigen::MatrixXd> ds(D * N, Eigen::ComputeFullV);
  const Vec6 a = N * ds.matrixV().col(N.cols() - 1);
  const double A = a[0], B = a[1], C = a[2], Dc = a[3], E = a[4], F = a[5];
  if (!(4 * A * C - B * B > 1e-12)) return std::nullopt;  // not an ellipse
  Eigen::Matrix2d M;
  M << 2 * A, B, B, 2 * C;
  const Vec2 c = M.lu().solve(Vec2(-Dc, -E));
  const double f0 = A * c.x() * c.x() + B * c.x() * c.y() + C * c.y() * c.y() + Dc * c.x() + E * c.y() + F;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(0.5 * M);
  const Vec2 lam = es.eigenvalues();
  if (!(-f0 / lam[0] > 0) || !(-f0 / lam[1] > 0)) return std::nullopt;
  const double ra = std::sqrt(-f0 / lam[0]), rb = std::sqrt(-f0 / lam[1]);
  const Vec2 u1 = es.eigenvectors().col(0), u2 = es.eigenvectors().col(1);
  auto angle_of = [&](const Vec2& q) { return std::atan2((q - c).dot(u2) / rb, (q - c).dot(u1) / ra); };
  auto point = [&](double phi) { return Vec2(c + ra * std::cos(phi) * u1 + rb * std::sin(phi) * u2); };
  auto deriv = [&](double phi) { return Vec2(-ra * std::sin(phi) * u1 + rb * std::cos(phi) * u2); };
  // Distance of every sample to the ellipse (radial along its own angle).
  const double major = std::max(ra, rb);
  for (const Vec3& p : pts) {
    const Vec2 q = to2(p);
    if ((point(angle_of(q)) - q).norm() > tolerance * major) return std::nullopt;
  }
  // Sweep direction and unwrapped joint angles.
  const double two_pi = 2 * std::numbers::pi;
  auto wrap = [&](double x) { return x - two_pi * std::floor(x / two_pi); };
  const double p0 = angle_of(to2(pts[0])), p1 = angle_of(to2(pts[std::min<std::size_t>(3, pts.size() - 1)]));
  const double sign = wrap(p1 - p0) < std::numbers::pi ? 1.0 : -1.0;
  std::vector<double> phi{angle_of(to2(joints[0]))};
  for (std::size_t j = 1; j < joints.size(); ++j)
    phi.push_back(phi.back() + sign * wrap(sign * (angle_of(to2(joints[j])) - angle_of(to2(joints[j - 1])))));
  if (std::abs(phi.back() - phi.front()) > two_pi) return std::nullopt;
  Curve out;
  out.kind = CurveKind::bezier;
  out.control_points.push_back(joints.front());
  for (std::size_t j = 0; j + 1 < joints.size(); ++j) {
    const double sweep = phi[j + 1] - phi[j];
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (std::numbers::pi / 2) - 1e-9)));
    for (int k = 0; k < pieces; ++k) {
      const double fa = phi[j] + sweep * k / pieces, fb = phi[j] + sweep * (k + 1) / pieces;
      const double kk = 4.0 / 3.0 * std::tan((fb - fa) / 4.0);
      const Vec3 pa = k == 0 ? joints[j] : to3(point(fa));
      const Vec3 pb = k + 1 == pieces ? joints[j + 1] : to3(point(fb));
      out.control_points.push_back(pa + size * kk * (deriv(fa).x() * e1 + deriv(fa).y() * e2));
      out.control_points.push_back(pb - size * kk * (deriv(fb).x() * e1 + deriv(fb).y() * e2));
      out.control_points.push_back(pb);
    }
  }
  out.sharp.assign(static_cast<std::size_t>(out.segment_count() + 1), false);
  // The arc must follow the curve, not the ellipse's other side.
  const int check = 8 * out.segment_count();
  for (int i = 0; i <= check; ++i) {
    const Vec3 q = evaluate(out, out.t_max() * i / check);
    double nearest = 1e300;
    for (const Vec3& p : pts) nearest = std::min(nearest, (p - q).norm());
    if (nearest > 2 * tolerance * major * size + 2 * size / samples * 3) return std::nullopt;
  }
  return out;
}

}  // namespace sketchlab::analytic
