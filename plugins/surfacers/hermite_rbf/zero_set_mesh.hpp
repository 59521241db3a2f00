#pragma once
// The zero set of a sampled implicit function as a triangle mesh (VTK flying
// edges).
#include "grid_evaluation.hpp"
#include "sketchlab/mesh.hpp"

namespace sketchlab::hermite_rbf {

// Triangles of {f = 0}, oriented with normals towards f > 0 (outside), with
// area-weighted vertex normals. Closed whenever the grid border is > 0, which
// evaluate_grid guarantees. Degenerate (zero-area) triangles are dropped.
Mesh extract_zero_set(const ScalarGrid& grid);

}  // namespace sketchlab::hermite_rbf
