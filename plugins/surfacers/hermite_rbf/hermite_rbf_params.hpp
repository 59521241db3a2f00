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
  // network: intersection normals oriented across the network and used along
  // every curve through them (default rules only away from intersections);
  // paper: §6 as written (default keys wherever no intersection is within
  // intersection_window samples, each curve oriented on its own).
  bool network_rule = true;
};

struct SolveParams {
  // λ added to the kernel block's diagonal, in coordinates normalised to a unit
  // bounding-box diagonal; raised ×100 (reported) when the factorisation fails.
  double regularizer = 1e-12;
};

// The partition of unity of local fits (partition_cells.hpp).
struct PartitionParams {
  int max_rows = 240;     // a cell is split while its support holds more rows
  int min_rows = 60;      // a leaf's support grows until it holds this many rows ...
  int min_normals = 4;    // ... and this many normal constraints
  double overlap = 1.5;   // support radius / cell half diagonal (Ohtake et al. 2003: 0.75 × diagonal)
  int max_depth = 14;     // octree levels at most
};

// dense: one global system (exact, O(m²) memory, O(m³) time; the reference);
// partition: local fits blended by a partition of unity (linear memory, and a
// single cell, i.e. the dense solve, while everything fits in max_rows).
enum class Solver { partition, dense };

// none: the closed zero set (JustDrawIt §6: "water-tight, manifold");
// far_components: without its components far from every curve (still
// closed); enclosed: also cut where no curves enclose it (surface_trim.hpp).
enum class Trim { none, far_components, enclosed };

struct MeshParams {
  int resolution = 64;     // grid cells along the longest side of the box
  double padding = 0.15;   // box margin around the constraints, × their bounding-box diagonal
  double far_distance = 0.1;  // "far from any curve", × the bounding-box diagonal
  Trim trim = Trim::enclosed;
  double trim_reach = 0.3;       // curves enclosing a point lie within this × the bounding-box diagonal
  double trim_elevation = 0.785398163397448;  // rad (45°), largest elevation of an enclosing curve seen from the tangent plane
  double trim_gap = 3.14159265358979;         // rad (180°), largest angle with no curve around an enclosed point
  int threads = 0;         // 0: one per core
};

struct HermiteRbfParams {
  SamplingParams sampling;
  NormalParams normals;
  SolveParams solve;
  Solver solver = Solver::partition;
  PartitionParams partition;
  MeshParams mesh;
};

std::vector<ParamSpec> hermite_rbf_param_specs();
HermiteRbfParams hermite_rbf_params(const Params& params);

}  // namespace sketchlab::hermite_rbf
