#pragma once
// Internal to viewers/: what makes an offscreen picture readable on its
// own (render_png): curves coloured by their deviation from the input stroke
// with a colour bar, and a scale bar.
#include <vector>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkProp.h>
#include <vtkSmartPointer.h>

#include "sketchlab/sketch.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::viewer {

// Per curve of `sketch`, its polyline every `spacing` metres and, per point,
// the distance (m) to the polyline of the curve's source stroke (3D samples;
// `raw_strokes` null: the sketch's strokes); NaN where the source stroke
// is unknown or 2D (drawn in the style's curve colour).
struct DeviationLines {
  std::vector<std::vector<Vec3>> polylines;
  std::vector<std::vector<double>> distances;
};
DeviationLines curve_deviations(const Sketch& sketch, const std::vector<Stroke>* raw_strokes, double spacing);

// The curves as one actor coloured by deviation on [0, max_m] (a perceptually
// uniform sequential map, viridis; above max_m: its last colour), drawn
// as wide as the style's shape curves.
vtkSmartPointer<vtkActor> deviation_actor(const DeviationLines& lines, double max_m, const SceneStyle& style);
// Its colour bar, in millimetres, at the viewport's right edge.
vtkSmartPointer<vtkProp> deviation_colour_bar(double max_m, int font_size, const SceneStyle& style);

// A horizontal bar of a round length (1, 2 or 5 × 10^k m) about a fifth of
// the viewport's width at `metres_per_pixel`, labelled ("5 cm"), at the
// bottom right of a viewport `viewport_width` pixels wide: two 2D props.
std::vector<vtkSmartPointer<vtkProp>> scale_bar(double metres_per_pixel, int viewport_width, int font_size,
                                                const SceneStyle& style);

}  // namespace sketchlab::viewer
