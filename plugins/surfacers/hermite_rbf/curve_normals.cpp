#include "curve_normals.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "normal_orientation.hpp"
#include "plane_fit.hpp"

namespace sketchlab::hermite_rbf {
namespace {

// Curves cross at a node when two of them meet at more than 20°.
const double min_crossing_sine = std::sin(20.0 * std::numbers::pi / 180.0);

int cyclic_distance(int a, int b, int n, bool closed) {
  const int d = std::abs(a - b);
  return closed ? std::min(d, n - d) : d;
}

// v carried along the samples from `from` to `to` (forwards, across the seam
// of a closed curve) by the rotation-minimising frame: each step turns it by
// the smallest rotation taking one tangent to the next (Wang, Jüttler, Zheng
// & Liu 2008, "Computation of rotation minimizing frames", the rotation
// method), so a curve's bending does not count as disagreement.
Vec3 transport(const CurveSamples& s, int from, int to, Vec3 v) {
  const int n = static_cast<int>(s.points.size());
  const int steps = to >= from ? to - from : to + n - from;
  for (int k = 0; k < steps; ++k) {
    const Vec3& a = s.tangents[static_cast<std::size_t>((from + k) % n)];
    const Vec3& b = s.tangents[static_cast<std::size_t>((from + k + 1) % n)];
    v = Eigen::Quaterniond::FromTwoVectors(a, b) * v;
  }
  return v;
}

Vec3 any_perpendicular(const Vec3& v) {
  const Vec3 axis = std::abs(v.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return v.cross(axis).normalized();
}

}  // namespace

Vec3 slerp(const Vec3& a, const Vec3& b, double u) {
  const double d = std::clamp(a.dot(b), -1.0, 1.0);
  if (d > 0.9995) return ((1.0 - u) * a + u * b).normalized();
  if (d < -0.9999) {
    // Opposite vectors: any great circle works; turn about a fixed perpendicular.
    const Vec3 axis = any_perpendicular(a);
    return Eigen::AngleAxisd(std::numbers::pi * u, axis) * a;
  }
  const double theta = std::acos(d);
  return ((std::sin((1.0 - u) * theta) * a + std::sin(u * theta) * b) / std::sin(theta)).normalized();
}

std::vector<NormalKey> default_normal_keys(const CurveSamples& s, const NormalParams& params) {
  const int n = static_cast<int>(s.points.size());
  if (n < 2) return {};
  const PrincipalAxes ax = principal_axes(s.points);
  const double length = s.spacing * (s.closed ? n : n - 1);
  if (std::sqrt(ax.spread[1]) <= 1e-6 * length) return {};  // a straight line: no plane, no centroid rule
  double off_plane = 0.0;
  for (const Vec3& p : s.points) off_plane = std::max(off_plane, std::abs((p - ax.centroid).dot(ax.axes[2])));
  std::vector<NormalKey> keys;
  if (off_plane <= params.planarity * length) {
    // Planar: tangent × plane normal, oriented out from the centroid as seen
    // at the curve's mid-point (§6).
    for (int i = 0; i < n; ++i) keys.push_back({i, s.tangents[static_cast<std::size_t>(i)].cross(ax.axes[2])});
    const int mid = n / 2;
    double side = keys[static_cast<std::size_t>(mid)].normal.dot(s.points[static_cast<std::size_t>(mid)] - ax.centroid);
    if (std::abs(side) <= 1e-9 * length) {
      side = 0.0;  // mid-point at the centroid: vote over the whole curve
      for (int i = 0; i < n; ++i)
        side += keys[static_cast<std::size_t>(i)].normal.dot(s.points[static_cast<std::size_t>(i)] - ax.centroid);
    }
    for (NormalKey& k : keys) k.normal = (side < 0.0 ? -k.normal : k.normal).normalized();
    return keys;
  }
  // Non-planar: where the tangent is perpendicular to v (point -> centroid),
  // the normal is along v; we orient it outwards (-v) like the planar rule.
  std::vector<double> f(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Vec3 v = ax.centroid - s.points[static_cast<std::size_t>(i)];
    f[static_cast<std::size_t>(i)] = v.norm() > 0.0 ? s.tangents[static_cast<std::size_t>(i)].dot(v.normalized()) : 1.0;
  }
  auto key_at = [&](int i) {
    const Vec3 out = s.points[static_cast<std::size_t>(i)] - ax.centroid;
    if (out.norm() > 0.0) keys.push_back({i, out.normalized()});
  };
  const int last = s.closed ? n : n - 1;
  for (int i = 0; i < last; ++i) {
    const int j = (i + 1) % n;
    const double a = f[static_cast<std::size_t>(i)], b = f[static_cast<std::size_t>(j)];
    if ((a <= 0.0 && b > 0.0) || (a >= 0.0 && b < 0.0)) key_at(std::abs(a) <= std::abs(b) ? i : j);
  }
  if (keys.empty()) {
    const auto best = std::min_element(f.begin(), f.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    key_at(static_cast<int>(best - f.begin()));
  }
  std::sort(keys.begin(), keys.end(), [](const NormalKey& a, const NormalKey& b) { return a.sample < b.sample; });
  keys.erase(std::unique(keys.begin(), keys.end(), [](const NormalKey& a, const NormalKey& b) { return a.sample == b.sample; }),
             keys.end());
  return keys;
}

void propagate_normals(CurveSamples& s, std::vector<NormalKey> keys) {
  const int n = static_cast<int>(s.points.size());
  s.normals.assign(static_cast<std::size_t>(n), Vec3::Zero());
  keys.erase(std::remove_if(keys.begin(), keys.end(),
                            [&](const NormalKey& k) { return k.sample < 0 || k.sample >= n || !(k.normal.norm() > 0.0) || !k.normal.allFinite(); }),
             keys.end());
  if (keys.empty()) return;
  std::stable_sort(keys.begin(), keys.end(), [](const NormalKey& a, const NormalKey& b) { return a.sample < b.sample; });
  for (NormalKey& k : keys) k.normal.normalize();
  std::vector<Vec3> raw(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    const int a = keys[k].sample, b = keys[k + 1].sample;
    for (int i = a; i <= b; ++i)
      raw[static_cast<std::size_t>(i)] = b > a ? slerp(keys[k].normal, keys[k + 1].normal, double(i - a) / (b - a)) : keys[k + 1].normal;
  }
  const NormalKey& first = keys.front();
  const NormalKey& last = keys.back();
  if (s.closed) {
    // Across the seam: from the last key to the first one, n samples later.
    const int span = first.sample + n - last.sample;
    for (int i = last.sample; i < last.sample + span; ++i) {
      const Vec3 v = span > 0 ? slerp(last.normal, first.normal, double(i - last.sample) / span) : last.normal;
      raw[static_cast<std::size_t>(i % n)] = v;
    }
  } else {
    for (int i = 0; i <= first.sample; ++i) raw[static_cast<std::size_t>(i)] = first.normal;
    for (int i = last.sample; i < n; ++i) raw[static_cast<std::size_t>(i)] = last.normal;
  }
  for (int i = 0; i < n; ++i) {
    const Vec3& t = s.tangents[static_cast<std::size_t>(i)];
    const Vec3 r = raw[static_cast<std::size_t>(i)] - raw[static_cast<std::size_t>(i)].dot(t) * t;
    if (r.norm() > 1e-6) s.normals[static_cast<std::size_t>(i)] = r.normalized();
  }
}

void assign_normals(std::vector<CurveSamples>& curves, const Network& network, const NormalParams& params) {
  std::map<CurveId, std::size_t> index;
  for (std::size_t i = 0; i < curves.size(); ++i) index[curves[i].curve] = i;
  std::vector<bool> exported(curves.size(), false);
  std::vector<std::vector<NormalKey>> defaults(curves.size());
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const NetworkCurve& nc = *network.find_curve(curves[c].curve);
    if (!nc.normals.empty()) {
      // The corrector's own normals (JustDrawIt defaults and pins) win.
      exported[c] = true;
      std::vector<NormalKey> keys;
      for (const CurveNormal& cn : nc.normals) keys.push_back({nearest_sample(curves[c], cn.t), cn.normal});
      propagate_normals(curves[c], std::move(keys));
      continue;
    }
    defaults[c] = default_normal_keys(curves[c], params);
    propagate_normals(curves[c], defaults[c]);
  }

  // Intersections (§6): a plane fitted to the samples each side of the node
  // on every curve through it, signed like the curves' normals there.
  struct Crossing {
    std::vector<std::pair<std::size_t, int>> at;  // (curve index, sample)
    Vec3 normal, position;
    bool fixed = false;  // signed by exported normals
  };
  std::vector<Crossing> crossings;
  const int w = params.intersection_window;
  for (const auto& [node_id, node] : network.nodes()) {
    Crossing x;
    for (const NodeIncidence& inc : node.incidences)
      if (auto it = index.find(inc.curve); it != index.end()) x.at.emplace_back(it->second, nearest_sample(curves[it->second], inc.t));
    std::sort(x.at.begin(), x.at.end());
    x.at.erase(std::unique(x.at.begin(), x.at.end()), x.at.end());
    if (x.at.size() < 2) continue;
    std::vector<Vec3> pts;
    for (const auto& [c, i0] : x.at) {
      const CurveSamples& s = curves[c];
      const int n = static_cast<int>(s.points.size());
      for (int d = -w; d <= w; ++d) {
        int i = i0 + d;
        if (s.closed) i = ((i % n) + n) % n;
        else if (i < 0 || i >= n) continue;
        pts.push_back(s.points[static_cast<std::size_t>(i)]);
      }
    }
    // Curves that only continue each other there (a stroke and its mirror
    // twin meeting at the mirror plane, say) share one tangent: the plane
    // through their samples is their osculating plane, the Frenet frame §6
    // warns against, not the surface's tangent plane. Only crossings count.
    bool crossing = false;
    for (std::size_t i = 0; i < x.at.size() && !crossing; ++i)
      for (std::size_t j = i + 1; j < x.at.size() && !crossing; ++j)
        crossing = curves[x.at[i].first].tangents[static_cast<std::size_t>(x.at[i].second)]
                       .cross(curves[x.at[j].first].tangents[static_cast<std::size_t>(x.at[j].second)])
                       .norm() >= min_crossing_sine;
    if (!crossing) continue;
    const PrincipalAxes ax = principal_axes(pts);
    if (!(ax.spread[1] > 1e-6 * ax.spread[0])) continue;  // tangent curves: no plane
    Vec3 reference = Vec3::Zero(), exported_reference = Vec3::Zero();
    x.position = Vec3::Zero();
    for (const auto& [c, i0] : x.at) {
      const Vec3& n = curves[c].normals[static_cast<std::size_t>(i0)];
      reference += n;
      if (exported[c]) exported_reference += n, x.fixed = true;
      x.position += curves[c].points[static_cast<std::size_t>(i0)];
    }
    x.position /= double(x.at.size());
    x.normal = ax.axes[2];
    if ((x.fixed ? exported_reference : reference).dot(x.normal) < 0.0) x.normal = -x.normal;
    crossings.push_back(std::move(x));
  }

  // One orientation across the network (normal_orientation.hpp): crossings
  // next to each other along a curve are neighbours. Per-curve rules may
  // disagree between neighbouring curves; the surface must not fold there.
  std::vector<std::vector<std::pair<int, std::size_t>>> along(curves.size());  // (sample, crossing)
  for (std::size_t k = 0; k < crossings.size(); ++k)
    for (const auto& [c, i0] : crossings[k].at) along[c].emplace_back(i0, k);
  std::vector<Agreement> edges;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    std::sort(along[c].begin(), along[c].end());
    auto link = [&](std::size_t i, std::size_t j) {
      const auto [si, ki] = along[c][i];
      const auto [sj, kj] = along[c][j];
      const Vec3 carried = transport(curves[c], si, sj, crossings[ki].normal);
      edges.push_back({ki, kj, carried.dot(crossings[kj].normal)});
    };
    for (std::size_t i = 0; i + 1 < along[c].size(); ++i) link(i, i + 1);
    if (curves[c].closed && along[c].size() > 2) link(along[c].size() - 1, 0);
  }
  if (params.network_rule) {
    std::vector<Vec3> normals, positions;
    std::vector<bool> fixed;
    for (const Crossing& x : crossings) normals.push_back(x.normal), positions.push_back(x.position), fixed.push_back(x.fixed);
    const std::vector<bool> flip = consistent_flips(normals, positions, edges, fixed);
    for (std::size_t k = 0; k < crossings.size(); ++k)
      if (flip[k]) crossings[k].normal = -crossings[k].normal;
  }

  // A curve through crossings takes their normals (the curves around them
  // say what the surface does there; the per-curve rules only guess); the
  // default keys remain beyond its first and last crossing (a dangling end),
  // signed like the crossing they continue. Curves without crossings keep
  // the default rules.
  for (std::size_t c = 0; c < curves.size(); ++c) {
    if (exported[c] || along[c].empty()) continue;
    std::vector<NormalKey> keys;
    for (const auto& [i0, k] : along[c]) keys.push_back({i0, crossings[k].normal});
    if (!params.network_rule) {
      // §6: the default keys stay wherever no intersection is near.
      const int n = static_cast<int>(curves[c].points.size());
      for (const NormalKey& d : defaults[c])
        if (std::none_of(along[c].begin(), along[c].end(), [&](const auto& x) { return cyclic_distance(d.sample, x.first, n, curves[c].closed) <= w; }))
          keys.push_back(d);
    } else if (!curves[c].closed) {
      const int first = along[c].front().first, last = along[c].back().first;
      const bool flip_start = curves[c].normals[static_cast<std::size_t>(first)].dot(crossings[along[c].front().second].normal) < 0.0;
      const bool flip_end = curves[c].normals[static_cast<std::size_t>(last)].dot(crossings[along[c].back().second].normal) < 0.0;
      for (const NormalKey& d : defaults[c]) {
        if (d.sample < first - w) keys.push_back({d.sample, flip_start ? -d.normal : d.normal});
        if (d.sample > last + w) keys.push_back({d.sample, flip_end ? -d.normal : d.normal});
      }
    }
    propagate_normals(curves[c], std::move(keys));
  }
}

}  // namespace sketchlab::hermite_rbf
