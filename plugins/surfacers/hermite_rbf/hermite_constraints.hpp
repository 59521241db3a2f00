#pragma once
// Point, tangent and normal constraints picked from curve samples (§6).
#include <vector>

#include "curve_samples.hpp"

namespace sketchlab::hermite_rbf {

// f = 0 at points; ∇f·t = 0 at tangent constraints; ∇f = n at normal
// constraints. Positions in metres, directions unit.
struct HermiteConstraints {
  std::vector<Vec3> points;
  std::vector<Vec3> tangent_points, tangents;
  std::vector<Vec3> normal_points, normals;
  std::size_t size() const { return points.size() + tangents.size() + normals.size(); }
  // Linear equations these stand for (1 per point or tangent, 3 per normal).
  std::size_t rows() const { return points.size() + tangents.size() + 3 * normals.size(); }
};

// §6 on one curve: a point constraint at the first and last sample and at
// least every point_stride samples, or earlier where the skipped samples
// leave the line fitted to them by more than deviation_factor × spacing.
// Tangent and normal constraints are placed at point-constraint samples (so
// they lie on the surface): a normal when 1 - dot(n, last normal) exceeds
// normal_change or normal_stride samples passed; a tangent likewise with
// tangent_change / tangent_stride, except where a normal is placed (∇f = n
// already makes ∇f·t = 0, and the repeated row would make the system singular).
void pick_constraints(const CurveSamples& samples, const SamplingParams& params, HermiteConstraints& out);

// Merges constraints that duplicate a kept one within `radius` metres
// (curves crossing at a node sample the same spot). Constraints at one
// position form a site (a point, its normal or tangents); in order, a site
// closer than `radius` to a kept site is merged into the earliest one: the kept
// site gains its point, its normal if it had none, its tangents unless
// nearly parallel (|dot| > 0.9) to one already there; tangents are dropped
// where a normal is. Derivative constraints thus stay on a point constraint,
// which the partition of unity needs to meet them exactly.
HermiteConstraints merge_duplicates(const HermiteConstraints& in, double radius);

// The constraints of each kind sorted by position, then direction: a
// canonical order, so that a model fitted to them does not depend on the
// order the curves were visited in (and an incremental update equals a fit
// from scratch).
HermiteConstraints canonical_order(HermiteConstraints constraints);

// Throws std::invalid_argument naming the problem when no surface can be
// fitted: no normal constraint, fewer than 3 points, a non-finite position,
// or every constraint on one straight line.
void check_constraints(const HermiteConstraints& constraints);

}  // namespace sketchlab::hermite_rbf
