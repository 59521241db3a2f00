#pragma once
// Points bucketed in a uniform grid of cell `radius`: everything within
// `radius` of a query lies in the 27 cells around it.
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::hermite_rbf {

class PointBuckets {
 public:
  explicit PointBuckets(double radius) : r_(radius) {}
  void add(const Vec3& p, int id) { cells_[key(p)].push_back(id); }
  // True when pred(id) holds for some id bucketed around p (early exit).
  template <class F>
  bool any_near(const Vec3& p, F&& pred) const {
    const auto k = key(p);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == cells_.end()) continue;
          for (int id : it->second)
            if (pred(id)) return true;
        }
    return false;
  }

 private:
  std::array<long, 3> key(const Vec3& p) const {
    return {static_cast<long>(std::floor(p.x() / r_)), static_cast<long>(std::floor(p.y() / r_)),
            static_cast<long>(std::floor(p.z() / r_))};
  }
  double r_;
  std::map<std::array<long, 3>, std::vector<int>> cells_;
};

}  // namespace sketchlab::hermite_rbf
