#include "partition_cells.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sketchlab::hermite_rbf {
namespace {

struct Builder {
  const HermiteConstraints& c;
  const ConstraintIndex index;
  const PartitionParams& params;
  std::vector<PartitionCell> leaves;

  Builder(const HermiteConstraints& constraints, const PartitionParams& p) : c(constraints), index(constraints), params(p) {}

  const Vec3& at(std::size_t k) const { return index.position(c, k); }
  double support_radius(double half_edge) const { return params.overlap * half_edge * std::sqrt(3.0); }

  int rows_of(const std::vector<std::size_t>& members) const {
    int rows = 0;
    for (std::size_t k : members) rows += index.rows(k);
    return rows;
  }
  int normals_of(const std::vector<std::size_t>& members) const {
    int n = 0;
    for (std::size_t k : members) n += index.is_normal(k);
    return n;
  }

  // Ancestors' supports, innermost last, to grow a sparse leaf's support from.
  struct Support {
    Vec3 center;
    double radius;
    const std::vector<std::size_t>* members;
  };

  // Grows the leaf's fit sphere to the nearest constraints that give
  // min_rows rows and min_normals normals, taken from the innermost ancestor
  // whose support contains the grown sphere (the root holds every constraint).
  void grow(PartitionCell& leaf, const std::vector<Support>& ancestors) const {
    for (auto a = ancestors.rbegin(); a != ancestors.rend(); ++a) {
      const bool root = a + 1 == ancestors.rend();
      const std::vector<std::size_t>& pool = *a->members;
      if (!root && (rows_of(pool) < params.min_rows || normals_of(pool) < params.min_normals)) continue;
      std::vector<std::pair<double, std::size_t>> by_distance;
      by_distance.reserve(pool.size());
      for (std::size_t k : pool) by_distance.emplace_back((at(k) - leaf.center).norm(), k);
      if (by_distance.empty()) return;
      // The nearest few sorted (nth_element, then sort that prefix), more
      // only when they do not give enough rows and normals.
      double reach = 0.0;
      for (std::size_t take = std::min(by_distance.size(), std::size_t(2 * params.min_rows));; take = std::min(by_distance.size(), 2 * take)) {
        std::nth_element(by_distance.begin(), by_distance.begin() + static_cast<std::ptrdiff_t>(take - 1), by_distance.end());
        std::sort(by_distance.begin(), by_distance.begin() + static_cast<std::ptrdiff_t>(take));
        int rows = 0, normals = 0;
        bool enough = false;
        for (std::size_t i = 0; i < take && !enough; ++i) {
          rows += index.rows(by_distance[i].second);
          normals += index.is_normal(by_distance[i].second);
          reach = by_distance[i].first;
          enough = rows >= params.min_rows && normals >= params.min_normals;
        }
        if (enough || take == by_distance.size()) break;
      }
      // Strictly beyond the last one taken (ties included), and never smaller
      // than the cell's own support.
      const double radius = std::max(leaf.radius, reach * (1.0 + 1e-9) + 1e-12);
      if (!root && (leaf.center - a->center).norm() + radius >= a->radius) continue;
      leaf.fit_radius = radius;
      leaf.members.clear();
      for (std::size_t k : pool)
        if ((at(k) - leaf.center).squaredNorm() < radius * radius) leaf.members.push_back(k);
      leaf.rows = rows_of(leaf.members);
      return;
    }
  }

  void split(const Vec3& center, double half_edge, int depth, std::vector<std::size_t> members,
             std::vector<Support>& ancestors) {
    const double radius = support_radius(half_edge);
    const int rows = rows_of(members);
    if (rows > params.max_rows && depth < params.max_depth) {
      ancestors.push_back({center, radius, &members});
      for (int child = 0; child < 8; ++child) {
        const Vec3 offset(child & 1 ? 0.5 : -0.5, child & 2 ? 0.5 : -0.5, child & 4 ? 0.5 : -0.5);
        const Vec3 cc = center + half_edge * offset;
        const double cr = support_radius(0.5 * half_edge);
        // overlap >= 1 puts the child's sphere inside the parent's: its
        // members are among the parent's.
        std::vector<std::size_t> inside;
        for (std::size_t k : members)
          if ((at(k) - cc).squaredNorm() < cr * cr) inside.push_back(k);
        split(cc, 0.5 * half_edge, depth + 1, std::move(inside), ancestors);
      }
      ancestors.pop_back();
      return;
    }
    PartitionCell leaf;
    leaf.center = center;
    leaf.half_edge = half_edge;
    leaf.radius = leaf.fit_radius = radius;
    leaf.depth = depth;
    leaf.rows = rows;
    leaf.members = std::move(members);
    if (leaf.rows < params.min_rows || normals_of(leaf.members) < params.min_normals) grow(leaf, ancestors);
    leaves.push_back(std::move(leaf));
  }
};

}  // namespace

std::vector<PartitionCell> partition_cells(const HermiteConstraints& constraints, const Box3& domain,
                                           const PartitionParams& params) {
  Builder b(constraints, params);
  std::vector<std::size_t> all(b.index.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  const double half_edge = 0.5 * std::max(domain.sizes().maxCoeff(), 1e-9);
  const Vec3 center = domain.center();
  // The root's support holds every constraint of the domain; constraints
  // outside it (none when the domain is their padded box) are dropped.
  const double radius = b.support_radius(half_edge);
  std::erase_if(all, [&](std::size_t k) { return (b.at(k) - center).squaredNorm() >= radius * radius; });
  std::vector<Builder::Support> ancestors;
  // The root's own list serves as the last resort of grow().
  std::vector<std::size_t> root_pool = all;
  ancestors.push_back({center, radius, &root_pool});
  b.split(center, half_edge, 0, std::move(all), ancestors);
  return std::move(b.leaves);
}

}  // namespace sketchlab::hermite_rbf
