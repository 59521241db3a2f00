#pragma once
// Discrete mean-curvature (Willmore-type) energy of a triangle mesh, used to
// check that curvature-flow smoothing does its job: Σ_v |Δx_v|² / (4 A_v)
// over interior vertices, Δ the cotangent Laplacian and A_v the barycentric
// area (∫H² for a smooth surface). Units 1 (scale invariant).
#include "sketchlab/mesh.hpp"

namespace sketchlab::soapfilm {

double mean_curvature_energy(const Mesh& mesh);

// True when every edge has one or two faces, border edges form one closed
// loop and no face is degenerate (repeated vertex).
bool is_manifold_disk(const Mesh& mesh);

}  // namespace sketchlab::soapfilm
