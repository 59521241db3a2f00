#pragma once
// Topology checks and measures of triangle meshes: closedness, manifoldness,
// components, volume.
#include <vector>

#include "sketchlab/mesh.hpp"

namespace sketchlab::hermite_rbf {

struct MeshTopology {
  int boundary_edges = 0;       // edges with one face
  int nonmanifold_edges = 0;    // edges with more than two faces
  int inconsistent_edges = 0;   // two faces traversing the edge the same way
  int nonmanifold_vertices = 0; // vertices whose faces form more than one fan
  int components = 0;           // vertex-connected pieces
  bool watertight_manifold() const {
    return boundary_edges == 0 && nonmanifold_edges == 0 && inconsistent_edges == 0 && nonmanifold_vertices == 0;
  }
};

MeshTopology mesh_topology(const Mesh& mesh);

// Component index of every vertex (connected through faces), and their count.
std::vector<int> vertex_components(const Mesh& mesh, int& count);

// Keeps the faces whose vertices are in components marked true, and the
// vertices they use (normals follow).
Mesh keep_components(const Mesh& mesh, const std::vector<int>& component, const std::vector<bool>& keep);

// Volume enclosed (m³, positive when faces are oriented outwards) and area (m²).
double signed_volume(const Mesh& mesh);
double surface_area(const Mesh& mesh);

}  // namespace sketchlab::hermite_rbf
