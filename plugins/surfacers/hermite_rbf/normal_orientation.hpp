#pragma once
// Consistent signs for unsigned normals on a graph (Hoppe, DeRose, Duchamp,
// McDonald & Stuetzle 1992, "Surface reconstruction from unorganized points",
// §3.3): neighbouring normals of a smooth surface point the same way, so the
// sign is propagated from a seed along a maximum spanning tree of the
// agreement |a_ij| (Prim's order: the strongest agreement first); a_ij < 0
// says j is flipped relative to i. Hoppe's agreement is n_i · n_j; between
// normals far apart along a curve, the caller compares n_j with n_i carried
// along the curve (curve_normals.cpp). Each
// connected part holding no fixed normal is then oriented so that its normals
// point, on the whole, away from its centroid; a part holding fixed normals
// (the corrector's) is grown from them.
#include <utility>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::hermite_rbf {

struct Agreement {
  std::size_t a = 0, b = 0;
  double weight = 0.0;  // in [-1, 1]
};

// normals: unit, or zero (takes no part); positions: m, one per normal;
// fixed: never flipped. Returns which to negate. Deterministic (ties go to
// the lower index).
std::vector<bool> consistent_flips(const std::vector<Vec3>& normals, const std::vector<Vec3>& positions,
                                   const std::vector<Agreement>& agreements, const std::vector<bool>& fixed);

}  // namespace sketchlab::hermite_rbf
