#pragma once
// Opening the surface where the network has no curves. JustDrawIt §6's
// surface is closed by construction and "may bulge unexpectedly"; a designer
// wants the surface where the curves enclose it and nothing elsewhere.
//
// A surface point is enclosed when, looking around it in its tangent plane,
// it sees curves in every direction: the largest angle around the normal
// within which no curve sample is seen (closer than `reach`, and no more than
// `max_elevation` above or below the tangent plane) is below `max_gap`. With
// max_gap = π the enclosed region is, locally, the convex hull of the
// surrounding curves seen in the tangent plane: inside a loop of curves the
// gap is small, just beyond a boundary curve it exceeds π, far from every
// curve it is 2π. The elevation limit keeps a balloon hanging below a loop of
// curves (seen steeply from it) from counting as enclosed by that loop.
#include <vector>

#include "implicit_function.hpp"
#include "point_tree.hpp"
#include "sketchlab/mesh.hpp"

namespace sketchlab::hermite_rbf {

struct TrimParams {
  double reach = 0.0;          // m
  double max_elevation = 0.0;  // rad
  double max_gap = 0.0;        // rad
};

// The gap (rad, in [0, 2π]) at x seen around `normal` (unit).
double enclosure_gap(const Vec3& x, const Vec3& normal, const PointTree& samples, const TrimParams& params);

// `mesh` without its unenclosed parts: the gap is evaluated on a lattice of
// spacing `cell` (m) around the mesh with normals ∇f/|∇f|, interpolated
// trilinearly at the vertices, and the mesh is cut along the interpolated
// level gap = max_gap (VTK's clip; the cut edge is smooth, not stair-cased
// by triangles). Normals are recomputed. `samples` should be thinned to
// about reach / 50 (thin_points): the cost is per sample within reach.
Mesh trim_unenclosed(const Mesh& mesh, const ImplicitFunction& f, const PointTree& samples, const TrimParams& params,
                     double cell, int threads);

}  // namespace sketchlab::hermite_rbf
