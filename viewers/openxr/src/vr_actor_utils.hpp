#pragma once
// Small VTK helpers the VR scene's parts share (one way to make an actor,
// place it by a pose, draw a polyline or a label).
#include <string>
#include <vector>

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include "sketchlab/plugin/controller_input.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::vr {

// An actor drawing `data` (or the output of `source`) through a new mapper.
vtkSmartPointer<vtkActor> actor_for(vtkPolyData* data);
vtkSmartPointer<vtkActor> actor_for(vtkPolyDataAlgorithm* source);
// Replaces the polydata an actor made by actor_for(vtkPolyData*) draws.
void set_data(vtkActor* actor, vtkPolyData* data);
void set_colour(vtkActor* actor, const viewer::Rgb& colour);

// Homogeneous matrices of a workspace placement (x_stage = s R w + t) and
// of a rigid pose (hand frame -> stage).
vtkSmartPointer<vtkMatrix4x4> placement_matrix(const StagePlacement& placement);
vtkSmartPointer<vtkMatrix4x4> pose_matrix(const Pose& pose);

// One polyline cell through `points` (empty polydata for fewer than two).
vtkSmartPointer<vtkPolyData> polyline_data(const std::vector<Vec3>& points);

// `text` as flat polygons (vtkVectorText) in the x-y plane of a local frame:
// cap height `height` metres, its left end of the baseline at `origin`, or
// centred on `origin` horizontally when `centred`.
vtkSmartPointer<vtkPolyData> text_data(const std::string& text, double height, const Vec3& origin,
                                       bool centred = false);

}  // namespace sketchlab::vr
