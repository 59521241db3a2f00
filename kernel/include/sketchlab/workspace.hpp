#pragma once
#include <optional>

#include "sketchlab/types.hpp"

namespace sketchlab {

// The drawing space. Thresholds given in metres at zoom 1 become δ/s at zoom s.
struct Workspace {
  Vec3 up = Vec3::UnitY();
  // Grid points are origin + spacing * (i, j, k); disabled when !grid_enabled.
  bool grid_enabled = false;
  double grid_spacing = 0.25;
  Vec3 grid_origin = Vec3::Zero();
  // Mirror plane {x : normal·x = offset}, active when mirror_enabled.
  bool mirror_enabled = false;
  Vec3 mirror_normal = Vec3::UnitX();
  double mirror_offset = 0.0;
  double scale = 1.0;  // zoom s (>0)

  bool operator==(const Workspace&) const = default;
};

// δ(s) = δ/s (CASSIE §4.1, ScaffoldSketch §3.2).
inline double scaled_threshold(double delta, double scale) { return delta / scale; }

// Nearest grid point to p (grid must be enabled).
Vec3 nearest_grid_point(const Workspace& ws, const Vec3& p);

// Reflection of p across the mirror plane.
Vec3 mirror_point(const Workspace& ws, const Vec3& p);

}  // namespace sketchlab
