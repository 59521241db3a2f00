#pragma once
// CASSIE's stroke structuring (CHI 2021 §4, thesis §3.2): preprocessing,
// candidate detection, greedy selection of intersections with a KKT solve per
// subset, lines by Appendix A, mirroring and on-surface projection.
#include "cassie_params.hpp"
#include "sketchlab/plugin/corrector.hpp"

namespace sketchlab::cassie {

// The correction of one stroke: new curve (and its mirrored copy), the nodes
// where it meets the sketch (new nodes, or existing ones with an extra
// incidence in nodes_replaced), every constraint considered, statistics.
// A stroke that cannot be fitted (fewer than 2 distinct samples, zero length)
// gives a Correction with `error` set and an empty edit.
// `applied` (not owned; nullptr: the search as usual): the constraint
// targets a reference applied to this stroke (constraint_oracle.hpp). A
// poly-Bézier then enforces exactly the bound constraints within
// oracle_radius·δ(s) of one of them (nearest first), with no search; a line's rules
// (item 17) choose among those only; with params.oracle_positions the
// matched ones are placed at the applied targets. Statistics "oracle" = 1 and
// "oracle_matched" (constraints matched) say it was used.
Correction correct_stroke(const Stroke& stroke, const Sketch& sketch, const CassieParams& params,
                          const std::vector<Vec3>* applied = nullptr);

}  // namespace sketchlab::cassie
