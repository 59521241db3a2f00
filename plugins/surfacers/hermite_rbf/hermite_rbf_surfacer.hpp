#pragma once
// The surfacer as free functions: curves -> normals -> §6 constraints ->
// Hermite RBF -> narrow-band grid -> zero-set mesh.
#include <map>
#include <string>

#include "hermite_constraints.hpp"
#include "hermite_interpolant.hpp"
#include "hermite_rbf_params.hpp"
#include "sketchlab/mesh.hpp"
#include "sketchlab/plugin/surfacer.hpp"

namespace sketchlab::hermite_rbf {

struct SurfaceResult {
  Mesh mesh;                     // closed, oriented outwards
  HermiteConstraints constraints;
  SolveReport solve;
  std::map<std::string, double> stats;  // see README ("Statistics")
};

// The surface through `constraints`; `curve_points` (m) decide which parts
// are near a curve (trimming, far_area_fraction). Throws
// std::invalid_argument on degenerate input or an empty zero set.
SurfaceResult surface_from_constraints(const HermiteConstraints& constraints, const std::vector<Vec3>& curve_points,
                                       const HermiteRbfParams& params);

// The whole pipeline on a network's curves.
SurfaceResult surface_from_network(const Network& network, const HermiteRbfParams& params);

// One patch holding the surface, replacing every existing patch; on failure
// an update with `error` set (and no edit).
SurfaceUpdate recompute_surface(const Sketch& sketch, const HermiteRbfParams& params);

// add_patch recomputes; delete_patch removes the surface patch nearest to the point.
SurfaceUpdate surface_command(const Sketch& sketch, const SurfaceCommand& command, const HermiteRbfParams& params);

}  // namespace sketchlab::hermite_rbf
