#pragma once
// A minimal static parallel loop over [0, n) with std::thread. Each index is
// processed once whatever the thread count, so results do not depend on it.
#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace sketchlab::hermite_rbf {

inline int thread_count(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

template <class F>
void parallel_for(std::size_t n, int threads, F&& body) {
  const std::size_t t = std::min<std::size_t>(static_cast<std::size_t>(thread_count(threads)), std::max<std::size_t>(1, n / 256));
  if (t <= 1) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  std::vector<std::thread> pool;
  const std::size_t chunk = (n + t - 1) / t;
  for (std::size_t k = 0; k < t; ++k)
    pool.emplace_back([&, k] {
      for (std::size_t i = k * chunk; i < std::min(n, (k + 1) * chunk); ++i) body(i);
    });
  for (auto& th : pool) th.join();
}

}  // namespace sketchlab::hermite_rbf
