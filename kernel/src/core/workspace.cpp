#include "sketchlab/workspace.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sketchlab {

Vec3 nearest_grid_point(const Workspace& ws, const Vec3& p) {
  if (!ws.grid_enabled) throw std::invalid_argument("nearest_grid_point: the grid is disabled");
  if (!std::isfinite(ws.grid_spacing) || ws.grid_spacing <= 0.0) {
    throw std::invalid_argument("nearest_grid_point: grid spacing " +
                                std::to_string(ws.grid_spacing) + " must be finite and > 0");
  }
  if (!ws.grid_origin.allFinite() || !p.allFinite()) {
    throw std::invalid_argument("nearest_grid_point: non-finite grid origin or point");
  }
  const Vec3 k = ((p - ws.grid_origin) / ws.grid_spacing).array().round();
  return ws.grid_origin + ws.grid_spacing * k;
}

Vec3 mirror_point(const Workspace& ws, const Vec3& p) {
  const double n2 = ws.mirror_normal.squaredNorm();
  if (!(n2 > 0.0) || !std::isfinite(n2) || !std::isfinite(ws.mirror_offset)) {
    throw std::invalid_argument("mirror_point: the mirror normal must be finite and non-zero");
  }
  // The normal need not be unit: signed distance is (n·p - offset)/|n|.
  return p - 2.0 * (ws.mirror_normal.dot(p) - ws.mirror_offset) / n2 * ws.mirror_normal;
}

}  // namespace sketchlab
