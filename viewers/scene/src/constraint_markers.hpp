#pragma once
// Internal to viewers/: markers for the constraints a corrector enforced on a
// stroke (shown on demand by the interactive viewers).
#include <vector>

#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include "sketchlab/constraint.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::viewer {

// Marker classes, one actor each (null when there is nothing of the class).
struct ConstraintMarkers {
  vtkSmartPointer<vtkActor> coincidence;  // coincident point, on curve, intersection, grid, closure: green dots
  vtkSmartPointer<vtkActor> right_angles; // perpendicular: magenta corner ticks
  vtkSmartPointer<vtkActor> tangents;     // tangent, parallel: cyan segments along the curve
  vtkSmartPointer<vtkActor> planes;       // planar, axis plane, mirror, symmetry: translucent squares
};

// Where a constraint is located: the point of each curve (or node) it
// references that exists in `sketch`, else its target for point-valued kinds.
std::vector<Vec3> constraint_anchors(const Constraint& constraint, const Sketch& sketch);

// Markers for the enforced constraints in `constraints`, sized `size` metres;
// with `rejected`, for the candidates the corrector considered and did not
// enforce instead (CASSIE app, item 21: "rejected" are all but the applied
// ones), every class in one red so they never read as applied.
ConstraintMarkers make_constraint_markers(const std::vector<Constraint>& constraints,
                                          const Sketch& sketch, double size, bool rejected = false);

}  // namespace sketchlab::viewer
