#pragma once
// The interpolant sampled on a regular grid, evaluated exactly only near its
// zero set (coarse-to-fine narrow band).
#include <array>
#include <cstdint>
#include <vector>

#include "implicit_function.hpp"

namespace sketchlab::hermite_rbf {

// Nodes origin + h (i, j, k), 0 <= i < n[0] ... (x fastest in `values`).
struct GridSpec {
  Vec3 origin = Vec3::Zero();  // m
  double h = 1.0;              // m, cell edge
  std::array<int, 3> n{2, 2, 2};
  std::size_t size() const { return std::size_t(n[0]) * n[1] * n[2]; }
  std::size_t index(int i, int j, int k) const { return std::size_t(i) + std::size_t(n[0]) * (std::size_t(j) + std::size_t(n[1]) * k); }
};

// A box around `box` (m) padded by `padding` (m) on each side, rounded
// outwards to multiples of a power of two near its diagonal / 32 (so that a
// sketch growing a little keeps its grid: incremental updates), with
// `resolution` cells along its longest side (rounded up so every side is a
// multiple of 8 cells, the coarsest refinement step).
GridSpec grid_around(const Box3& box, double padding, int resolution);

// The box spanned by the grid's nodes (m).
Box3 grid_box(const GridSpec& spec);

struct ScalarGrid {
  GridSpec spec;
  std::vector<double> values;  // f at every node; > 0 outside (the box border is forced > 0)
  std::size_t evaluated = 0;   // nodes where f is exact (the rest interpolated)
  std::size_t computed = 0;    // of those, evaluated now (the others came from the cache)
};

// Exact node values of earlier evaluations on one grid, for an incremental
// update: where f did not change, the nodes are not evaluated again. The
// result is the same as without the cache.
struct GridCache {
  GridSpec spec;
  std::vector<double> values;
  std::vector<float> gradient_norms;
  std::vector<std::uint8_t> known;  // 0: nothing, 1: f, 2: f and |∇f|
  // Forgets the nodes inside the spheres (m), where f changed.
  void invalidate(const std::vector<Sphere>& changed);
};

// Evaluates f coarse to fine: at each level (steps 8, 4, 2, 1 cells) a cell is
// refined when its corners change sign or one of them is within max(1, |∇f|) ×
// the cell diagonal (0.6 × on the last level) of zero (first-order distance bound); the nodes of the
// other cells are trilinearly interpolated from their corners, which share
// one sign, so no zero crossing is invented there. Border nodes are then set
// positive so that the zero set is closed inside the box, and exact zeros are
// nudged positive so marching cubes makes no degenerate triangles.
// With `cache` (reset when its spec differs), known exact nodes are reused
// and the new ones recorded.
ScalarGrid evaluate_grid(const ImplicitFunction& f, const GridSpec& spec, int threads, GridCache* cache = nullptr);

}  // namespace sketchlab::hermite_rbf
