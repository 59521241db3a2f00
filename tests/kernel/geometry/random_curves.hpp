#pragma once
// Seeded random poly-Bézier curves for the geometry tests.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab::test {

// A curve with k segments and control points uniform in [-1, 1]^3 (so
// loops, cusps and near-degenerate segments occur).
inline Curve random_curve(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Curve c;
  for (int i = 0; i < 3 * k + 1; ++i) c.control_points.emplace_back(u(rng), u(rng), u(rng));
  c.sharp.assign(static_cast<std::size_t>(k) + 1, false);
  return c;
}

inline Vec3 random_point(std::mt19937_64& rng, double half_extent) {
  std::uniform_real_distribution<double> u(-half_extent, half_extent);
  return {u(rng), u(rng), u(rng)};
}

// Parameters from t0 to t1 about 1/per_unit apart that include every joint
// in between: random curves have kinks at joints, which a uniform sampling
// that misses them only approaches to first order.
inline std::vector<double> dense_parameters(double t0, double t1, int per_unit) {
  std::vector<double> ts{t0};
  for (double j = std::floor(t0) + 1.0; j < t1; j += 1.0) ts.push_back(j);
  ts.push_back(t1);
  std::vector<double> out{t0};
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const int n = std::max(1, static_cast<int>(std::ceil((ts[i + 1] - ts[i]) * per_unit)));
    for (int k = 1; k <= n; ++k) out.push_back(k == n ? ts[i + 1] : ts[i] + (ts[i + 1] - ts[i]) * k / n);
  }
  return out;
}

}  // namespace sketchlab::test
