#pragma once
// Curves and patches in formats MeshLab opens. Curves become polylines
// sampled every `spacing` metres along their arclength; patches their meshes.
#include <string>

#include "sketchlab/network.hpp"

namespace sketchlab {

// Wavefront OBJ: `v` vertices, `l` polylines (one per curve, grouped as
// `o curve_<id>`), `f` faces of patches (`o patch_<id>`).
std::string network_to_obj(const Network& network, double spacing = 0.005);

// ASCII PLY with vertex, edge (curve polylines) and face (patch) elements.
std::string network_to_ply(const Network& network, double spacing = 0.005);

}  // namespace sketchlab
