#pragma once
// Nearest-neighbour and radius queries over a fixed set of points (a
// nanoflann kd-tree; the header keeps nanoflann out of its users).
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::hermite_rbf {

class PointTree {
 public:
  explicit PointTree(std::vector<Vec3> points);  // m
  ~PointTree();
  PointTree(PointTree&&) noexcept;
  PointTree& operator=(PointTree&&) noexcept;

  const std::vector<Vec3>& points() const { return points_; }
  // Index of the point nearest to p and its distance (m); (npos, +inf) when empty.
  std::pair<std::size_t, double> nearest(const Vec3& p) const;
  // Indices of the points with ‖q − p‖ < radius, ascending.
  std::vector<std::size_t> within(const Vec3& p, double radius) const;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  struct Index;
  std::vector<Vec3> points_;
  std::unique_ptr<Index> index_;
};

// One point per cell of a grid of `spacing` (m): the first in order of each
// cell (all points when spacing <= 0).
std::vector<Vec3> thin_points(const std::vector<Vec3>& points, double spacing);

}  // namespace sketchlab::hermite_rbf
