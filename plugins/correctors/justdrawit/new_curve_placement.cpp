#include "new_curve_placement.hpp"

#include <algorithm>
#include <vector>

#include "default_normals.hpp"
#include "drawing_surface.hpp"
#include "network_curves.hpp"
#include "promotion.hpp"
#include "stroke_scene.hpp"

namespace sketchlab::justdrawit {

namespace {

const NetworkCurve* resolve_curve(const Network& net, std::int64_t id, CurveId last) {
  if (id > 0) return net.find_curve(static_cast<CurveId>(id));
  return last ? net.find_curve(last) : nullptr;
}

// The latest two guide-layer 2D strokes before `id` (left then right).
std::vector<const Stroke*> guide_strokes(const Sketch& sketch, StrokeId id) {
  std::vector<const Stroke*> out;
  for (auto it = sketch.strokes.rbegin(); it != sketch.strokes.rend() && out.size() < 2; ++it)
    if (it->first < id && it->second.layer == Layer::guide && it->second.is_2d())
      out.insert(out.begin(), &it->second);
  return out;
}

}  // namespace

Plane draw_plane_from(const JdiParams& p, const Network& net, CurveId last) {
  if (p.plane_from == PlaneFrom::explicit_plane) return {p.plane_origin, p.plane_normal};
  const NetworkCurve* c1 = resolve_curve(net, p.plane_curve, last);
  if (!c1) return {p.plane_origin, p.plane_normal};
  const Points3 a = curve_points(c1->curve, 1e-3);
  const auto ca = cumulative(a);
  const double sa = p.plane_at * ca.back();
  const Vec3 pa = point_at(a, ca, sa), ta = tangent_at(a, ca, sa, 0.02 * ca.back());
  if (p.plane_from == PlaneFrom::two_points) {
    const NetworkCurve* c2 = resolve_curve(net, p.plane_curve2, 0);
    if (!c2) return plane_at_point(pa, ta);
    const Points3 b = curve_points(c2->curve, 1e-3);
    const auto cb = cumulative(b);
    const double sb = p.plane_at2 * cb.back();
    return plane_through_two_points(pa, ta, point_at(b, cb, sb), tangent_at(b, cb, sb, 0.02 * cb.back()));
  }
  if (p.plane_from == PlaneFrom::curve_tangent) return plane_at_point(pa, ta);
  const PlaneFit fit = fit_plane(a);
  const auto normals = default_normals(a, c1->curve.closed, {}, 0.01 * (a.empty() ? 1.0 : length(a)),
                                       fit.normal);
  const Vec3 n = normals[index_at(ca, sa)];
  return plane_at_point(pa, p.plane_from == PlaneFrom::curve_normal ? n : Vec3(ta.cross(n)));
}

std::optional<Points3> place_new(const Points2& s2, const Stroke& stroke, const Sketch& sketch,
                                 const Network& net, CurveId last, const Ctx& ctx,
                                 std::string& surface_used) {
  const Plane view_plane = ctx.cam.film_plane(ctx.p.plane_origin);
  const std::vector<double> zeros(s2.size(), 0.0);
  if (ctx.draw_plane) {
    surface_used = "draw_plane";
    if (auto pts = lift(ctx.cam, *ctx.draw_plane, s2, zeros, 0)) return pts;
  } else if (ctx.p.surface == SurfaceKind::extrusion) {
    if (const NetworkCurve* c = resolve_curve(net, ctx.p.extrusion_curve, last)) {
      const Points3 pts = curve_points(c->curve, 1e-3);
      Box3 box;
      for (const Vec3& q : pts) box.extend(q);
      const TriangleMesh mesh = extrusion_surface(pts, ctx.p.extrusion_direction,
                                                  std::max(1.0, 4 * box.diagonal().norm()));
      const Plane ref = ctx.cam.film_plane(mean(pts));
      if (auto z = surface_depths(ctx.cam, ref, s2, mesh)) {
        surface_used = "extrusion";
        return lift(ctx.cam, ref, s2, *z, 0);
      }
    }
  } else if (ctx.p.surface == SurfaceKind::inflation) {
    const auto guides = guide_strokes(sketch, stroke.id);
    if (guides.size() == 2) {
      std::vector<Points3> sides;
      Vec3 towards = -ctx.cam.forward();
      for (const Stroke* g : guides) {
        const Camera gc(*g->view);
        const Points2 pts = dedupe(pixels(*g), 1e-9);
        const Points2 g2 = resample(pts, stroke_spacing(pts, ctx.d));
        if (g2.size() < 2) break;
        const Scene all = build_scene(net, gc, g2, ctx.d, false);
        std::vector<SceneCurve> curves;
        for (const SceneItem& it : all.items) curves.push_back({it.pts3, it.proj.pts});
        auto t = temporary_curve(gc, g2, curves, gc.film_plane(ctx.p.plane_origin), ctx.d);
        if (!t) break;
        sides.push_back(std::move(*t));
        towards = -gc.forward();
      }
      if (sides.size() == 2) {
        const TriangleMesh mesh = inflation_surface(sides[0], sides[1], towards);
        const Plane ref = ctx.cam.film_plane(0.5 * (mean(sides[0]) + mean(sides[1])));
        if (auto z = surface_depths(ctx.cam, ref, s2, mesh)) {
          surface_used = "inflation";
          return lift(ctx.cam, ref, s2, *z, 0);
        }
      }
    }
  }
  surface_used = "view_plane";
  return lift(ctx.cam, view_plane, s2, zeros, 0);
}

}  // namespace sketchlab::justdrawit
