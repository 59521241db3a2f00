#include "hermite_constraints.hpp"

#include <cmath>

#include "plane_fit.hpp"
#include "point_buckets.hpp"

namespace sketchlab::hermite_rbf {
namespace {

// Max distance of samples (a, b) exclusive from the line fitted to samples [a, b].
double deviation(const std::vector<Vec3>& p, int a, int b) {
  if (b - a < 2) return 0.0;
  const std::vector<Vec3> window(p.begin() + a, p.begin() + b + 1);
  const PrincipalAxes ax = principal_axes(window);
  double d = 0.0;
  for (int i = a + 1; i < b; ++i) {
    const Vec3 v = p[static_cast<std::size_t>(i)] - ax.centroid;
    d = std::max(d, (v - v.dot(ax.axes[0]) * ax.axes[0]).norm());
  }
  return d;
}

}  // namespace

void pick_constraints(const CurveSamples& s, const SamplingParams& params, HermiteConstraints& out) {
  const int n = static_cast<int>(s.points.size());
  if (n == 0) return;
  const double tolerance = params.deviation_factor * s.spacing;
  int last_point = 0, last_tangent = -1, last_normal = -1;
  auto place = [&](int i) {
    const auto k = static_cast<std::size_t>(i);
    out.points.push_back(s.points[k]);
    const Vec3& nrm = s.normals[k];
    const bool has_normal = nrm.squaredNorm() > 0.5;
    bool normal = false;
    if (has_normal) {
      normal = last_normal < 0 || i - last_normal >= params.normal_stride ||
               1.0 - nrm.dot(s.normals[static_cast<std::size_t>(last_normal)]) > params.normal_change;
      if (normal) {
        out.normal_points.push_back(s.points[k]);
        out.normals.push_back(nrm);
        last_normal = i;
      }
    }
    const bool tangent = last_tangent < 0 || i - last_tangent >= params.tangent_stride ||
                         1.0 - s.tangents[k].dot(s.tangents[static_cast<std::size_t>(last_tangent)]) > params.tangent_change;
    if (tangent || normal) {
      if (!normal) {
        out.tangent_points.push_back(s.points[k]);
        out.tangents.push_back(s.tangents[k]);
      }
      last_tangent = i;
    }
  };
  place(0);
  for (int j = 1; j < n; ++j) {
    const bool end = j == n - 1 && !s.closed;
    if (end || j - last_point >= params.point_stride || deviation(s.points, last_point, j) > tolerance) {
      place(j);
      last_point = j;
    }
  }
}

HermiteConstraints merge_duplicates(const HermiteConstraints& in, double radius) {
  HermiteConstraints out;
  if (!(radius > 0.0)) return in;
  const double r2 = radius * radius;
  PointBuckets points(radius), normals(radius), tangents(radius);
  for (const Vec3& p : in.points) {
    if (points.any_near(p, [&](int id) { return (out.points[static_cast<std::size_t>(id)] - p).squaredNorm() <= r2; })) continue;
    points.add(p, static_cast<int>(out.points.size()));
    out.points.push_back(p);
  }
  for (std::size_t i = 0; i < in.normals.size(); ++i) {
    const Vec3& p = in.normal_points[i];
    if (normals.any_near(p, [&](int id) { return (out.normal_points[static_cast<std::size_t>(id)] - p).squaredNorm() <= r2; })) continue;
    normals.add(p, static_cast<int>(out.normals.size()));
    out.normal_points.push_back(p);
    out.normals.push_back(in.normals[i]);
  }
  for (std::size_t i = 0; i < in.tangents.size(); ++i) {
    const Vec3& p = in.tangent_points[i];
    const Vec3& t = in.tangents[i];
    if (normals.any_near(p, [&](int id) { return (out.normal_points[static_cast<std::size_t>(id)] - p).squaredNorm() <= r2; })) continue;
    if (tangents.any_near(p, [&](int id) {
          const auto k = static_cast<std::size_t>(id);
          return (out.tangent_points[k] - p).squaredNorm() <= r2 && std::abs(out.tangents[k].dot(t)) > 0.9;
        }))
      continue;
    tangents.add(p, static_cast<int>(out.tangents.size()));
    out.tangent_points.push_back(p);
    out.tangents.push_back(t);
  }
  return out;
}

}  // namespace sketchlab::hermite_rbf
