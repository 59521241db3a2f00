#pragma once
// Candidate constraints of a new scaffold line l = (l_a, l_b) against the
// existing scaffold (ScaffoldSketch §4.1, eq. 1–5). Each term is a residual
// r(l) whose squared norm is the paper's C(l).
#include <vector>

#include "scaffold_params.hpp"
#include "sketchlab/network.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab::scaffoldsketch {

enum class TermKind { point_point, point_line, perpendicular, parallel, equal_length };

// The point of l a point term acts on.
enum class LinePoint { start, end, middle };

struct ScaffoldTerm {
  TermKind kind = TermKind::point_point;
  LinePoint at = LinePoint::start;  // point kinds only
  Vec3 p = Vec3::Zero();            // point_point: the keypoint
  Vec3 ka = Vec3::Zero(), kb = Vec3::Zero();  // point_line / equal_length: line k
  Vec3 d = Vec3::Zero();            // perpendicular / parallel: unit direction
  CurveId curve = 0;                // the scaffold line referenced (0: the up axis)
  double curve_t = 0.0;             // keypoint / closest parameter on that curve
};

// A scaffold line of the network: kind line, on any layer but shape.
bool is_scaffold_line(const NetworkCurve& curve);

// C_i(l) of eq. 1–5 (squared metres for point kinds, dimensionless else);
// parallel is |u x d|² = sin²θ instead of eq. 4's (1 - |u·d|)² (README).
// Angle kinds use the unit direction of l; a zero-length l gives C = 1 for
// them (maximally unsatisfied, never NaN).
double term_energy(const ScaffoldTerm& term, const Vec3& a, const Vec3& b);

// Whether s and t have the same energy for every l up to `tolerance`
// (metres for points and line ends, unit-vector difference for directions,
// relative for lengths): e.g. parallel to two lines drawn parallel. Such
// terms also share their IRLS weight, so the solver may merge them.
bool same_energy(const ScaffoldTerm& s, const ScaffoldTerm& t, double tolerance);

// Residual r (rows used: 3 for point kinds and parallel, 1 else; returned) with
// |r|² = C, and its Jacobian with respect to x = (a, b) (rows x 6).
int term_residual(const ScaffoldTerm& term, const Vec3& a, const Vec3& b, Vec3& r,
                  Eigen::Matrix<double, 3, 6>& jacobian);

// The same residual with its Jacobian in factored form: every term depends
// on (a, b) through one point fa·a + fb·b (the line point, or b - a for
// directions and length), so J = [fa·m, fb·m] with m = dr/d(that point)
// (rows x 3, unused rows zero). The solver's normal equations need only mᵀm.
int term_linearisation(const ScaffoldTerm& term, const Vec3& a, const Vec3& b, Vec3& r, Mat3& m,
                       double& fa, double& fb);

// Every candidate whose energy on the input line (a, b) is below its
// threshold: point–point and point–line within point_distance/s of l_a, l_b
// (and l_m for point–point when midpoint_snapping), perpendicular and parallel
// within angle_threshold, equal length within equal_length_tolerance, against
// every scaffold line, and workspace.up for parallel (eq. 4) and
// perpendicular (eq. 3). Coincident keypoints
// (several lines sharing a corner) give one point–point term, and a keypoint
// is a candidate for the nearest point of l only (two points of l held at
// one keypoint would make l a point). Deterministic order: by line point,
// then kind, then curve id.
std::vector<ScaffoldTerm> scaffold_candidates(const Vec3& a, const Vec3& b, const Network& network,
                                              const Workspace& workspace,
                                              const ScaffoldParams& params, double scale);

}  // namespace sketchlab::scaffoldsketch
