#include "point_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <nanoflann.hpp>

namespace sketchlab::hermite_rbf {

// nanoflann's dataset adaptor over the points.
struct PointTree::Index {
  const std::vector<Vec3>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][static_cast<Eigen::Index>(dim)]; }
  template <class B>
  bool kdtree_get_bbox(B&) const {
    return false;
  }
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Index>, Index, 3, std::size_t>;
  Tree tree;
  explicit Index(const std::vector<Vec3>* p) : points(p), tree(3, *this, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    tree.buildIndex();
  }
};

PointTree::PointTree(std::vector<Vec3> points) : points_(std::move(points)), index_(std::make_unique<Index>(&points_)) {}
PointTree::~PointTree() = default;
PointTree::PointTree(PointTree&& o) noexcept : points_(std::move(o.points_)), index_(std::make_unique<Index>(&points_)) {}
PointTree& PointTree::operator=(PointTree&& o) noexcept {
  points_ = std::move(o.points_);
  index_ = std::make_unique<Index>(&points_);
  return *this;
}

std::pair<std::size_t, double> PointTree::nearest(const Vec3& p) const {
  if (points_.empty()) return {npos, std::numeric_limits<double>::infinity()};
  std::size_t i = 0;
  double d2 = 0.0;
  index_->tree.knnSearch(p.data(), 1, &i, &d2);
  return {i, std::sqrt(d2)};
}

std::vector<std::size_t> PointTree::within(const Vec3& p, double radius) const {
  std::vector<std::pair<std::size_t, double>> found;
  if (!points_.empty()) index_->tree.radiusSearch(p.data(), radius * radius, found, nanoflann::SearchParams(32, 0.0f, false));
  std::vector<std::size_t> out;
  out.reserve(found.size());
  for (const auto& [i, d2] : found) out.push_back(i);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Vec3> thin_points(const std::vector<Vec3>& points, double spacing) {
  if (!(spacing > 0.0)) return points;
  std::set<std::array<long, 3>> taken;
  std::vector<Vec3> out;
  for (const Vec3& p : points) {
    const std::array<long, 3> key{static_cast<long>(std::floor(p.x() / spacing)), static_cast<long>(std::floor(p.y() / spacing)),
                                  static_cast<long>(std::floor(p.z() / spacing))};
    if (taken.insert(key).second) out.push_back(p);
  }
  return out;
}

}  // namespace sketchlab::hermite_rbf
