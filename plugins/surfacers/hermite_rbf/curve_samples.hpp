#pragma once
// Curves as the dense point samples JustDrawIt's §6 rules count.
#include <vector>

#include "hermite_rbf_params.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::hermite_rbf {

// One curve sampled at (nearly) equal arclength. Closed curves do not repeat
// their first sample at the end.
struct CurveSamples {
  CurveId curve = 0;
  bool closed = false;
  double t_max = 0.0;           // the curve's parameter range is [0, t_max]
  double spacing = 0.0;         // m, average distance between consecutive samples
  std::vector<double> t;        // curve parameters
  std::vector<Vec3> points;     // m
  std::vector<Vec3> tangents;   // unit
  std::vector<Vec3> normals;    // unit and ⊥ tangent, or zero where unknown (curve_normals.hpp)
};

// Samples every curve of the network (by id) at spacing
// max(params.sample_spacing, total length / params.max_samples). Curves of
// (numerically) zero length are skipped.
std::vector<CurveSamples> sample_curves(const Network& network, const SamplingParams& params);

// Index of the sample whose parameter is closest to t.
int nearest_sample(const CurveSamples& samples, double t);

}  // namespace sketchlab::hermite_rbf
