#include "sketchlab/constraint.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace sketchlab {

namespace {
// Indexed by the enum value; the names are the enumerators themselves.
constexpr std::array<std::string_view, constraint_kind_count> kind_names{
    "coincident_point", "point_on_curve", "intersection", "grid_point",
    "mirror_plane",     "closure",        "tangent",      "parallel",
    "perpendicular",    "equal_length",   "planar",       "axis_plane",
    "on_surface",       "symmetry",       "straight",     "arc",
};
static_assert(static_cast<int>(ConstraintKind::arc) + 1 == constraint_kind_count);
}  // namespace

std::string_view to_string(ConstraintKind kind) {
  const auto i = static_cast<std::size_t>(kind);
  if (i >= kind_names.size()) {
    throw std::invalid_argument("invalid ConstraintKind value " + std::to_string(i));
  }
  return kind_names[i];
}

ConstraintKind constraint_kind_from_string(std::string_view name) {
  std::string allowed;
  for (std::size_t i = 0; i < kind_names.size(); ++i) {
    if (kind_names[i] == name) return static_cast<ConstraintKind>(i);
    allowed += (i ? ", " : "") + std::string(kind_names[i]);
  }
  throw std::invalid_argument("unknown constraint kind '" + std::string(name) +
                              "' (allowed: " + allowed + ")");
}

}  // namespace sketchlab
