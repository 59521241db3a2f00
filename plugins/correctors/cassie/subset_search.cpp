#include "subset_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "plane_fit.hpp"
#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::cassie {

double connectivity_energy(const std::vector<Candidate>& cands, const Binding& b,
                           const std::vector<int>& subset, bool over_detected) {
  double all = 0.0, on = 0.0;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (over_detected || b.anchor[i] >= 0) all += cands[i].weight;
  for (int i : subset) on += cands[i].weight;
  const double ratio = all > 0 ? on / all : 0.0;
  return std::exp(-ratio * ratio);
}

SubsetResult evaluate_subset(const Binding& b, const std::vector<Candidate>& cands,
                             const std::vector<int>& subset, const SearchSettings& st) {
  SubsetResult r;
  r.subset = subset;
  const std::vector<Vec3>& cp = b.curve.control_points;
  const int last = static_cast<int>(cp.size()) - 1;
  SolveProblem pr;
  pr.input = b.curve;
  pr.closure = st.closure;
  pr.min_edge = st.min_edge;
  pr.fidelity = st.fidelity;
  pr.planarity_weight = st.planarity_weight;
  // Closure makes both ends one point: a target at the last joint is a
  // target at the first.
  auto group = [&](int idx) { return st.closure && idx == last ? 0 : idx; };
  std::vector<Vec3> placed = cp;
  for (int i : subset) {
    const Candidate& c = cands[i];
    const int a = b.anchor[i];
    pr.points.push_back({group(a), c.target});
    placed[a] = c.target;
    if (c.tangent) pr.tangents.push_back({a, *c.tangent, st.tangent_weight});
  }
  if (st.closure && st.closure_tangent) {
    pr.tangents.push_back({0, *st.closure_tangent, st.tangent_weight});
    pr.tangents.push_back({last, *st.closure_tangent, st.tangent_weight});
  }
  if (st.planarity_weight > 0) {
    const PlaneFit plane = fit_plane(placed, st.planar_distance, st.axis_angle, st.planar_test_snapped);
    if (plane.planar) {
      pr.plane_normal = plane.normal;
      r.plane_normal = plane.normal;
      r.plane_axis = plane.axis;
    }
  }
  r.solve = solve_constrained(pr);
  if (!r.solve.ok) return r;
  r.feasible = true;
  r.connectivity = connectivity_energy(cands, b, subset, st.connectivity_over_detected);
  r.energy = st.lambda * r.solve.fidelity + (1.0 - st.lambda) * r.connectivity;
  return r;
}

SearchResult greedy_search(const Binding& b, const std::vector<Candidate>& cands, const SearchSettings& st) {
  SearchResult out;
  std::vector<int> current;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (b.anchor[i] >= 0) current.push_back(static_cast<int>(i));
  const double inf = std::numeric_limits<double>::infinity();
  SubsetResult cur = evaluate_subset(b, cands, current, st);
  ++out.subsets_tried;
  double e_cur = cur.feasible ? cur.energy : inf;
  while (!current.empty()) {
    ++out.levels;
    SubsetResult best;
    double e_best = inf;
    for (std::size_t k = 0; k < current.size(); ++k) {
      check_budget();  // issue 17: the per-event time budget
      std::vector<int> child = current;
      child.erase(child.begin() + static_cast<std::ptrdiff_t>(k));
      SubsetResult r = evaluate_subset(b, cands, child, st);
      ++out.subsets_tried;
      if (r.feasible && r.energy < e_best) e_best = r.energy, best = std::move(r);
    }
    if (!(e_best < e_cur)) break;
    current = best.subset;
    cur = std::move(best);
    e_cur = e_best;
  }
  out.best = std::move(cur);
  return out;
}

}  // namespace sketchlab::cassie
