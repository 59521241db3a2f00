#pragma once
// How closely a surface follows the curve network it was built from (issue
// 24's figures): the distance from the surface to the curves, and how much of
// it lies outside the network's bounding region (where a balloon goes).
#include "point_tree.hpp"
#include "sketchlab/mesh.hpp"

namespace sketchlab::hermite_rbf {

// The network's bounding region used by the surfacer's figures: the curves'
// box grown by this × its diagonal (a surface between curves bulges a little
// past them).
constexpr double quality_margin = 0.02;

struct SurfaceQuality {
  double area = 0.0;              // m²
  double distance_mean = 0.0;     // m, area-weighted mean distance from the surface to the nearest curve sample
  double distance_p95 = 0.0;      // m, 95 % of the area is closer than this
  double distance_max = 0.0;      // m
  double outside_area = 0.0;      // m², faces whose centroid is outside the bounding region
  double outside_fraction = 0.0;  // outside_area / area (0 for an empty mesh)
};

// `curves`: samples of the network's curves (m), spaced finely enough that
// the distance to the nearest sample stands for the distance to the curves.
// The bounding region is their axis-aligned box grown by `margin` (m) on
// every side. Distances are measured at vertices, weighted by a third of the
// area of their faces.
SurfaceQuality surface_quality(const Mesh& mesh, const PointTree& curves, double margin);

}  // namespace sketchlab::hermite_rbf
