#pragma once
// The surfacer as free functions: curves -> normals -> §6 constraints ->
// Hermite RBF (partition of unity of local fits, or one dense system) ->
// narrow-band grid -> zero-set mesh.
#include <map>
#include <memory>
#include <string>

#include "grid_evaluation.hpp"
#include "hermite_constraints.hpp"
#include "hermite_interpolant.hpp"
#include "hermite_rbf_params.hpp"
#include "partition_of_unity.hpp"
#include "sketchlab/mesh.hpp"
#include "sketchlab/plugin/surfacer.hpp"

namespace sketchlab::hermite_rbf {

struct SurfaceResult {
  Mesh mesh;                     // oriented outwards
  HermiteConstraints constraints;  // canonical order
  SolveReport solve;
  std::map<std::string, double> stats;  // see README ("Statistics")
};

// What one surface leaves for the next of the same, changing sketch: the
// partition-of-unity model (unchanged cells keep their fit) and the exact grid
// values (unchanged regions are not evaluated again). The surface built with a
// state equals the one built without.
struct SurfaceState {
  std::shared_ptr<const PartitionOfUnity> model;
  GridCache grid;
};

// The surface through `constraints`; `curve_points` (m) decide which parts
// are near a curve (trimming, far_area_fraction). Throws
// std::invalid_argument on degenerate input or an empty zero set.
SurfaceResult surface_from_constraints(const HermiteConstraints& constraints, const std::vector<Vec3>& curve_points,
                                       const HermiteRbfParams& params, SurfaceState* state = nullptr);

// The whole pipeline on a network's curves.
SurfaceResult surface_from_network(const Network& network, const HermiteRbfParams& params,
                                   SurfaceState* state = nullptr);

// One patch holding the surface, replacing every existing patch; on failure
// an update with `error` set (and no edit).
SurfaceUpdate recompute_surface(const Sketch& sketch, const HermiteRbfParams& params, SurfaceState* state = nullptr);

// add_patch recomputes; delete_patch removes the surface patch nearest to the point.
SurfaceUpdate surface_command(const Sketch& sketch, const SurfaceCommand& command, const HermiteRbfParams& params,
                              SurfaceState* state = nullptr);

}  // namespace sketchlab::hermite_rbf
