#include "jdi_params.hpp"

#include <stdexcept>

namespace sketchlab::justdrawit {

namespace {
ParamSpec real(std::string name, double def, double lo, double hi, std::string unit, std::string doc) {
  return {std::move(name), ParamType::real, def, lo, hi, {}, std::move(unit), std::move(doc)};
}
const std::vector<std::string> surface_names{"view_plane", "draw_plane", "extrusion", "inflation"};
const std::vector<std::string> plane_names{"explicit", "curve_tangent", "curve_normal",
                                           "curve_binormal", "two_points"};
}  // namespace

std::string to_string(SurfaceKind kind) { return surface_names.at(static_cast<int>(kind)); }

std::vector<ParamSpec> jdi_param_specs() {
  const JdiParams d;
  return {
      real("d", d.d, 1.0, 200.0, "px",
           "selection distance d (§4): every distance threshold is a multiple of it"),
      {"smoothing", ParamType::integer, std::int64_t{d.smoothing}, 0.0, 50.0, {}, "rounds",
       "N (§4.5): N rounds on the stroke, 2+N on depths, 1+N+40q around joins"},
      {"scratch", ParamType::boolean, d.scratch, {}, {}, {}, "",
       "turn back-and-forth scratches into one smooth stroke (§4.1)"},
      {"surface", ParamType::choice, std::string("view_plane"), {}, {}, surface_names, "",
       "drawing surface for new curves (§5.1): view_plane (film plane through plane_origin, no "
       "draw plane visible), draw_plane, extrusion, inflation (between the two latest guide-layer "
       "strokes)"},
      {"plane_from", ParamType::choice, std::string("explicit"), {}, {}, plane_names, "",
       "how the draw plane is placed (§5.1): explicit origin/normal, through a curve point along "
       "its tangent/normal/binormal, or through two curve points"},
      real("plane_origin_x", 0, -1e6, 1e6, "m", "draw plane / view plane point"),
      real("plane_origin_y", 0, -1e6, 1e6, "m", "draw plane / view plane point"),
      real("plane_origin_z", 0, -1e6, 1e6, "m", "draw plane / view plane point"),
      real("plane_normal_x", 0, -1, 1, "", "explicit draw plane normal"),
      real("plane_normal_y", 0, -1, 1, "", "explicit draw plane normal"),
      real("plane_normal_z", 1, -1, 1, "", "explicit draw plane normal"),
      {"plane_curve", ParamType::integer, std::int64_t{0}, 0.0, 1e15, {}, "",
       "curve id for plane_from=curve_* / two_points (0: the last edited curve)"},
      real("plane_at", 0.5, 0, 1, "", "arclength fraction of the point on plane_curve"),
      {"plane_curve2", ParamType::integer, std::int64_t{0}, 0.0, 1e15, {}, "",
       "second curve id for plane_from=two_points"},
      real("plane_at2", 0.5, 0, 1, "", "arclength fraction of the point on plane_curve2"),
      {"extrusion_curve", ParamType::integer, std::int64_t{0}, 0.0, 1e15, {}, "",
       "curve extruded for surface=extrusion (0: the last edited curve)"},
      real("extrusion_x", 0, -1, 1, "", "extrusion direction"),
      real("extrusion_y", 0, -1, 1, "", "extrusion direction"),
      real("extrusion_z", 1, -1, 1, "", "extrusion direction"),
      {"normals", ParamType::boolean, d.normals, {}, {}, {}, "",
       "export default surface normals with each curve (§6) for the Hermite RBF surfacer"},
  };
}

JdiParams jdi_params_from(const Params& p) {
  JdiParams r;
  r.d = p.real("d");
  r.smoothing = static_cast<int>(p.integer("smoothing"));
  r.scratch = p.boolean("scratch");
  const std::string& s = p.string("surface");
  for (std::size_t i = 0; i < surface_names.size(); ++i)
    if (s == surface_names[i]) r.surface = static_cast<SurfaceKind>(i);
  const std::string& pf = p.string("plane_from");
  for (std::size_t i = 0; i < plane_names.size(); ++i)
    if (pf == plane_names[i]) r.plane_from = static_cast<PlaneFrom>(i);
  r.plane_origin = {p.real("plane_origin_x"), p.real("plane_origin_y"), p.real("plane_origin_z")};
  r.plane_normal = {p.real("plane_normal_x"), p.real("plane_normal_y"), p.real("plane_normal_z")};
  if (r.plane_normal.norm() < 1e-9) throw std::invalid_argument("plane_normal_*: the normal is zero");
  r.plane_normal.normalize();
  r.plane_curve = p.integer("plane_curve");
  r.plane_at = p.real("plane_at");
  r.plane_curve2 = p.integer("plane_curve2");
  r.plane_at2 = p.real("plane_at2");
  r.extrusion_curve = p.integer("extrusion_curve");
  r.extrusion_direction = {p.real("extrusion_x"), p.real("extrusion_y"), p.real("extrusion_z")};
  if (r.extrusion_direction.norm() < 1e-9)
    throw std::invalid_argument("extrusion_*: the direction is zero");
  r.extrusion_direction.normalize();
  r.normals = p.boolean("normals");
  return r;
}

}  // namespace sketchlab::justdrawit
