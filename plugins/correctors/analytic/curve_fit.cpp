#include "curve_fit.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::analytic {

namespace {

using MatX = Eigen::MatrixXd;
using VecX = Eigen::VectorXd;

// m_j = B_j · x[offset_j .. offset_j + cols).
struct TangentMap {
  Eigen::Matrix<double, 3, Eigen::Dynamic> basis;
  int offset = 0;
};

std::vector<TangentMap> tangent_maps(const FitProblem& pr, int& nvars) {
  const int n = static_cast<int>(pr.joints.size());
  std::vector<TangentMap> maps(static_cast<std::size_t>(n));
  nvars = 0;
  Vec3 e1 = Vec3::UnitX(), e2 = Vec3::UnitY();
  if (pr.plane_normal) {
    const Vec3 nn = pr.plane_normal->normalized();
    e1 = nn.unitOrthogonal();
    e2 = nn.cross(e1);
  }
  const Vec3 chord = (pr.joints.back() - pr.joints.front()).normalized();
  const Mat3 reflect = Mat3::Identity() - 2.0 * chord * chord.transpose();
  for (int j = 0; j < n; ++j) {
    const int mirror = n - 1 - j;
    TangentMap& m = maps[static_cast<std::size_t>(j)];
    if (pr.symmetric && mirror < j) {
      // c(T - t) = R c(t)  =>  m_{n-1-j} = -R m_j.
      const TangentMap& src = maps[static_cast<std::size_t>(mirror)];
      m.basis = -reflect * src.basis;
      m.offset = src.offset;
      continue;
    }
    const auto& dir = pr.tangent_dir[static_cast<std::size_t>(j)];
    if (pr.symmetric && mirror == j) {
      m.basis = chord;  // the middle tangent is perpendicular to the mirror plane
    } else if (dir) {
      m.basis = dir->normalized();
    } else if (pr.plane_normal) {
      m.basis.resize(3, 2);
      m.basis.col(0) = e1;
      m.basis.col(1) = e2;
    } else {
      m.basis = Mat3::Identity();
    }
    m.offset = nvars;
    nvars += static_cast<int>(m.basis.cols());
  }
  return maps;
}

// Bernstein weights.
void bernstein(double u, double b[4]) {
  const double v = 1.0 - u;
  b[0] = v * v * v;
  b[1] = 3 * v * v * u;
  b[2] = 3 * v * u * u;
  b[3] = u * u * u;
}

Curve build_curve(const FitProblem& pr, const std::vector<TangentMap>& maps, const VecX& x) {
  const std::size_t n = pr.joints.size();
  std::vector<Vec3> m(n);
  for (std::size_t j = 0; j < n; ++j)
    m[j] = maps[j].basis * x.segment(maps[j].offset, maps[j].basis.cols());
  Curve c;
  c.kind = CurveKind::bezier;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (k == 0) c.control_points.push_back(pr.joints[0]);
    c.control_points.push_back(pr.joints[k] + m[k] / 3.0);
    c.control_points.push_back(pr.joints[k + 1] - m[k + 1] / 3.0);
    c.control_points.push_back(pr.joints[k + 1]);
  }
  c.sharp.assign(n, false);
  return c;
}

}  // namespace

FitResult fit_spline(const FitProblem& pr, int iterations) {
  FitResult out;
  const std::size_t n = pr.joints.size();
  if (n < 2 || pr.tangent_dir.size() != n || pr.rays.size() != n - 1 || pr.u0.size() != n - 1)
    return out;
  int nv = 0;
  const std::vector<TangentMap> maps = tangent_maps(pr, nv);
  // Initial guess: Catmull-Rom-like tangents projected on each basis; also the
  // target of a tiny ridge term that keeps depth-only directions determined.
  VecX x0 = VecX::Zero(nv);
  for (std::size_t j = 0; j < n; ++j) {
    const Vec3 prev = pr.joints[j > 0 ? j - 1 : j], next = pr.joints[j + 1 < n ? j + 1 : j];
    const Vec3 guess = (next - prev) * (j > 0 && j + 1 < n ? 0.5 : 1.0);
    const auto& b = maps[j].basis;
    const VecX coef = b.colPivHouseholderQr().solve(guess);
    x0.segment(maps[j].offset, b.cols()) = coef;
  }
  std::vector<std::vector<double>> u = pr.u0;
  VecX x = x0;
  double scale = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) scale += (pr.joints[k + 1] - pr.joints[k]).squaredNorm();
  scale = std::max(scale, 1e-12);
  for (int it = 0; it <= std::max(0, iterations); ++it) {
    // θ step: linear least squares with the parameters fixed.
    MatX A = MatX::Zero(nv, nv);
    VecX rhs = VecX::Zero(nv);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const TangentMap& ma = maps[k];
      const TangentMap& mb = maps[k + 1];
      for (std::size_t i = 0; i < pr.rays[k].size(); ++i) {
        const Ray& r = pr.rays[k][i];
        double b[4];
        bernstein(u[k][i], b);
        const Vec3 a = (b[0] + b[1]) * pr.joints[k] + (b[2] + b[3]) * pr.joints[k + 1];
        // Only the tangents of the segment's two joints enter: a 3×(≤6)
        // Jacobian, projected off the ray (P = I − r rᵀ).
        const int ca = static_cast<int>(ma.basis.cols()), cb = static_cast<int>(mb.basis.cols());
        Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6> J(3, ca + cb);
        J.leftCols(ca) = (b[1] / 3.0) * ma.basis;
        J.rightCols(cb) = -(b[2] / 3.0) * mb.basis;
        J -= r.direction * (r.direction.transpose() * J);
        Vec3 res = r.origin - a;
        res -= r.direction * r.direction.dot(res);
        int idx[6];
        for (int q = 0; q < ca; ++q) idx[q] = ma.offset + q;
        for (int q = 0; q < cb; ++q) idx[ca + q] = mb.offset + q;
        for (int i1 = 0; i1 < ca + cb; ++i1) {
          rhs[idx[i1]] += J.col(i1).dot(res);
          for (int i2 = 0; i2 < ca + cb; ++i2) A(idx[i1], idx[i2]) += J.col(i1).dot(J.col(i2));
        }
      }
    }
    const double ridge = 1e-9 * (A.trace() / std::max(1, nv) + 1e-12);
    A.diagonal().array() += ridge;
    rhs += ridge * x0;
    const VecX xn = A.ldlt().solve(rhs);
    if (!xn.allFinite()) return out;
    x = xn;
    if (it == iterations) break;
    // Foot points: each sample's parameter moves to the nearest point of its
    // segment to its ray (Gauss-Newton on |P(c(u) - o)|², warm started).
    const Curve c = build_curve(pr, maps, x);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const auto seg = segment_points(c, static_cast<int>(k));
      for (std::size_t i = 0; i < pr.rays[k].size(); ++i) {
        const Ray& r = pr.rays[k][i];
        double uu = u[k][i];
        for (int g = 0; g < 4; ++g) {
          const Vec3 d = bezier_point(seg, uu) - r.origin;
          const Vec3 pd = d - r.direction * r.direction.dot(d);
          const Vec3 t = bezier_derivative(seg, uu);
          const Vec3 pt = t - r.direction * r.direction.dot(t);
          const double den = pt.squaredNorm();
          if (!(den > 1e-18 * scale)) break;
          uu = std::clamp(uu - pt.dot(pd) / den, 0.0, 1.0);
        }
        u[k][i] = uu;
      }
    }
  }
  out.curve = build_curve(pr, maps, x);
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const auto seg = segment_points(out.curve, static_cast<int>(k));
    for (std::size_t i = 0; i < pr.rays[k].size(); ++i) {
      const Vec3 d = bezier_point(seg, u[k][i]) - pr.rays[k][i].origin;
      sum += (d - pr.rays[k][i].direction * pr.rays[k][i].direction.dot(d)).squaredNorm();
      ++count;
    }
  }
  out.residual = count > 0 ? std::sqrt(sum / count) : 0.0;
  out.u = u;
  out.ok = out.curve.control_points.size() == 3 * (n - 1) + 1;
  for (const Vec3& p : out.curve.control_points) out.ok = out.ok && p.allFinite();
  return out;
}

}  // namespace sketchlab::analytic
