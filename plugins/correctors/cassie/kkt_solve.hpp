#pragma once
// The constrained least-squares problem of CASSIE (thesis eq. 3.10) for one
// poly-Bézier, solved as a single linear KKT system (eq. 3.11).
//
// Variables: the M = 3K+1 control points (C0 between Béziers holds by
// construction: the curve stores shared joints, which is eq. 3.6 "by
// elimination"). Objective: E_fidelity (eq. 3.2) + Σ E_tangent (eq. 3.8) +
// E_planar (eq. 3.9). Hard constraints: linearised G1 at smooth interior
// joints (eq. 3.7), point targets (eq. 3.4) and closure (eq. 3.5).
#include <optional>
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab::cassie {

struct PointTarget {
  int index = 0;  // control point index (a joint, multiple of 3)
  Vec3 target = Vec3::Zero();
};

struct TangentTarget {
  int index = 0;               // joint whose adjacent edge is aligned
  Vec3 direction = Vec3::UnitX();  // unit
  double weight = 1.0;
};

// E_fidelity = factor·(1/(M·S²)·Σ|P_i − P̄_i|² + 1/(M−1)·Σ|Δe_i|²/|ē_i|²),
// with S = position_scale, or the span L of eq. 3.2 when position_scale is
// 0 (thesis); the CASSIE app uses S = 2δ and factor 0.5 (item 13).
struct FidelityScale {
  double position_scale = 0.0;  // m
  double factor = 1.0;
};

// How eq. 3.11 is solved (the same solution up to rounding): block
// elimination with a dense Schur complement (range_space; fastest for the
// usual few constraints), or one sparse LU of the whole KKT matrix
// (sparse_lu; a stroke across tens of curves: 80 crossings took 600 ms a
// stroke the first way, 30 ms this way, `bench_cassie` hatch cases).
// automatic: sparse_lu from kSparseLuRows constraint rows (about ten
// segments, where the two cost the same).
enum class KktMethod { automatic, range_space, sparse_lu };
inline constexpr int kSparseLuRows = 48;

struct SolveProblem {
  Curve input;  // P̄: the (possibly split) fitted curve
  std::vector<PointTarget> points;
  bool closure = false;
  std::vector<TangentTarget> tangents;
  std::optional<Vec3> plane_normal;  // unit; E_planar active when set
  double planarity_weight = 1.0;
  // Edges shorter than this (m) get this length in the normalisations and
  // their joints no G1 row (the linearisation needs a direction).
  double min_edge = 1e-6;
  FidelityScale fidelity;
  KktMethod method = KktMethod::automatic;
};

struct SolveResult {
  bool ok = false;
  std::vector<Vec3> control_points;
  double fidelity = 0.0;  // eq. 3.2 on the result
  double max_constraint_residual = 0.0;  // m, over point and closure targets
};

// E_fidelity of `points` against `input` (same size M >= 2).
double fidelity_energy(const std::vector<Vec3>& input, const std::vector<Vec3>& points,
                       double min_edge, const FidelityScale& scale = {});

// Solves eq. 3.11 (`problem.method`) with one step of iterative refinement.
// ok = false when the KKT matrix is singular or the result is not finite
// (e.g. incompatible targets that slipped through).
SolveResult solve_constrained(const SolveProblem& problem);

}  // namespace sketchlab::cassie
