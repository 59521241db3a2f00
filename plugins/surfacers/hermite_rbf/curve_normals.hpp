#pragma once
// Surface normals along the curves (JustDrawIt §6): exported normals when the
// corrector gave some, otherwise the default rules (planar curve: tangent ×
// plane normal pointing out from the centroid; non-planar: the centroid rule;
// intersections: a plane fitted to the samples around them), propagated by
// spherical interpolation and made perpendicular to the tangent.
#include <vector>

#include "curve_samples.hpp"

namespace sketchlab::hermite_rbf {

// A normal known at one sample (before propagation).
struct NormalKey {
  int sample = 0;
  Vec3 normal = Vec3::UnitZ();
};

// Default keys of one curve from its shape alone (planar or centroid rule);
// empty for a straight line, whose plane is undefined.
std::vector<NormalKey> default_normal_keys(const CurveSamples& samples, const NormalParams& params);

// Fills samples.normals from keys sorted by sample: slerp between keys (by
// sample index, i.e. arclength), constant beyond the end keys of open curves,
// across the seam of closed ones; then the rejection from the tangent,
// normalised. Samples whose normal is parallel to the tangent, and all samples
// when there is no key, get a zero normal.
void propagate_normals(CurveSamples& samples, std::vector<NormalKey> keys);

// Fills the normals of every curve (curves[i].curve must exist in network).
void assign_normals(std::vector<CurveSamples>& curves, const Network& network, const NormalParams& params);

// Spherical interpolation of unit vectors a -> b at u in [0, 1].
Vec3 slerp(const Vec3& a, const Vec3& b, double u);

}  // namespace sketchlab::hermite_rbf
