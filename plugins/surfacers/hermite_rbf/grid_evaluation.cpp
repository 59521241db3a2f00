#include "grid_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "parallel_for.hpp"

namespace sketchlab::hermite_rbf {
namespace {

constexpr int coarsest_step = 8;
enum : std::uint8_t { unknown = 0, interpolated = 1, exact = 2, scheduled = 3 };

}  // namespace

GridSpec grid_around(const Box3& box, double padding, int resolution) {
  Vec3 lo = box.min() - Vec3::Constant(padding), hi = box.max() + Vec3::Constant(padding);
  // Rounded outwards to multiples of a power of two near diagonal / 32.
  const double quantum = std::exp2(std::floor(std::log2(std::max((hi - lo).norm(), 1e-9) / 32.0)));
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::floor(lo[a] / quantum) * quantum;
    hi[a] = std::ceil(hi[a] / quantum) * quantum;
  }
  const Vec3 extent = hi - lo;
  GridSpec g;
  g.h = extent.maxCoeff() / std::max(1, resolution);
  if (!(g.h > 0.0) || !std::isfinite(g.h)) g.h = 1.0;
  Vec3 size;
  for (int a = 0; a < 3; ++a) {
    int cells = std::max(1, static_cast<int>(std::ceil(extent[a] / g.h - 1e-9)));
    cells = (cells + coarsest_step - 1) / coarsest_step * coarsest_step;
    g.n[static_cast<std::size_t>(a)] = cells + 1;
    size[a] = cells * g.h;
  }
  g.origin = 0.5 * (lo + hi) - 0.5 * size;
  return g;
}

void GridCache::invalidate(const std::vector<Sphere>& changed) {
  if (known.empty()) return;
  for (const Sphere& s : changed) {
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      const auto n = spec.n[static_cast<std::size_t>(a)];
      lo[a] = std::clamp(static_cast<int>(std::floor((s.center[a] - s.radius - spec.origin[a]) / spec.h)), 0, n - 1);
      hi[a] = std::clamp(static_cast<int>(std::ceil((s.center[a] + s.radius - spec.origin[a]) / spec.h)), 0, n - 1);
    }
    const double r2 = s.radius * s.radius * (1.0 + 1e-9);
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
          if ((spec.origin + spec.h * Vec3(i, j, k) - s.center).squaredNorm() <= r2) known[spec.index(i, j, k)] = 0;
  }
}

Box3 grid_box(const GridSpec& spec) {
  return Box3(spec.origin, spec.origin + spec.h * Vec3(spec.n[0] - 1, spec.n[1] - 1, spec.n[2] - 1));
}

ScalarGrid evaluate_grid(const ImplicitFunction& f, const GridSpec& spec, int threads, GridCache* cache) {
  if (cache && (cache->spec.origin != spec.origin || cache->spec.h != spec.h || cache->spec.n != spec.n ||
                cache->known.size() != spec.size())) {
    cache->spec = spec;
    cache->values.assign(spec.size(), 0.0);
    cache->gradient_norms.assign(spec.size(), 0.0f);
    cache->known.assign(spec.size(), 0);
  }
  ScalarGrid grid;
  grid.spec = spec;
  grid.values.assign(spec.size(), 0.0);
  std::vector<std::uint8_t> flag(spec.size(), unknown);
  std::vector<float> gnorm(spec.size(), 0.0f);
  auto node = [&](int i, int j, int k) -> Vec3 { return spec.origin + spec.h * Vec3(i, j, k); };

  std::vector<std::array<int, 3>> cells;
  for (int k = 0; k + coarsest_step < spec.n[2]; k += coarsest_step)
    for (int j = 0; j + coarsest_step < spec.n[1]; j += coarsest_step)
      for (int i = 0; i + coarsest_step < spec.n[0]; i += coarsest_step) cells.push_back({i, j, k});

  for (int step = coarsest_step; step >= 1 && !cells.empty(); step /= 2) {
    // Exact values at the corners of this level's cells.
    std::vector<std::array<int, 3>> todo;
    for (const auto& c : cells)
      for (int d = 0; d < 8; ++d) {
        const int i = c[0] + (d & 1 ? step : 0), j = c[1] + (d & 2 ? step : 0), k = c[2] + (d & 4 ? step : 0);
        std::uint8_t& fl = flag[spec.index(i, j, k)];
        if (fl == exact || fl == scheduled) continue;
        fl = scheduled;
        todo.push_back({i, j, k});
      }
    const bool gradients = step > 1;
    const std::uint8_t needed = gradients ? 2 : 1;
    if (cache) {
      // Known nodes come from the cache; the rest are evaluated below.
      std::erase_if(todo, [&](const std::array<int, 3>& t) {
        const std::size_t id = spec.index(t[0], t[1], t[2]);
        if (cache->known[id] < needed) return false;
        grid.values[id] = cache->values[id];
        gnorm[id] = cache->gradient_norms[id];
        flag[id] = exact;
        ++grid.evaluated;
        return true;
      });
    }
    parallel_for(todo.size(), threads, [&](std::size_t t) {
      const auto& [i, j, k] = todo[t];
      const std::size_t id = spec.index(i, j, k);
      if (gradients) {
        Vec3 g;
        grid.values[id] = f.value_gradient(node(i, j, k), g);
        gnorm[id] = static_cast<float>(g.norm());
      } else {
        grid.values[id] = f.value(node(i, j, k));
      }
    });
    if (cache)
      for (const auto& t : todo) {
        const std::size_t id = spec.index(t[0], t[1], t[2]);
        cache->values[id] = grid.values[id];
        cache->gradient_norms[id] = gnorm[id];
        cache->known[id] = needed;
      }
    grid.computed += todo.size();
    for (const auto& t : todo) flag[spec.index(t[0], t[1], t[2])] = exact;
    grid.evaluated += todo.size();
    if (step == 1) break;

    std::vector<std::array<int, 3>> finer;
    // Every point of a cell lies within half its diagonal of a corner; twice
    // that leaves room for the curvature the first-order estimate ignores on
    // coarse cells, 1.2 times on the 2-cell level where it is accurate.
    const double reach = (step > 2 ? 1.0 : 0.6) * step * spec.h * std::sqrt(3.0);
    for (const auto& c : cells) {
      double v[8];
      bool pos = false, neg = false, close = false;
      for (int d = 0; d < 8; ++d) {
        const std::size_t id = spec.index(c[0] + (d & 1 ? step : 0), c[1] + (d & 2 ? step : 0), c[2] + (d & 4 ? step : 0));
        v[d] = grid.values[id];
        (v[d] > 0.0 ? pos : neg) = true;
        close = close || std::abs(v[d]) <= reach * std::max(1.0, double(gnorm[id]));
      }
      if ((pos && neg) || close) {
        const int s = step / 2;
        for (int d = 0; d < 8; ++d) finer.push_back({c[0] + (d & 1 ? s : 0), c[1] + (d & 2 ? s : 0), c[2] + (d & 4 ? s : 0)});
        continue;
      }
      // Far from the zero set: trilinear fill (all corners share one sign).
      for (int k = 0; k <= step; ++k)
        for (int j = 0; j <= step; ++j)
          for (int i = 0; i <= step; ++i) {
            const std::size_t id = spec.index(c[0] + i, c[1] + j, c[2] + k);
            if (flag[id] != unknown) continue;
            const double u = double(i) / step, w = double(j) / step, z = double(k) / step;
            const double x00 = v[0] * (1 - u) + v[1] * u, x10 = v[2] * (1 - u) + v[3] * u;
            const double x01 = v[4] * (1 - u) + v[5] * u, x11 = v[6] * (1 - u) + v[7] * u;
            grid.values[id] = (x00 * (1 - w) + x10 * w) * (1 - z) + (x01 * (1 - w) + x11 * w) * z;
            flag[id] = interpolated;
          }
    }
    cells = std::move(finer);
  }

  const double outside = spec.h;
  for (int k = 0; k < spec.n[2]; ++k)
    for (int j = 0; j < spec.n[1]; ++j)
      for (int i = 0; i < spec.n[0]; ++i) {
        double& v = grid.values[spec.index(i, j, k)];
        const bool border = i == 0 || j == 0 || k == 0 || i == spec.n[0] - 1 || j == spec.n[1] - 1 || k == spec.n[2] - 1;
        if (border && v <= 0.0) v = outside;
        if (v == 0.0 || !std::isfinite(v)) v = 1e-12 * outside;
      }
  return grid;
}

}  // namespace sketchlab::hermite_rbf
