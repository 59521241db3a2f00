#pragma once
// Selecting which constraints to enforce (CHI §4.3; CASSIE app items 10, 13,
// 14, 15): greedy removal minimising E = λ·E_fidelity + (1−λ)·E_connectivity
// over the constraints bound to an anchor, with the stroke's closure (if
// any) a hard constraint in every subset.
#include <optional>
#include <vector>

#include "anchor_binding.hpp"
#include "kkt_solve.hpp"

namespace sketchlab::cassie {

struct SearchSettings {
  double lambda = 0.6;
  FidelityScale fidelity;
  // E_connectivity's total: the constraints that got an anchor (item 13) or
  // every detected one (thesis eq. 3.12).
  bool connectivity_over_detected = false;
  double tangent_weight = 2.0;        // E_tangent multiplier (item 14)
  double planarity_weight = 1.0;      // E_planar multiplier; 0 disables planarity
  double planar_distance = 0.04;      // m: planar when every control point is this close (2δ)
  bool planar_test_snapped = false;   // ... to the axis-snapped plane, else to the fitted one
  double axis_angle = 0.5235987755982988;  // rad: plane normal snapped to an axis within this
  double min_edge = 1e-8;             // m, see SolveProblem
  bool closure = false;               // item 10: ends joined in every subset
  // Item 10: the end-tangent term of a closed stroke, unit direction both end
  // edges are drawn towards (when the end tangents agree).
  std::optional<Vec3> closure_tangent;
};

struct SubsetResult {
  bool feasible = false;      // solved with a finite result
  std::vector<int> subset;    // constraint indices (bound ones), ascending
  SolveResult solve;
  std::optional<Vec3> plane_normal;  // E_planar normal used, when planar
  int plane_axis = -1;        // axis the normal was snapped to, or -1
  double connectivity = 1.0;  // CHI eq. 3
  double energy = 0.0;        // CHI eq. 2
};

// E_connectivity = exp(−(Σ_subset w / Σ_total w)²) (CHI eq. 3), the total
// over the constraints that got an anchor (item 13) or, with
// `over_detected`, over every detected one (thesis eq. 3.12).
double connectivity_energy(const std::vector<Candidate>& constraints, const Binding& binding,
                           const std::vector<int>& subset, bool over_detected);

// Solves one subset on the bound curve: point targets at the anchors,
// tangent targets of aligned constraints, the closure, E_planar when the
// control points with the subset's targets in place fit a plane within
// planar_distance (item 14: tested per subset, normal snapped to an axis).
SubsetResult evaluate_subset(const Binding& binding, const std::vector<Candidate>& constraints,
                             const std::vector<int>& subset, const SearchSettings& settings);

struct SearchResult {
  SubsetResult best;
  int subsets_tried = 0;  // systems solved
  int levels = 0;         // greedy rounds
};

// Item 15 (`GetBestFit/GetBestSubset`): all bound constraints first; each
// round tries removing each of the current ones and moves to the child of
// lowest energy while that lowers E. A subset whose solve fails (not finite)
// is skipped; when every one fails `best` is infeasible.
SearchResult greedy_search(const Binding& binding, const std::vector<Candidate>& constraints,
                           const SearchSettings& settings);

}  // namespace sketchlab::cassie
