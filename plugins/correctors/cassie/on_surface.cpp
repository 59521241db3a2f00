#include "on_surface.hpp"

#include <algorithm>
#include <cmath>

namespace sketchlab::cassie {
namespace {

// Closest point on triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double den = va + vb + vc;
  if (!(std::abs(den) > 0)) return a;
  return a + ab * (vb / den) + ac * (vc / den);
}

// p within r of the mesh whose bounding box is `box`.
bool within(const Mesh& mesh, const Box3& box, const Vec3& p, double r) {
  if (mesh.faces.empty() || box.exteriorDistance(p) > r) return false;
  const auto m = closest_on_mesh(mesh, p);
  return m && m->distance <= r;
}

Box3 mesh_box(const Mesh& mesh) {
  Box3 box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  return box;
}

}  // namespace

std::optional<MeshPoint> closest_on_mesh(const Mesh& mesh, const Vec3& p) {
  std::optional<MeshPoint> best;
  const int nv = static_cast<int>(mesh.vertices.size());
  for (const auto& f : mesh.faces) {
    if (f[0] < 0 || f[1] < 0 || f[2] < 0 || f[0] >= nv || f[1] >= nv || f[2] >= nv) continue;
    const Vec3 &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]], &c = mesh.vertices[f[2]];
    const Vec3 q = closest_on_triangle(p, a, b, c);
    const double d = (q - p).norm();
    if (!best || d < best->distance) {
      const Vec3 n = (b - a).cross(c - a);
      best = MeshPoint{q, n.norm() > 0 ? Vec3(n.normalized()) : Vec3::UnitZ(), d};
    }
  }
  return best;
}

std::optional<SurfaceProjection> project_on_surface(const Network& network,
                                                    const std::vector<Vec3>& points,
                                                    const std::vector<int>& anchors,
                                                    const std::vector<CurveId>& intersections,
                                                    double max_distance, const SurfaceBrush& brush) {
  if (points.empty()) return std::nullopt;
  for (const auto& entry : network.patches()) {
    const Patch& patch = entry.second;  // named, not bound: the lambda below captures it (clang 14)
    if (patch.mesh.faces.empty()) continue;
    const Box3 bounds = mesh_box(patch.mesh);
    bool touched = false;
    const auto on_patch = [&](const Vec3& b) { return within(patch.mesh, bounds, b, brush.radius); };
    if (brush.away) {
      touched = std::any_of(brush.away->begin(), brush.away->end(), on_patch);
      if (!touched) continue;
    }
    std::vector<std::optional<MeshPoint>> near(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      near[i] = closest_on_mesh(patch.mesh, points[i]);
      if (near[i] && near[i]->distance <= max_distance) touched = true;  // with `brush`: already
      else near[i].reset();
    }
    if (!touched) continue;
    Box3 box = bounds;
    box.min().array() -= max_distance;
    box.max().array() += max_distance;
    bool whole = std::all_of(points.begin(), points.end(), [&](const Vec3& p) { return box.contains(p); });
    // Item 20, "the patch spans it": see SurfaceSpan.
    if (brush.span != SurfaceSpan::box) whole = whole && on_patch(brush.ends[0]) && on_patch(brush.ends[1]);
    if (brush.span == SurfaceSpan::brush && brush.away)
      whole = whole && std::all_of(brush.away->begin(), brush.away->end(), on_patch);
    for (int a : anchors) whole = whole && near[static_cast<std::size_t>(a)].has_value();
    std::set<CurveId> boundary;
    for (const OrientedSegment& s : patch.boundary) boundary.insert(s.curve);
    int on_boundary = 0;
    for (CurveId c : intersections) on_boundary += boundary.count(c) > 0;
    whole = whole && on_boundary <= 1;
    SurfaceProjection proj{entry.first, points, whole};
    for (std::size_t i = 0; i < points.size(); ++i) {
      const bool end = i == 0 || i + 1 == points.size();
      if (near[i] && (whole || end)) proj.control_points[i] = near[i]->point;
    }
    return proj;
  }
  return std::nullopt;
}

}  // namespace sketchlab::cassie
