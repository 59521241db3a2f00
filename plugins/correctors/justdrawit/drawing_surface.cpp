#include "drawing_surface.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "promotion.hpp"

namespace sketchlab::justdrawit {

Plane plane_at_point(const Vec3& p, const Vec3& direction) {
  const double n = direction.norm();
  return {p, n > 0 ? Vec3(direction / n) : Vec3::UnitZ()};
}

Plane plane_through_two_points(const Vec3& p1, const Vec3& t1, const Vec3& p2, const Vec3& t2) {
  const Vec3 chord = p2 - p1;
  if (chord.norm() < 1e-12) return plane_at_point(p1, t1 + t2);
  const Vec3 e = chord.normalized();
  Vec3 a = e.unitOrthogonal();
  const Vec3 b = e.cross(a);
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (const Vec3& t : {t1, t2}) {
    const Eigen::Vector2d q(t.dot(a), t.dot(b));
    m += q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(m);
  const Eigen::Vector2d best = es.eigenvectors().col(1);  // largest eigenvalue
  Vec3 n = best.x() * a + best.y() * b;
  if (n.dot(t1) < 0) n = -n;
  return {0.5 * (p1 + p2), n.normalized()};
}

TriangleMesh extrusion_surface(const Points3& curve, const Vec3& direction, double extent) {
  TriangleMesh m;
  const Vec3 dir = direction.normalized();
  for (const Vec3& p : curve) {
    m.vertices.push_back(p - extent * dir);
    m.vertices.push_back(p + extent * dir);
  }
  for (int i = 0; i + 1 < static_cast<int>(curve.size()); ++i) {
    m.faces.push_back({2 * i, 2 * i + 2, 2 * i + 1});
    m.faces.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
  }
  return m;
}

TriangleMesh inflation_surface(const Points3& left, const Points3& right,
                               const Vec3& towards_viewer, int arc_samples) {
  TriangleMesh m;
  if (left.size() < 2 || right.size() < 2) return m;
  const int n = static_cast<int>(std::max(left.size(), right.size()));
  const Points3 l = resample(left, length(left) / (n - 1));
  const Points3 r = resample(right, length(right) / (n - 1));
  const int rows = static_cast<int>(std::min(l.size(), r.size()));
  const int cols = std::max(2, arc_samples);
  for (int i = 0; i < rows; ++i) {
    const Vec3 c = 0.5 * (l[i] + r[i]);
    const Vec3 span = r[i] - l[i];
    const double radius = 0.5 * span.norm();
    const Vec3 u = radius > 0 ? Vec3(span / (2 * radius)) : Vec3::UnitX();
    Vec3 w = towards_viewer - towards_viewer.dot(u) * u;
    w = w.norm() > 1e-12 ? Vec3(w.normalized()) : u.unitOrthogonal();
    for (int j = 0; j < cols; ++j) {
      const double th = std::numbers::pi * j / (cols - 1);
      m.vertices.push_back(c + radius * (-std::cos(th) * u + std::sin(th) * w));
    }
  }
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j + 1 < cols; ++j) {
      const int a = i * cols + j, b = a + 1, c = a + cols, e = c + 1;
      m.faces.push_back({a, c, b});
      m.faces.push_back({b, c, e});
    }
  return m;
}

std::optional<Vec3> ray_hit(const TriangleMesh& mesh, const Ray& ray) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& f : mesh.faces) {
    const Vec3& a = mesh.vertices[f[0]];
    const Vec3 e1 = mesh.vertices[f[1]] - a, e2 = mesh.vertices[f[2]] - a;
    const Vec3 p = ray.direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-18) continue;
    const Vec3 s = ray.origin - a;
    const double u = s.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const Vec3 q = s.cross(e1);
    const double v = ray.direction.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const double t = e2.dot(q) / det;
    if (t > 0 && t < best) best = t;
  }
  if (!std::isfinite(best)) return std::nullopt;
  return ray.origin + best * ray.direction;
}

std::optional<Points3> temporary_curve(const Camera& cam, const Points2& stroke,
                                       const std::vector<SceneCurve>& curves, const Plane& fallback,
                                       double d) {
  std::vector<std::optional<double>> known(stroke.size());
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const SceneCurve& c : curves)
      for (std::size_t j = 0; j < c.pts2.size(); ++j) {
        if ((c.pts2[j] - stroke[i]).norm() > 2 * d) continue;
        const double z = cam.eye_depth(c.pts3[j]);
        if (z < nearest) {
          nearest = z;
          known[i] = plane_depth(cam, fallback, c.pts3[j]);
        }
      }
  }
  const auto cum = cumulative(stroke);
  return lift(cam, fallback, stroke, fill_depths(cum, known, 0.0, 0.0), 0);
}

std::optional<std::vector<double>> surface_depths(const Camera& cam, const Plane& plane,
                                                  const Points2& stroke, const TriangleMesh& mesh) {
  std::vector<std::optional<double>> known(stroke.size());
  bool any = false;
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    const Ray r = cam.ray(stroke[i]);
    if (const auto hit = ray_hit(mesh, r)) {
      known[i] = plane_depth(cam, plane, *hit);
      any = any || known[i].has_value();
    }
  }
  if (!any) return std::nullopt;
  return fill_depths(cumulative(stroke), known, 0.0, 0.0);
}

}  // namespace sketchlab::justdrawit
