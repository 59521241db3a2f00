#pragma once
// The candidates for one stroke (§4.2, §4.3): every curve of the scene the
// stroke over-sketches, extends or closes, every pair of curves it combines,
// and the stroke closing on itself, each with its scores. choose() (choice.hpp)
// picks among them.
#include <vector>

#include "choice.hpp"
#include "inference_context.hpp"
#include "stroke_scene.hpp"

namespace sketchlab::justdrawit {

// `cum` is cumulative(s2). Curves lying wholly behind a visible draw plane
// give no candidate (§4.3).
std::vector<Candidate> gather_candidates(const Scene& scene, const Points2& s2, const std::vector<double>& cum,
                                         const Ctx& ctx);

}  // namespace sketchlab::justdrawit
