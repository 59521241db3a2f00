#pragma once
// Temporary drawing surfaces (§5.1): draw planes placed from curves,
// extrusion surfaces and inflation surfaces, and ray casting onto them.
// Units: metres; point lists n x 3.
#include <array>
#include <optional>

#include "plane_depth.hpp"
#include "point_list.hpp"

namespace sketchlab::justdrawit {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
};

// Plane through p with the given normal direction (tangent, normal or
// binormal at a curve point, §5.1).
Plane plane_at_point(const Vec3& p, const Vec3& direction);
// Plane through p1 and p2 as perpendicular as possible to both tangents
// (§5.1, Figure 10): the unit normal n ⊥ (p2 - p1) maximising
// (n·t1)² + (n·t2)².
Plane plane_through_two_points(const Vec3& p1, const Vec3& t1, const Vec3& p2, const Vec3& t2);

// The curve swept along `direction` by ±extent (a ruled quad strip).
TriangleMesh extrusion_surface(const Points3& curve, const Vec3& direction, double extent);

// §5.1 inflation surface: left and right resampled to the same count by
// arclength, each pair joined by a half-circle of radius half their distance
// starting in the view direction and bulging towards the viewer
// (`towards_viewer` = -forward); `arc_samples` points per half-circle.
TriangleMesh inflation_surface(const Points3& left, const Points3& right,
                               const Vec3& towards_viewer, int arc_samples = 16);

// Nearest hit of the ray (parameter > 0) with the mesh (Möller–Trumbore).
std::optional<Vec3> ray_hit(const TriangleMesh& mesh, const Ray& ray);

// A curve the analysis sees: 3D points and their projection.
struct SceneCurve {
  Points3 pts3;
  Points2 pts2;
};

// §5.1 temporary curve under a stroke: each stroke pixel takes the depth of
// the curve point nearest the viewer within 2d pixels ("fat" selection);
// pixels with none are interpolated / extrapolated from the others; with no
// hit at all the stroke lies on `fallback`. Depths are relative to
// `fallback` (a film plane).
std::optional<Points3> temporary_curve(const Camera& cam, const Points2& stroke,
                                       const std::vector<SceneCurve>& curves, const Plane& fallback,
                                       double d);

// Depths (relative to `plane`) of the stroke pixels cast onto the mesh;
// pixels that miss are interpolated / extrapolated (slope 0); nothing when
// every pixel misses.
std::optional<std::vector<double>> surface_depths(const Camera& cam, const Plane& plane,
                                                  const Points2& stroke, const TriangleMesh& mesh);

}  // namespace sketchlab::justdrawit
