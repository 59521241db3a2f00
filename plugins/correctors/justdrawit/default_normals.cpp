#include "default_normals.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace sketchlab::justdrawit {

namespace {

Vec3 reject(const Vec3& n, const Vec3& t) {
  const Vec3 r = n - n.dot(t) * t;
  return r.norm() > 1e-12 ? Vec3(r.normalized()) : Vec3(t.unitOrthogonal());
}

std::vector<Vec3> tangents(const Points3& pts, bool closed) {
  const std::size_t n = pts.size();
  std::vector<Vec3> t(n, Vec3::UnitX());
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 a = i > 0 ? pts[i - 1] : (closed && n > 2 ? pts[n - 2] : pts[i]);
    Vec3 b = i + 1 < n ? pts[i + 1] : (closed && n > 2 ? pts[1] : pts[i]);
    Vec3 d = b - a;
    if (d.norm() < 1e-15) d = pts.back() - pts.front();
    if (d.norm() > 1e-15) t[i] = d.normalized();
  }
  return t;
}

}  // namespace

Vec3 slerp(const Vec3& a, const Vec3& b, double t) {
  const double c = std::clamp(a.dot(b), -1.0, 1.0);
  const double th = std::acos(c);
  if (th < 1e-9) return ((1 - t) * a + t * b).normalized();
  if (std::abs(th - M_PI) < 1e-9) {
    // Antipodal: rotate about any axis perpendicular to a.
    const Vec3 axis = a.unitOrthogonal();
    return Eigen::AngleAxisd(t * th, axis) * a;
  }
  return (std::sin((1 - t) * th) * a + std::sin(t * th) * b) / std::sin(th);
}

PlaneFit fit_plane(const Points3& pts) {
  PlaneFit f;
  if (pts.empty()) return f;
  for (const Vec3& p : pts) f.centroid += p;
  f.centroid /= static_cast<double>(pts.size());
  Mat3 cov = Mat3::Zero();
  for (const Vec3& p : pts) cov += (p - f.centroid) * (p - f.centroid).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> es(cov);
  f.normal = es.eigenvectors().col(0).normalized();
  const double l1 = es.eigenvalues()(1), l2 = es.eigenvalues()(2);
  f.degenerate = !(l1 > 1e-10 * std::max(l2, 1e-300));
  for (const Vec3& p : pts) f.max_distance = std::max(f.max_distance, std::abs((p - f.centroid).dot(f.normal)));
  return f;
}

Vec3 pin_normal(const Points3& a, std::size_t ia, const Points3& b, std::size_t ib) {
  Points3 pts;
  auto take = [&](const Points3& c, std::size_t i) {
    const std::size_t lo = i >= 5 ? i - 5 : 0, hi = std::min(c.size(), lo + 10);
    for (std::size_t k = lo; k < hi; ++k) pts.push_back(c[k]);
  };
  take(a, ia);
  take(b, ib);
  return fit_plane(pts).normal;
}

std::vector<Vec3> default_normals(const Points3& pts, bool closed, const std::vector<NormalPin>& pins,
                                  double planar_tolerance, const Vec3& fallback) {
  const std::size_t n = pts.size();
  std::vector<Vec3> out(n, Vec3::UnitZ());
  if (n < 2) return out;
  const std::vector<Vec3> t = tangents(pts, closed);
  const PlaneFit fit = fit_plane(pts);
  const auto cum = cumulative(pts);
  std::vector<std::pair<std::size_t, Vec3>> keys;
  if (!fit.degenerate && fit.max_distance <= planar_tolerance) {
    // Planar: tangent x plane normal, oriented out from the centroid at the
    // curve's mid-point (by arclength).
    std::size_t mid = 0;
    while (mid + 1 < n && cum[mid] < 0.5 * cum.back()) ++mid;
    Vec3 pn = fit.normal;
    if (t[mid].cross(pn).dot(pts[mid] - fit.centroid) < 0) pn = -pn;
    for (std::size_t i = 0; i < n; ++i) out[i] = reject(t[i].cross(pn), t[i]);
    for (const NormalPin& p : pins)
      if (p.index < n) out[p.index] = reject(p.normal, t[p.index]);
    return out;
  }
  if (!fit.degenerate) {
    // Non-planar: keys where the tangent is perpendicular to v (sign change
    // of t·v between neighbours), normal v pointing out from the centroid.
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const Vec3 v0 = pts[i] - fit.centroid, v1 = pts[i + 1] - fit.centroid;
      const double a = t[i].dot(v0), b = t[i + 1].dot(v1);
      if ((a <= 0 && b > 0) || (a >= 0 && b < 0)) {
        const std::size_t k = std::abs(a) <= std::abs(b) ? i : i + 1;
        const Vec3 v = pts[k] - fit.centroid;
        if (v.norm() > 1e-12) keys.emplace_back(k, reject(v, t[k]));
      }
    }
  }
  for (const NormalPin& p : pins)
    if (p.index < n) {
      Vec3 pn = reject(p.normal, t[p.index]);
      // A pin's sign follows the nearest default key, so the ribbon does not flip.
      std::erase_if(keys, [&](const auto& k) { return k.first == p.index; });
      const std::pair<std::size_t, Vec3>* nearest = nullptr;
      for (const auto& k : keys)
        if (!nearest || std::abs(static_cast<double>(k.first) - static_cast<double>(p.index)) <
                            std::abs(static_cast<double>(nearest->first) - static_cast<double>(p.index)))
          nearest = &k;
      if (nearest && nearest->second.dot(pn) < 0) pn = -pn;
      keys.emplace_back(p.index, pn);
    }
  std::sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (keys.empty()) {
    for (std::size_t i = 0; i < n; ++i) out[i] = reject(fallback, t[i]);
    return out;
  }
  // Spherical interpolation between keys (§6), then perpendicular to the tangent.
  for (std::size_t i = 0; i <= keys.front().first; ++i) out[i] = keys.front().second;
  for (std::size_t i = keys.back().first; i < n; ++i) out[i] = keys.back().second;
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    const auto& [ia, na] = keys[k];
    const auto& [ib, nb] = keys[k + 1];
    const double span = cum[ib] - cum[ia];
    for (std::size_t i = ia; i <= ib; ++i)
      out[i] = slerp(na, nb, span > 0 ? (cum[i] - cum[ia]) / span : 0.0);
  }
  if (closed && keys.size() >= 1) {
    // Wrap from the last key across the seam to the first.
    const auto& [ia, na] = keys.back();
    const auto& [ib, nb] = keys.front();
    const double span = (cum.back() - cum[ia]) + cum[ib];
    for (std::size_t i = ia; i < n; ++i)
      out[i] = slerp(na, nb, span > 0 ? (cum[i] - cum[ia]) / span : 0.0);
    for (std::size_t i = 0; i <= ib; ++i)
      out[i] = slerp(na, nb, span > 0 ? (cum.back() - cum[ia] + cum[i]) / span : 1.0);
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = reject(out[i], t[i]);
  return out;
}

}  // namespace sketchlab::justdrawit
