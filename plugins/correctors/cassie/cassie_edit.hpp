#pragma once
// The edit and the log of one corrected stroke: its curve (and mirrored
// copy), the nodes where it meets the sketch, every constraint considered
// (CASSIE app item 21: "applied" are the enforced ones, every other one,
// including those lost to a clash on an anchor, "rejected").
#include <vector>

#include "cassie_params.hpp"
#include "constraint_types.hpp"
#include "sketchlab/plugin/corrector.hpp"

namespace sketchlab::cassie {

// An enforced constraint and its parameter on the final curve.
struct Placement {
  int constraint = 0;
  double t = 0.0;
};

struct CorrectedStroke {
  Curve curve;                          // the final curve
  std::vector<Candidate> constraints;   // every position constraint considered
  std::vector<bool> enforced;           // per constraint
  std::vector<Placement> placed;        // enforced constraints that make a node
  bool closure_considered = false;      // item 10
  bool closure_enforced = false;
  bool mirror_copy = true;              // false when projected onto the mirror plane (item 18)
  std::vector<Constraint> soft;         // soft terms, reported as they are
};

// The Correction of `stroke`: the curve (id next_curve_id(), layer of the
// stroke, free for automatic) and, when `copy` and the stroke is off the
// mirror plane, its reflection (next id); a node per placement (a new one,
// or an extra incidence of the existing node through nodes_replaced; the
// copy joins nodes on the plane and gets nodes where its reflected
// intersections land on existing curves); a Constraint per position
// constraint (kinds intersection, grid_point, mirror_plane) and the closure,
// with `enforced` and the final distance as residual, then the soft terms.
Correction build_correction(const Stroke& stroke, const Sketch& sketch, const CorrectedStroke& corrected,
                            bool copy);

}  // namespace sketchlab::cassie
