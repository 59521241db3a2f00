#pragma once
// Parameters of the JustDrawIt stroke inference engine (Grimm & Joshi 2012).
// Only d and N are user controls in the paper (§4 "Parameters"); every other
// constant is the paper's own, derived from them in the code that uses it.
#include <string>
#include <vector>

#include "sketchlab/plugin/params.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab::justdrawit {

// Which temporary drawing surface new curves are placed on (§5.1).
enum class SurfaceKind {
  view_plane,  // no visible draw plane: the film plane through plane_origin (§2)
  draw_plane,  // a visible draw plane (explicit, or from a curve, §5.1)
  extrusion,   // a curve extruded along a direction (§5.1, [BBS08])
  inflation,   // half-circles between two guide strokes (§5.1, Figure 11)
};

// How the draw plane is positioned (§5.1).
enum class PlaneFrom {
  explicit_plane,  // plane_origin + plane_normal
  curve_tangent,   // through a curve point, normal = tangent there
  curve_normal,    // ... normal = the curve's (default) normal there
  curve_binormal,  // ... normal = tangent x normal
  two_points,      // through two curve points, as perpendicular as possible to both tangents
};

struct JdiParams {
  double d = 15.0;      // selection distance, pixels (§4)
  int smoothing = 2;    // N, smoothing rounds (§4, §4.5)
  bool scratch = true;  // back-and-forth scratch processing enabled (§4.1)
  SurfaceKind surface = SurfaceKind::view_plane;
  PlaneFrom plane_from = PlaneFrom::explicit_plane;
  Vec3 plane_origin = Vec3::Zero();
  Vec3 plane_normal = Vec3::UnitZ();
  // Curve points for plane_from != explicit_plane (curve id; arclength fraction).
  std::int64_t plane_curve = 0, plane_curve2 = 0;
  double plane_at = 0.5, plane_at2 = 0.5;
  std::int64_t extrusion_curve = 0;  // 0: the last edited curve
  Vec3 extrusion_direction = Vec3::UnitZ();
  bool normals = true;  // export default normals (§6)
};

std::vector<ParamSpec> jdi_param_specs();
JdiParams jdi_params_from(const Params& p);

std::string to_string(SurfaceKind kind);

}  // namespace sketchlab::justdrawit
