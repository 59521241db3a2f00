#pragma once
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab {

// Arclength of the curve between parameters t0 <= t1 (metres), by adaptive
// Gauss–Legendre quadrature to relative tolerance 1e-9. A length that does
// not fit a double (coordinates near 1e300) comes back non-finite, at once.
double arclength(const Curve& curve, double t0, double t1);
double arclength(const Curve& curve);

// Parameter t at which arclength from 0 equals s (clamped to [0, length]).
double parameter_at_arclength(const Curve& curve, double s);

// n >= 2 parameters equally spaced in arclength, first 0, last t_max.
std::vector<double> arclength_parameters(const Curve& curve, int n);
// Points at those parameters.
std::vector<Vec3> sample_by_arclength(const Curve& curve, int n);
// Points spaced at most `spacing` metres apart along the curve (>= 2 points).
// Throws std::invalid_argument when that needs more than 1e7 points.
std::vector<Vec3> sample_with_spacing(const Curve& curve, double spacing);
// The same, but at most `max_points` (>= 2) points: on a curve longer than
// spacing·(max_points − 1) they are spread evenly, farther apart. For
// exports and proximity tests that must stay bounded whatever the input (one
// tracking-glitch sample kilometres away makes a curve kilometres long).
std::vector<Vec3> sample_with_spacing(const Curve& curve, double spacing, int max_points);

}  // namespace sketchlab
