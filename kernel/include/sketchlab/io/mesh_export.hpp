#pragma once
// Curves and patches in formats MeshLab opens. Curves become polylines
// sampled every `spacing` metres along their arclength, at most
// kMaxPointsPerExportedCurve points each (a longer curve, such as one
// stretched kilometres by a tracking-glitch sample, is sampled more
// coarsely rather than written as millions of points); patches their meshes.
#include <string>
#include <vector>

#include "sketchlab/mesh.hpp"

#include "sketchlab/network.hpp"

namespace sketchlab {

// 50 m of curve at the default 5 mm spacing.
inline constexpr int kMaxPointsPerExportedCurve = 10001;

// Wavefront OBJ: `v` vertices, `l` polylines (one per curve, grouped as
// `o curve_<id>`), `f` faces of patches (`o patch_<id>`).
std::string network_to_obj(const Network& network, double spacing = 0.005);

// ASCII PLY with vertex, edge (curve polylines) and face (patch) elements.
std::string network_to_ply(const Network& network, double spacing = 0.005);

// Single-layer PLY files (one MeshLab layer each).
std::string polylines_to_ply(const std::vector<std::vector<Vec3>>& polylines);  // vertices + edges
std::string points_to_ply(const std::vector<Vec3>& points);                     // vertices only
std::string meshes_to_ply(const std::vector<const Mesh*>& meshes);              // vertices + faces

// Curves of a network as polylines sampled every `spacing` metres (at most
// kMaxPointsPerExportedCurve points each).
std::vector<std::vector<Vec3>> curve_polylines(const Network& network, double spacing = 0.005);

struct MeshLabLayer {
  std::string label;
  std::string filename;  // relative to the project file
};
// A MeshLab project (.mlp) opening every layer at once, identity transforms.
std::string meshlab_project(const std::vector<MeshLabLayer>& layers);

}  // namespace sketchlab
