#pragma once
// Constraints found while the stroke is drawn, as in the CASSIE app: not by
// intersecting the finished curve with the network, but from the moving
// brush (items 6, 7, 18, 19).
#include <vector>

#include "cassie_params.hpp"
#include "constraint_types.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::cassie {

struct DetectionStats {
  int brush_queries = 0;   // spatial-index queries of the brush (one per step)
  int curve_contacts = 0;  // curves found in contact, summed over the steps
  int grid_queries = 0;    // raw samples tested against the grid
};

// Item 6: the brush sphere (radius th.brush) around the raw hand
// position, interpolated from the samples at t0, t0 + brush_step, ... (before
// the last sample's time: one query at the start, none at the end; strokes
// without duration are stepped sample by sample). It fires a curve
// constraint when it enters a curve's collider tube (distance <= th.contact,
// from the spatial index): the target is the closest point of the curve to
// the brush; node kind when an end node of the crossed piece (with more than
// one incidence) is within th.node_snap (item 8), or the crossed curve's own
// end node with one incidence within th.dangling_snap (item 22). Re-entering
// fires again.
// Item 18 (`mirror` true): entering the mirror plane fires a plane
// constraint at the brush projected onto it, unless a curve in contact
// lies in the plane (the stroke beats the plane).
// Item 19 (grid on): each raw sample within th.grid of a grid point fires
// a grid constraint there, or a curve (plane) constraint at the closest
// point of a curve (the plane) within th.grid of that point.
// Constraints arrive in time order and are merged by add_constraint. Work:
// one index query per step, independent of the curves' sizes beyond the
// closest points of the curves in contact.
std::vector<Candidate> detect_constraints(const Stroke& stroke, const Sketch& sketch,
                                          const Thresholds& th, double brush_step, bool mirror,
                                          DetectionStats& stats);

// Item 7 (`InputStroke.AddConstraint`): `c` is compared with the last
// constraint only. Two plane constraints within th.plane_merge are one (the
// newer kept); otherwise within th.merge one is kept: a curve beats a grid
// point or the plane, a node beats a non-node, else the newer wins. No cap.
void add_constraint(std::vector<Candidate>& constraints, const Candidate& c, const Thresholds& th);

}  // namespace sketchlab::cassie
