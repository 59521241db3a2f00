#pragma once
// Parameters of the Hermite RBF surfacer (JustDrawIt, Grimm & Joshi 2012, §6)
// and their ParamSpecs.
#include <cstdint>
#include <vector>

#include "sketchlab/plugin/params.hpp"

namespace sketchlab::hermite_rbf {

// How curves become constraints (§6).
struct SamplingParams {
  double sample_spacing = 0.005;  // m between curve samples (the paper's "point samples")
  int max_samples = 6000;         // the spacing grows when the curves need more
  int point_stride = 6;           // a point constraint at least every 6 samples
  double deviation_factor = 1.0;  // ... or when skipped samples leave the fitted line by this × spacing
  int tangent_stride = 12;        // a tangent constraint at least every 12 samples
  double tangent_change = 0.4;    // ... or when 1 - dot(t, t_last) exceeds this
  int normal_stride = 12;         // normal constraints likewise
  double normal_change = 0.1;     // ... with 1 - dot(n, n_last) > 0.1
};

// Default normals when the corrector exported none (§6).
struct NormalParams {
  double planarity = 0.01;   // a curve is planar when it leaves its fitted plane by <= this × its length
  int intersection_window = 10;  // samples each side fitted by the plane at an intersection
};

struct SolveParams {
  // λ added to the kernel block's diagonal, in coordinates normalised to a unit
  // bounding-box diagonal; raised ×100 (reported) when the factorisation fails.
  double regularizer = 1e-12;
};

struct MeshParams {
  int resolution = 64;     // grid cells along the longest side of the box
  double padding = 0.15;   // box margin around the constraints, × their bounding-box diagonal
  double far_distance = 0.1;  // "far from any curve", × the bounding-box diagonal
  bool trim_far_components = true;  // drop closed components with no vertex near a curve
  int threads = 0;         // 0: one per core
};

struct HermiteRbfParams {
  SamplingParams sampling;
  NormalParams normals;
  SolveParams solve;
  MeshParams mesh;
};

std::vector<ParamSpec> hermite_rbf_param_specs();
HermiteRbfParams hermite_rbf_params(const Params& params);

}  // namespace sketchlab::hermite_rbf
