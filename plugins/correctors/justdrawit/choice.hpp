#pragma once
// Choosing what to do with the stroke (§4.3): scores and the exceptions.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stroke_curve_analysis.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab::justdrawit {

// Depth score q_d (eq. 6) of a curve with eye depths in [z_m, z_M] in a
// network spanning [Z_m, Z_M]; `first_term_only` for over-sketches; doubled
// for joins (§4.3). 0 when the network has no depth extent.
double depth_score(double z_m, double z_M, double Z_m, double Z_M, bool first_term_only,
                   bool is_join);

// q = q_d/4 + 3 q_m/4 (§4.3).
inline double final_score(double q_d, double q_m) { return 0.25 * q_d + 0.75 * q_m; }

enum class Decision { new_curve, new_closed_curve, oversketch, extend, partial_oversketch,
                      extend_close, combine };
const char* to_string(Decision d);
// The decision `to_string` names; nullopt for any other text.
std::optional<Decision> decision_from_string(std::string_view name);

struct Candidate {
  Decision decision = Decision::new_curve;
  CurveId curve = 0;   // the curve edited (combine: the one the stroke starts on)
  CurveId curve2 = 0;  // combine: the one it ends on
  CurveMatch match;    // single curve; combine: start vs curve, end vs curve2
  EndMatch self;       // new closed curve: the stroke's end against its start
  double q_m = 0, q_d = 0, q = 0;
};

// §4.3 order: a candidate on the last edited curve wins; then the best
// combination of two curves; then the lowest score (ties: lower curve id).
// Candidates on curves behind a visible draw plane must already be removed.
// Returns the index of the chosen candidate, or -1 for "new curve".
int choose(const std::vector<Candidate>& candidates, CurveId last_edited);

}  // namespace sketchlab::justdrawit
