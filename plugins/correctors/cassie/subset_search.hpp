#pragma once
// Selecting which candidate intersections to enforce (CHI §4.3, thesis
// §3.2.4.4): greedy removal minimising E = λ·E_fidelity + (1−λ)·E_connectivity.
#include <optional>
#include <vector>

#include "candidates.hpp"
#include "kkt_solve.hpp"

namespace sketchlab::cassie {

// The fitted curve with joints inserted for a subset of candidates
// (eq. 3.3: reuse a joint within the reuse distance, else de Casteljau split).
struct BoundCurve {
  Curve curve;
  std::vector<int> control_index;  // per subset entry: constrained control point
};

BoundCurve bind_candidates(const Curve& fitted, const std::vector<Candidate>& candidates,
                           const std::vector<int>& subset, double reuse);

// Soft terms shared by every subset.
struct SoftTerms {
  std::optional<Vec3> plane_normal;
  double planarity_weight = 1.0;
  double tangent_weight = 1.0;
  double min_edge = 1e-6;
};

struct SubsetResult {
  bool feasible = false;  // false: incompatible targets (pruned, not solved) or singular
  std::vector<int> subset;  // candidate indices, ascending
  BoundCurve bound;
  SolveResult solve;
  double connectivity = 1.0;  // CHI eq. 3
  double energy = 0.0;        // CHI eq. 2
};

// E_connectivity = exp(−(Σ b_i w_i / Σ w_i)²) (CHI eq. 3).
double connectivity_energy(const std::vector<Candidate>& candidates, const std::vector<int>& subset);

// Binds and solves one subset; infeasible without solving when two
// candidates pin one control point (closure joins both ends) to different
// places ("incompatible", CHI §4.3).
SubsetResult evaluate_subset(const Curve& fitted, const std::vector<Candidate>& candidates,
                             const std::vector<int>& subset, const SoftTerms& soft,
                             double lambda, double reuse, int& solves);

struct SearchResult {
  SubsetResult best;
  int subsets_tried = 0;  // subsets whose system was solved
  int levels = 0;         // greedy rounds
  int pruned = 0;         // subsets skipped as incompatible
};

// Starts from all candidates and repeatedly removes the one whose removal
// lowers E the most, while E decreases (CHI §4.3).
SearchResult greedy_search(const Curve& fitted, const std::vector<Candidate>& candidates,
                           const SoftTerms& soft, double lambda, double reuse);

}  // namespace sketchlab::cassie
