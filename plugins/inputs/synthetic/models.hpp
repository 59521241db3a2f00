#pragma once
// Built-in ground-truth models. Each is built around `center` (metres) with
// its largest extent about `size` metres; up is +y. Circles are the usual
// four-segment cubic approximation (kappa = 0.5523), so joints sit exactly at
// the circle's 0°, 90°, 180°, 270° points (global t = 0, 1, 2, 3).
#include <string>
#include <vector>

#include "ground_truth.hpp"

namespace sketchlab::synthetic {

// The names accepted by make_model, in listing order.
const std::vector<std::string>& model_names();

// A scaffold cube: its 12 edges as scaffold lines.
GroundTruthNetwork make_cube(const Vec3& center, double size);
// A box whose 12 edges are scaffold lines and each of whose 6 faces carries
// an inset rounded rectangle (shape, closed, planar).
GroundTruthNetwork make_rounded_box(const Vec3& center, double size);
// A mug: rim and base circles, four vertical sides joining them at the circle
// joints, and a C-shaped handle whose ends lie on one side line.
GroundTruthNetwork make_mug(const Vec3& center, double size);
// A chair: seat rectangle, four legs, two back uprights, a straight middle
// rail and an arched top rail between the uprights.
GroundTruthNetwork make_chair(const Vec3& center, double size);
// A desk lamp: base circle with two crossing diameters, a stem from their
// crossing, a slanted arm, and a conical shade (two circles, four sides).
GroundTruthNetwork make_lamp(const Vec3& center, double size);

// Dispatch by name; throws std::invalid_argument listing model_names().
GroundTruthNetwork make_model(const std::string& name, const Vec3& center, double size);

// A closed circle of radius r around c in the plane spanned by the unit
// vectors u, v (t = 0 at c + r u, t = 1 at c + r v).
Curve make_circle(const Vec3& c, const Vec3& u, const Vec3& v, double r);

}  // namespace sketchlab::synthetic
