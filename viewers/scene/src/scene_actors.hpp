#pragma once
// Internal to viewers/: the VTK actors of a sketch, shared by the offscreen
// renderer, the desktop viewer (#7) and the VR viewer (#11). Public headers
// stay VTK-free.
#include <vector>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include "sketchlab/sketch.hpp"
#include "sketchlab/viewer/camera.hpp"
#include "sketchlab/viewer/scene_style.hpp"
#include "sketch_geometry.hpp"

namespace sketchlab::viewer {

// One actor per drawing class, so a viewer can toggle or restyle a class
// (null when the sketch has nothing of that class or the style hides it).
struct SceneActors {
  vtkSmartPointer<vtkActor> raw_strokes;
  vtkSmartPointer<vtkActor> scaffold_curves;
  vtkSmartPointer<vtkActor> shape_curves;
  vtkSmartPointer<vtkActor> other_curves;  // free, guide, automatic
  vtkSmartPointer<vtkActor> nodes;
  vtkSmartPointer<vtkActor> patches;
};

// Builds the actors of `sketch` and adds them to `renderer`. Curves are
// polylines sampled every `spacing` metres (> 0). `raw_strokes` null means
// the sketch's own strokes; strokes with pixel samples (2D input) are skipped.
SceneActors add_sketch_actors(vtkRenderer* renderer, const Sketch& sketch,
                              const std::vector<Stroke>* raw_strokes, const SceneStyle& style,
                              double spacing);

// VTK polydata of `data` (the arrays copied). VTK objects are made and
// dropped on the render thread only (see sketch_geometry.hpp).
vtkSmartPointer<vtkPolyData> to_polydata(const DrawData& data);

// An actor drawing `poly` (not null) as `style` draws `cls`: lines flat in
// their colour and width, nodes as dots in front of the curves, patches
// translucent.
vtkSmartPointer<vtkActor> make_sketch_actor(DrawClass cls, vtkPolyData* poly, const SceneStyle& style);
// Whether `style` draws `cls` at all (raw strokes, nodes, patches can be off).
bool drawn(DrawClass cls, const SceneStyle& style);

// Curve polyline spacing for a scene of these bounds (style fraction of the
// diagonal, with a floor for degenerate scenes).
double curve_spacing(const Box3& bounds, const SceneStyle& style);

// Sets the renderer's active camera to `camera` and resets the clipping
// range to what the renderer currently shows.
void apply_camera(vtkRenderer* renderer, const Camera& camera);

// Text in the viewport's normalized coordinates (x, y in [0, 1]); anchored at
// its top-left corner when `top` is true, else bottom-left.
vtkSmartPointer<vtkTextActor> make_text(const std::string& text, double x, double y, bool top,
                                        int font_size, const Rgb& colour, bool monospace);

// A vertical line along the viewport's left edge.
vtkSmartPointer<vtkActor2D> make_left_separator(const Rgb& colour);

}  // namespace sketchlab::viewer
