#pragma once
// Default surface normals along a curve (§6), for surfacers (Hermite RBF).
// Units: metres; point lists n x 3 (closed lists repeat the first point).
#include <utility>

#include "point_list.hpp"

namespace sketchlab::justdrawit {

// A normal fixed at a curve point (a pin at a snapped intersection).
struct NormalPin {
  std::size_t index = 0;
  Vec3 normal;
};

// Best-fit plane normal of 10 points on each curve around the intersection
// (§6: more stable than the cross product of the tangents).
Vec3 pin_normal(const Points3& a, std::size_t ia, const Points3& b, std::size_t ib);

// Least-squares plane of the points: (centroid, unit normal, max |distance|).
struct PlaneFit {
  Vec3 centroid = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double max_distance = 0;
  bool degenerate = false;  // points (nearly) collinear: the normal is arbitrary
};
PlaneFit fit_plane(const Points3& pts);

// One unit normal per point, perpendicular to the tangent (§6):
//  - planar curves (max distance to the fitted plane <= planar_tolerance):
//    tangent x plane normal, oriented away from the centroid at the midpoint;
//  - other curves: at points where the tangent is perpendicular to the
//    vector v between the point and the centroid, the normal is v (oriented
//    outwards), then spherical interpolation between those keys;
//  - pins override and join the keys.
// Straight curves (no plane, no key) use `fallback` rejected from the tangent.
std::vector<Vec3> default_normals(const Points3& pts, bool closed, const std::vector<NormalPin>& pins,
                                  double planar_tolerance, const Vec3& fallback);

// Spherical linear interpolation of unit vectors.
Vec3 slerp(const Vec3& a, const Vec3& b, double t);

}  // namespace sketchlab::justdrawit
