#include "normal_orientation.hpp"

#include <cmath>
#include <queue>
#include <tuple>

namespace sketchlab::hermite_rbf {

std::vector<bool> consistent_flips(const std::vector<Vec3>& normals, const std::vector<Vec3>& positions,
                                   const std::vector<Agreement>& agreements, const std::vector<bool>& fixed) {
  const std::size_t n = normals.size();
  auto usable = [&](std::size_t i) { return normals[i].squaredNorm() > 0.5; };
  std::vector<std::vector<std::pair<std::size_t, double>>> next(n);
  for (const auto& [a, b, w] : agreements) {
    if (a == b || !usable(a) || !usable(b)) continue;
    next[a].emplace_back(b, w);
    next[b].emplace_back(a, w);
  }
  std::vector<bool> flip(n, false), done(n, false);
  auto grow = [&](const std::vector<std::size_t>& seeds) {
    std::vector<std::size_t> part;
    std::priority_queue<std::tuple<double, std::size_t, std::size_t, bool>> queue;  // (|w|, ~index, index, flip)
    auto visit = [&](std::size_t i) {
      done[i] = true;
      part.push_back(i);
      for (const auto& [j, w] : next[i])
        if (!done[j]) queue.emplace(std::abs(w), ~j, j, flip[i] != (w < 0.0));
    };
    for (std::size_t s : seeds) visit(s);
    while (!queue.empty()) {
      const auto [w, order, i, f] = queue.top();
      queue.pop();
      if (done[i]) continue;
      flip[i] = f;
      visit(i);
    }
    return part;
  };
  std::vector<std::size_t> seeds;
  for (std::size_t i = 0; i < n; ++i)
    if (fixed[i] && usable(i)) seeds.push_back(i);
  if (!seeds.empty()) grow(seeds);
  for (std::size_t i = 0; i < n; ++i) {
    if (done[i] || !usable(i)) continue;
    const std::vector<std::size_t> part = grow({i});
    Vec3 centroid = Vec3::Zero();
    for (std::size_t k : part) centroid += positions[k];
    centroid /= double(part.size());
    double outward = 0.0;
    for (std::size_t k : part) outward += (flip[k] ? -1.0 : 1.0) * normals[k].dot(positions[k] - centroid);
    if (outward < 0.0)
      for (std::size_t k : part) flip[k] = !flip[k];
  }
  return flip;
}

}  // namespace sketchlab::hermite_rbf
