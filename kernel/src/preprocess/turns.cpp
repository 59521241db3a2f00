#include "sketchlab/preprocess/turns.hpp"

#include <cmath>

namespace sketchlab {

std::vector<double> sample_turns(const std::vector<Vec3>& p, TurnSpan span) {
  const std::size_t n = p.size();
  std::vector<double> turn(n, 0.0);
  if (n < 3) return turn;
  // Averaged direction at j: one-sided at the ends.
  auto direction = [&](std::size_t j) -> Vec3 {
    const std::size_t a = j == 0 ? 0 : j - 1, b = j + 1 < n ? j + 1 : n - 1;
    return p[b] - p[a];
  };
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vec3 a = direction(i - 1), b = direction(span == TurnSpan::across ? i + 1 : i);
    if (a.norm() == 0.0 || b.norm() == 0.0) continue;
    turn[i] = std::atan2(a.cross(b).norm(), a.dot(b));
  }
  return turn;
}

}  // namespace sketchlab
