#pragma once
// Intended relations of a ground-truth network, found from its exact
// geometry, and the order in which a person would draw its curves.
#include <cstddef>
#include <vector>

#include "ground_truth.hpp"

namespace sketchlab::synthetic {

// Length scale of a network: the diagonal of its control points' bounding
// box (metres); 1 for an empty network.
double network_scale(const GroundTruthNetwork& net);

// Where two curves meet: parameters on each and whether both are curve ends.
struct Contact {
  double ta = 0.0, tb = 0.0;
  bool both_ends = false;  // coincident endpoints (else an intersection)
};

// Contacts of curves a and b within `tolerance` metres: coincident ends, an
// end of one on the interior of the other, and interior crossings of two
// lines. Parameters within 1e-9 of a joint are snapped to it, so relations
// at circle joints are exact. Interior crossings of two non-line curves are
// not searched (none of the built-in models has one).
std::vector<Contact> contacts(const Curve& a, const Curve& b, double tolerance);

// Relations among the curves, in the order of the later curve involved (so a
// relation can be emitted right after its last curve is drawn):
//  - coincident_point: ends of two curves within tol (parameters: t on each);
//  - intersection: an end on the other's interior, or two lines crossing;
//  - parallel, equal_length: lines whose directions (lengths) agree within
//    1e-9 (relative); each line is related to the first-drawn line of its
//    class only, which implies all pairs (linear, not quadratic, in size);
//  - perpendicular: two lines that meet (a contact above) at a right angle
//    within 1e-9;
//  - planar: a non-line curve whose control points lie in a plane within
//    tol (one curve).
// tol = 1e-9 · network_scale.
std::vector<GroundTruthRelation> infer_relations(const GroundTruthNetwork& net);

// The curve traced backwards (same points, t -> t_max - t).
Curve reversed(const Curve& curve);

// The network in drawing order: scaffold curves first, then the others; in
// each group the longest curve first, then repeatedly the longest curve that
// touches one already drawn (or the longest left when none does). A curve
// whose end touches the drawing but whose start does not is reversed so it
// starts from the connection, as people draw from an existing point.
GroundTruthNetwork plan_drawing(const GroundTruthNetwork& net);

}  // namespace sketchlab::synthetic
