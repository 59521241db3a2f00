#include "jdi_params.hpp"

#include <stdexcept>

#include "sketchlab/plugin/param_table.hpp"

namespace sketchlab::justdrawit {

namespace {
const std::vector<std::string> surface_names{"view_plane", "draw_plane", "extrusion", "inflation"};

template <class E>
std::vector<std::pair<std::string, E>> named(const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, E>> r;
  for (std::size_t i = 0; i < names.size(); ++i) r.emplace_back(names[i], static_cast<E>(i));
  return r;
}

// A Vec3 component as a parameter field.
template <int I>
auto component(Vec3 JdiParams::*v) {
  return [v](JdiParams& p) -> double& { return (p.*v)[I]; };
}

const ParamTable<JdiParams>& parameters() {
  using P = JdiParams;
  static const auto table =
      ParamTable<P>()
          .real("d", &P::d, 1.0, 200.0, "px",
                "selection distance d (§4): every distance threshold is a multiple of it")
          .integer("smoothing", &P::smoothing, 0.0, 50.0, "rounds",
                   "N (§4.5): N rounds on the stroke, 2+N on depths, 1+N+40q around joins")
          .boolean("scratch", &P::scratch, "turn back-and-forth scratches into one smooth stroke (§4.1)")
          .choice("surface", &P::surface, named<SurfaceKind>(surface_names),
                  "drawing surface for new curves (§5.1): view_plane (film plane through plane_origin, no "
                  "draw plane visible), draw_plane, extrusion, inflation (between the two latest guide-layer "
                  "strokes)")
          .choice("plane_from", &P::plane_from,
                  named<PlaneFrom>({"explicit", "curve_tangent", "curve_normal", "curve_binormal", "two_points"}),
                  "how the draw plane is placed (§5.1): explicit origin/normal, through a curve point along "
                  "its tangent/normal/binormal, or through two curve points")
          .real("plane_origin_x", component<0>(&P::plane_origin), -1e6, 1e6, "m", "draw plane / view plane point")
          .real("plane_origin_y", component<1>(&P::plane_origin), -1e6, 1e6, "m", "draw plane / view plane point")
          .real("plane_origin_z", component<2>(&P::plane_origin), -1e6, 1e6, "m", "draw plane / view plane point")
          .real("plane_normal_x", component<0>(&P::plane_normal), -1, 1, "", "explicit draw plane normal")
          .real("plane_normal_y", component<1>(&P::plane_normal), -1, 1, "", "explicit draw plane normal")
          .real("plane_normal_z", component<2>(&P::plane_normal), -1, 1, "", "explicit draw plane normal")
          .integer("plane_curve", &P::plane_curve, 0.0, 1e15, "",
                   "curve id for plane_from=curve_* / two_points (0: the last edited curve)")
          .real("plane_at", &P::plane_at, 0, 1, "", "arclength fraction of the point on plane_curve")
          .integer("plane_curve2", &P::plane_curve2, 0.0, 1e15, "", "second curve id for plane_from=two_points")
          .real("plane_at2", &P::plane_at2, 0, 1, "", "arclength fraction of the point on plane_curve2")
          .integer("extrusion_curve", &P::extrusion_curve, 0.0, 1e15, "",
                   "curve extruded for surface=extrusion (0: the last edited curve)")
          .real("extrusion_x", component<0>(&P::extrusion_direction), -1, 1, "", "extrusion direction")
          .real("extrusion_y", component<1>(&P::extrusion_direction), -1, 1, "", "extrusion direction")
          .real("extrusion_z", component<2>(&P::extrusion_direction), -1, 1, "", "extrusion direction")
          .boolean("normals", &P::normals,
                   "export default surface normals with each curve (§6) for the Hermite RBF surfacer")
          .check([](P& r) {
            if (r.plane_normal.norm() < 1e-9) throw std::invalid_argument("plane_normal_*: the normal is zero");
            r.plane_normal.normalize();
            if (r.extrusion_direction.norm() < 1e-9)
              throw std::invalid_argument("extrusion_*: the direction is zero");
            r.extrusion_direction.normalize();
          });
  return table;
}
}  // namespace

std::string to_string(SurfaceKind kind) { return surface_names.at(static_cast<int>(kind)); }

std::vector<ParamSpec> jdi_param_specs() { return parameters().specs(); }

JdiParams jdi_params_from(const Params& p) { return parameters().read(p); }

}  // namespace sketchlab::justdrawit
