#pragma once
// Where a new curve goes in depth (§5.1): the active drawing surface (draw
// plane, extrusion or inflation surface from guide strokes, else the view
// plane through plane_origin), and the draw plane placed from curves.
#include <optional>
#include <string>

#include "inference_context.hpp"
#include "point_list.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::justdrawit {

// The draw plane placed from curves (§5.1), or the explicit one. `last` is
// the last edited curve (the default reference curve).
Plane draw_plane_from(const JdiParams& p, const Network& net, CurveId last);

// The stroke lifted onto the active drawing surface; `surface_used` names the
// one that took it ("draw_plane", "extrusion", "inflation", "view_plane").
std::optional<Points3> place_new(const Points2& s2, const Stroke& stroke, const Sketch& sketch,
                                 const Network& net, CurveId last, const Ctx& ctx,
                                 std::string& surface_used);

}  // namespace sketchlab::justdrawit
