#pragma once
// Mesh <-> vtkPolyData (triangles), for the VTK filters the plugin uses
// (flying edges, clipping). Include from .cpp files only.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "sketchlab/mesh.hpp"

namespace sketchlab::hermite_rbf {

// Points and triangles (polygons with more corners fanned; degenerate
// triangles with a repeated vertex dropped). No normals.
Mesh mesh_from_polydata(vtkPolyData* polydata);

vtkSmartPointer<vtkPolyData> polydata_from_mesh(const Mesh& mesh);

// Area-weighted vertex normals along the faces' orientation.
void compute_vertex_normals(Mesh& mesh);

}  // namespace sketchlab::hermite_rbf
