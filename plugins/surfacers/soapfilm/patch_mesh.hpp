#pragma once
// Patch geometry (CASSIE CHI'21 §5.2, thesis §3.3.4): fill a closed boundary
// polyline with triangles, remesh isotropically with the border protected,
// then smooth by curvature flow with the border fixed ("soap film").
// The only file of the plugin that includes CGAL.
#include <vector>

#include "sketchlab/mesh.hpp"

namespace sketchlab::soapfilm {

struct PatchMeshParams {
  int remesh_iterations = 3;   // isotropic remeshing passes (CASSIE native plugin: 3)
  int smooth_iterations = 10;  // curvature-flow steps (CASSIE native plugin: 10)
  // Curvature-flow time step, relative to the squared boundary diameter (the
  // implicit step solves (M - t L) x = M x, whose mass matrix scales as
  // length², so this keeps the result independent of the patch size).
  double smoothing_time = 1e-3;
  // Hole filling over the triangles of the boundary's 3D Delaunay
  // triangulation (Zou et al., the code CASSIE ran; CGAL's default) rather
  // than over all O(n³) triangles (Liepa). Both minimise the same weight
  // (worst dihedral angle, then area); the Delaunay search is the faster one
  // (measured, README.md). CGAL falls back to the exhaustive search when the
  // restricted one finds no triangulation.
  bool delaunay_hole_filling = true;
};

// CPU time (ms, calling thread) of each stage of one patch_mesh call
// (statistics only).
struct PatchMeshTimings {
  double fill_ms = 0.0;    // hole-filling triangulation + mesh construction
  double remesh_ms = 0.0;  // isotropic remeshing
  double smooth_ms = 0.0;  // curvature-flow smoothing
  double output_ms = 0.0;  // conversion to the kernel Mesh with normals
};

// `boundary`: the cycle as a closed polygon (n >= 3 points in order, the
// first not repeated at the end), every edge at most `target_edge` metres
// long (sample the boundary curves at that spacing: that is the "split long
// border edges" step done on the curves, so border vertices stay on them).
// Returns a triangle mesh whose border is exactly `boundary` (same points,
// same order: vertices 0..n-1), with per-vertex normals.
// Throws std::runtime_error when the polygon cannot be triangulated, or
// runs back along itself (a point inside another edge: no surface spans it).
// `timings`, when given, receives the wall time of each stage.
Mesh patch_mesh(const std::vector<Vec3>& boundary, double target_edge,
                const PatchMeshParams& params, PatchMeshTimings* timings = nullptr);

}  // namespace sketchlab::soapfilm
