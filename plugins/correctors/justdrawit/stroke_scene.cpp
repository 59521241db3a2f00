#include "stroke_scene.hpp"

#include <algorithm>
#include <limits>

#include "network_curves.hpp"

namespace sketchlab::justdrawit {

bool on_screen(const Vec2& pixel, const Vec4& viewport) {
  const double w = viewport[2], h = viewport[3];
  return pixel.x() >= viewport[0] - w && pixel.x() <= viewport[0] + 2 * w &&
         pixel.y() >= viewport[1] - h && pixel.y() <= viewport[1] + 2 * h;
}

Points2 pixels(const Stroke& stroke) {
  Points2 out;
  out.reserve(stroke.samples.size());
  for (const Sample& s : stroke.samples) {
    const Vec2 p(s.position.x(), s.position.y());
    if (!stroke.view || on_screen(p, stroke.view->viewport)) out.push_back(p);
  }
  return out;
}

double stroke_spacing(const Points2& pts, double d) {
  return std::max(0.1 * d, length(pts) / (max_stroke_points - 1));
}

// §4.5 bounding-box culling: curves whose projected box lies far outside the
// stroke's box are not analysed. The margin is 8d, not the paper's d: a join
// (eq. 2) reaches curve ends up to 8d away, and a d margin would cull them.
Scene build_scene(const Network& net, const Camera& cam, const Points2& stroke, double d,
                  bool cull) {
  Scene sc;
  Vec2 lo = stroke.front(), hi = stroke.front();
  for (const Vec2& p : stroke) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool first = true;
  for (const auto& [id, nc] : net.curves()) {
    const auto& cp = nc.curve.control_points;
    if (cp.empty()) continue;
    Box3 box;
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (const Vec3& q : cp) {
      box.extend(q);
      const double z = cam.eye_depth(q);
      zmin = std::min(zmin, z);
      zmax = std::max(zmax, z);
    }
    sc.Z_min = first ? zmin : std::min(sc.Z_min, zmin);
    sc.Z_max = first ? zmax : std::max(sc.Z_max, zmax);
    first = false;
    if (cull) {
      Vec2 blo(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
      Vec2 bhi = -blo;
      bool all = true;
      for (int c = 0; c < 8 && all; ++c) {
        const auto px = cam.project(box.corner(static_cast<Box3::CornerType>(c)));
        all = px.has_value();
        if (!all) break;
        blo = blo.cwiseMin(*px);
        bhi = bhi.cwiseMax(*px);
      }
      const double m = 8 * d;
      if (all && (blo.x() > hi.x() + m || blo.y() > hi.y() + m || bhi.x() < lo.x() - m ||
                  bhi.y() < lo.y() - m))
        continue;
    }
    SceneItem it;
    it.id = id;
    it.pts3 = curve_points(nc.curve, 0.1 * d * cam.world_per_pixel(box.center()));
    Points2 p2;
    p2.reserve(it.pts3.size());
    bool visible = it.pts3.size() >= 2;
    for (const Vec3& q : it.pts3) {
      const auto px = cam.project(q);
      if (!px) {
        visible = false;
        break;
      }
      p2.push_back(*px);
    }
    if (!visible) continue;
    it.proj = make_projected(std::move(p2), nc.curve.closed);
    if (!(it.proj.length() > 0)) continue;
    it.centroid = mean(it.pts3);
    it.z_min = std::numeric_limits<double>::infinity();
    it.z_max = -it.z_min;
    for (const Vec3& q : it.pts3) {
      const double z = cam.eye_depth(q);
      it.z_min = std::min(it.z_min, z);
      it.z_max = std::max(it.z_max, z);
    }
    sc.items.push_back(std::move(it));
  }
  return sc;
}

SceneItem reversed_item(SceneItem it) {
  it.pts3 = reversed(it.pts3);
  it.proj = make_projected(reversed(it.proj.pts), it.proj.closed);
  return it;
}

}  // namespace sketchlab::justdrawit
