#pragma once
// What a corrector considered for a stroke, and whether it enforced it.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

enum class ConstraintKind {
  coincident_point,
  point_on_curve,
  intersection,
  grid_point,
  mirror_plane,
  closure,
  tangent,
  parallel,
  perpendicular,
  equal_length,
  planar,
  axis_plane,
  on_surface,
  symmetry,
  straight,
  arc,
};
inline constexpr int constraint_kind_count = 16;

std::string_view to_string(ConstraintKind kind);
ConstraintKind constraint_kind_from_string(std::string_view name);  // throws

// What a constraint refers to.
struct ConstraintRef {
  enum class Kind { stroke, curve, node, grid, mirror, axis } kind = Kind::stroke;
  std::uint64_t id = 0;    // stroke / curve / node id; axis index 0,1,2
  double parameter = 0.0;  // curve parameter t (or stroke arclength fraction)

  bool operator==(const ConstraintRef&) const = default;
};

struct Constraint {
  ConstraintKind kind = ConstraintKind::coincident_point;
  std::vector<ConstraintRef> references;
  // Target value: a point, a direction, a plane normal (x,y,z) as the kind
  // needs; unused components are zero.
  Vec3 target = Vec3::Zero();
  double weight = 1.0;
  bool hard = false;
  bool enforced = false;
  double residual = 0.0;  // metres or radians, as the kind measures

  bool operator==(const Constraint&) const = default;
};

}  // namespace sketchlab
