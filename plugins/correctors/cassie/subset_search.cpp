#include "subset_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/split.hpp"
#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::cassie {

BoundCurve bind_candidates(const Curve& fitted, const std::vector<Candidate>& cands,
                           const std::vector<int>& subset, double reuse) {
  BoundCurve b;
  const int k_count = fitted.segment_count();
  // Global parameter of the joint each entry constrains (closure: -1).
  std::vector<double> joint_t(subset.size(), -1.0);
  std::vector<double> splits;
  for (std::size_t s = 0; s < subset.size(); ++s) {
    const Candidate& c = cands[subset[s]];
    if (c.kind == TargetKind::closure) continue;
    const Vec3 p = evaluate(fitted, c.t_stroke);
    int best = -1;
    double best_d = reuse;
    for (int k = 0; k <= k_count; ++k) {
      const double d = (fitted.control_points[3 * k] - p).norm();
      if (d <= best_d) best = k, best_d = d;
    }
    double t = best >= 0 ? static_cast<double>(best) : c.t_stroke;
    if (best < 0 && std::abs(t - std::round(t)) < 1e-9) t = std::round(t);
    joint_t[s] = t;
    if (t != std::round(t)) splits.push_back(t);
  }
  std::sort(splits.begin(), splits.end());
  splits.erase(std::unique(splits.begin(), splits.end(),
                           [](double x, double y) { return std::abs(x - y) < 1e-9; }),
               splits.end());
  b.curve = fitted;
  for (auto it = splits.rbegin(); it != splits.rend(); ++it) b.curve = insert_joint(b.curve, *it).first;
  // Final joint index: joints of the input and inserted ones strictly before t.
  auto index_of = [&](double t) {
    int before = 0;
    for (int k = 0; k <= k_count; ++k) before += (k < t - 1e-9);
    for (double s : splits) before += (s < t - 1e-9);
    return 3 * before;
  };
  const int last = static_cast<int>(b.curve.control_points.size()) - 1;
  for (std::size_t s = 0; s < subset.size(); ++s)
    b.control_index.push_back(joint_t[s] < 0 ? last : index_of(joint_t[s]));
  return b;
}

double connectivity_energy(const std::vector<Candidate>& cands, const std::vector<int>& subset) {
  double all = 0.0, on = 0.0;
  for (const Candidate& c : cands) all += c.weight;
  for (int i : subset) on += cands[i].weight;
  const double ratio = all > 0 ? on / all : 0.0;
  return std::exp(-ratio * ratio);
}

SubsetResult evaluate_subset(const Curve& fitted, const std::vector<Candidate>& cands,
                             const std::vector<int>& subset, const SoftTerms& soft, double lambda,
                             double reuse, int& solves) {
  SubsetResult r;
  r.subset = subset;
  r.bound = bind_candidates(fitted, cands, subset, reuse);
  const int last = static_cast<int>(r.bound.curve.control_points.size()) - 1;
  bool closure = false;
  for (int i : subset) closure |= cands[i].kind == TargetKind::closure;
  // Closure makes both ends one point: group them.
  auto group = [&](int idx) { return closure && idx == last ? 0 : idx; };
  SolveProblem pr;
  pr.input = r.bound.curve;
  pr.closure = closure;
  pr.plane_normal = soft.plane_normal;
  pr.planarity_weight = soft.planarity_weight;
  pr.min_edge = soft.min_edge;
  for (std::size_t s = 0; s < subset.size(); ++s) {
    const Candidate& c = cands[subset[s]];
    if (c.kind == TargetKind::closure) continue;
    const int g = group(r.bound.control_index[s]);
    bool dup = false;
    for (const PointTarget& p : pr.points)
      if (p.index == g) {
        if ((p.target - c.target).norm() > 1e-9) return r;  // incompatible: pruned
        dup = true;
      }
    if (!dup) pr.points.push_back({g, c.target});
    if (c.tangent) pr.tangents.push_back({r.bound.control_index[s], *c.tangent, soft.tangent_weight});
  }
  ++solves;
  r.solve = solve_constrained(pr);
  if (!r.solve.ok) return r;
  r.feasible = true;
  r.connectivity = connectivity_energy(cands, subset);
  r.energy = lambda * r.solve.fidelity + (1.0 - lambda) * r.connectivity;
  return r;
}

SearchResult greedy_search(const Curve& fitted, const std::vector<Candidate>& cands,
                           const SoftTerms& soft, double lambda, double reuse) {
  SearchResult out;
  std::vector<int> current(cands.size());
  for (std::size_t i = 0; i < cands.size(); ++i) current[i] = static_cast<int>(i);
  int solves = 0;
  const double inf = std::numeric_limits<double>::infinity();
  SubsetResult cur = evaluate_subset(fitted, cands, current, soft, lambda, reuse, solves);
  double e_cur = cur.feasible ? cur.energy : inf;
  while (!current.empty()) {
    ++out.levels;
    SubsetResult best;
    double e_best = inf;
    int drop_if_stuck = -1;
    for (std::size_t k = 0; k < current.size(); ++k) {
      check_budget();  // issue 17: the per-event time budget
      std::vector<int> child = current;
      child.erase(child.begin() + static_cast<std::ptrdiff_t>(k));
      const int before = solves;
      SubsetResult r = evaluate_subset(fitted, cands, child, soft, lambda, reuse, solves);
      out.pruned += solves == before;
      if (r.feasible && r.energy < e_best) e_best = r.energy, best = std::move(r);
      // When every child is infeasible, drop the lightest candidate.
      if (drop_if_stuck < 0 || cands[current[k]].weight < cands[current[drop_if_stuck]].weight)
        drop_if_stuck = static_cast<int>(k);
    }
    if (e_best < e_cur) {
      current = best.subset;
      cur = std::move(best);
      e_cur = e_best;
    } else if (e_cur == inf) {
      current.erase(current.begin() + drop_if_stuck);
      cur = evaluate_subset(fitted, cands, current, soft, lambda, reuse, solves);
      e_cur = cur.feasible ? cur.energy : inf;
    } else {
      break;
    }
  }
  if (e_cur == inf) cur = evaluate_subset(fitted, cands, {}, soft, lambda, reuse, solves);
  out.best = std::move(cur);
  out.subsets_tried = solves;
  return out;
}

}  // namespace sketchlab::cassie
