#include "choice.hpp"

namespace sketchlab::justdrawit {

double depth_score(double z_m, double z_M, double Z_m, double Z_M, bool first_term_only,
                   bool is_join) {
  const double span = Z_M - Z_m;
  if (!(span > 1e-12)) return 0.0;
  double q = 0.25 * (0.5 * (z_m + z_M) - Z_m) / span;  // further back: worse
  if (!first_term_only) q += 0.75 * (z_M - z_m) / span;  // more depth change: worse
  return is_join ? 2 * q : q;
}

const char* to_string(Decision d) {
  switch (d) {
    case Decision::new_curve: return "new_curve";
    case Decision::new_closed_curve: return "new_closed_curve";
    case Decision::oversketch: return "oversketch";
    case Decision::extend: return "extend";
    case Decision::partial_oversketch: return "partial_oversketch";
    case Decision::extend_close: return "extend_close";
    case Decision::combine: return "combine";
  }
  return "?";
}

std::optional<Decision> decision_from_string(std::string_view name) {
  for (Decision d : {Decision::new_curve, Decision::new_closed_curve, Decision::oversketch, Decision::extend,
                     Decision::partial_oversketch, Decision::extend_close, Decision::combine})
    if (name == to_string(d)) return d;
  return std::nullopt;
}

int choose(const std::vector<Candidate>& c, CurveId last_edited) {
  auto better = [&](int a, int b) {
    if (b < 0) return true;
    if (c[a].q != c[b].q) return c[a].q < c[b].q;
    return c[a].curve < c[b].curve;
  };
  int best = -1;
  if (last_edited != 0)
    for (int i = 0; i < static_cast<int>(c.size()); ++i)
      if (c[i].decision != Decision::combine && c[i].decision != Decision::new_closed_curve &&
          c[i].curve == last_edited && better(i, best))
        best = i;
  if (best >= 0) return best;
  for (int i = 0; i < static_cast<int>(c.size()); ++i)
    if (c[i].decision == Decision::combine && better(i, best)) best = i;
  if (best >= 0) return best;
  for (int i = 0; i < static_cast<int>(c.size()); ++i)
    if (better(i, best)) best = i;
  return best;
}

}  // namespace sketchlab::justdrawit
