#pragma once
// Planes as correctors and viewers use them: a point on the plane and its
// unit normal. Strokes and recordings store a draw plane as the coefficients
// (n, d) of n·x = d (Stroke::draw_plane, plane_through in draw_plane.hpp);
// the two conversions below go between the forms.
#include <optional>
#include <vector>

#include "sketchlab/types.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab {

struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit length
  bool operator==(const Plane&) const = default;
};

// The plane n·x = d of `coefficients` (n, d) with |n| = 1: the point d·n and
// the normal n normalised. No check: a zero n gives a non-finite normal.
Plane plane_from_coefficients(const Vec4& coefficients);

// Where the line of `ray` meets `plane`, at any ray parameter (behind the
// origin too); nothing when the ray is parallel to the plane
// (|direction·normal| < 1e-12).
std::optional<Vec3> intersect(const Ray& ray, const Plane& plane);

// Largest distance (m) of `points` to the plane through their centroid with
// unit normal `n`, 0 for no points: how far they are from lying in one plane
// of that orientation (e.g. a curve's control points, CASSIE's planarity).
double plane_residual(const std::vector<Vec3>& points, const Vec3& n);

}  // namespace sketchlab
