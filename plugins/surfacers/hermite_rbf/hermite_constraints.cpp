#include "hermite_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "plane_fit.hpp"
#include "point_tree.hpp"

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
  if (!(radius > 0.0)) return in;
  // A site: one position with its value and derivative constraints.
  struct Site {
    Vec3 p;
    bool point = false;
    std::optional<Vec3> normal;
    std::vector<Vec3> tangents;
  };
  std::vector<Site> sites;
  std::map<std::array<double, 3>, std::size_t> at;
  auto site_of = [&](const Vec3& p) -> Site& {
    const auto [it, added] = at.try_emplace({p.x(), p.y(), p.z()}, sites.size());
    if (added) sites.push_back({p, false, std::nullopt, {}});
    return sites[it->second];
  };
  for (const Vec3& p : in.points) site_of(p).point = true;
  for (std::size_t i = 0; i < in.normals.size(); ++i) {
    Site& s = site_of(in.normal_points[i]);
    if (!s.normal) s.normal = in.normals[i];
  }
  for (std::size_t i = 0; i < in.tangents.size(); ++i) site_of(in.tangent_points[i]).tangents.push_back(in.tangents[i]);

  // Greedy in order: a site merges into the earliest kept site within radius.
  std::vector<Vec3> positions;
  for (const Site& s : sites) positions.push_back(s.p);
  const PointTree tree(std::move(positions));
  std::vector<Site> kept;
  std::vector<std::size_t> kept_as(sites.size(), PointTree::npos);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    Site& s = sites[i];
    std::size_t target = PointTree::npos;
    for (std::size_t j : tree.within(s.p, radius))
      if (j < i && kept_as[j] != PointTree::npos) {
        target = kept_as[j];
        break;
      }
    if (target == PointTree::npos) {
      kept_as[i] = kept.size();
      kept.push_back(std::move(s));
      continue;
    }
    Site& k = kept[target];
    k.point = k.point || s.point;
    if (!k.normal) k.normal = s.normal;
    k.tangents.insert(k.tangents.end(), s.tangents.begin(), s.tangents.end());
  }

  HermiteConstraints out;
  for (const Site& k : kept) {
    if (k.point) out.points.push_back(k.p);
    if (k.normal) {
      out.normal_points.push_back(k.p);
      out.normals.push_back(*k.normal);
      continue;  // ∇f = n already gives ∇f·t = 0: a tangent row would repeat it
    }
    std::vector<Vec3> distinct;
    for (const Vec3& t : k.tangents) {
      if (std::any_of(distinct.begin(), distinct.end(), [&](const Vec3& d) { return std::abs(d.dot(t)) > 0.9; })) continue;
      distinct.push_back(t);
      out.tangent_points.push_back(k.p);
      out.tangents.push_back(t);
    }
  }
  return out;
}

namespace {

bool position_less(const Vec3& a, const Vec3& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

// Sorts positions (and their directions alike) by (position, direction).
void sort_pairs(std::vector<Vec3>& positions, std::vector<Vec3>& directions) {
  std::vector<std::size_t> order(positions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (positions[a] != positions[b]) return position_less(positions[a], positions[b]);
    return position_less(directions[a], directions[b]);
  });
  std::vector<Vec3> p, d;
  for (std::size_t i : order) p.push_back(positions[i]), d.push_back(directions[i]);
  positions = std::move(p);
  directions = std::move(d);
}

}  // namespace

HermiteConstraints canonical_order(HermiteConstraints c) {
  std::sort(c.points.begin(), c.points.end(), position_less);
  sort_pairs(c.tangent_points, c.tangents);
  sort_pairs(c.normal_points, c.normals);
  return c;
}

void check_constraints(const HermiteConstraints& cons) {
  if (cons.normals.empty())
    throw std::invalid_argument("hermite_rbf: no normal constraint: with only f = 0 and ∇f·t = 0 the interpolant is "
                                "f ≡ 0; the curves need normals (straight lines have none by default)");
  if (cons.points.size() < 3) throw std::invalid_argument("hermite_rbf: degenerate input: fewer than 3 distinct point constraints");
  std::vector<Vec3> all = cons.points;
  all.insert(all.end(), cons.normal_points.begin(), cons.normal_points.end());
  all.insert(all.end(), cons.tangent_points.begin(), cons.tangent_points.end());
  for (const Vec3& p : all)
    if (!p.allFinite()) throw std::invalid_argument("hermite_rbf: non-finite constraint position");
  for (const Vec3& d : cons.normals)
    if (!d.allFinite() || !(d.norm() > 0.0)) throw std::invalid_argument("hermite_rbf: zero or non-finite normal constraint");
  const PrincipalAxes ax = principal_axes(all);
  if (!(std::sqrt(ax.spread[1]) > 1e-6 * std::sqrt(ax.spread[0])) || !(ax.spread[0] > 0.0))
    throw std::invalid_argument("hermite_rbf: degenerate input: the constraints lie on one straight line "
                                "(or coincide); a surface needs curves spanning at least a plane");
}

}  // namespace sketchlab::hermite_rbf
