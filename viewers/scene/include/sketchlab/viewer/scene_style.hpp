#pragma once
// How a sketch is drawn (DESIGN.md "Viewers"): raw strokes faint, corrected
// curves dark (scaffold thin, shape thick, as in ScaffoldSketch), nodes as
// small dots, patches translucent. Shared by the offscreen renderer and the
// interactive viewers. Widths and sizes are pixels; colours are linear RGB in
// [0, 1].
#include <array>

namespace sketchlab::viewer {

using Rgb = std::array<double, 3>;

struct SceneStyle {
  Rgb background{1.0, 1.0, 1.0};

  bool show_raw_strokes = true;
  Rgb raw_stroke_colour{0.72, 0.72, 0.72};
  double raw_stroke_width = 1.5;

  Rgb scaffold_colour{0.30, 0.33, 0.40};
  double scaffold_width = 1.5;
  Rgb shape_colour{0.05, 0.05, 0.08};
  double shape_width = 4.0;
  // Free, guide and automatic curves.
  Rgb curve_colour{0.10, 0.10, 0.14};
  double curve_width = 3.0;
  // Polyline spacing along curves: the offscreen renderer uses pixels at the
  // focal distance (smooth at any zoom; much finer chords make VTK's wide
  // lines break up), viewers whose camera moves use a fraction of the
  // scene's bounding-box diagonal.
  double curve_spacing_pixels = 3.0;
  double curve_spacing_fraction = 0.002;

  bool show_nodes = true;
  Rgb node_colour{0.85, 0.33, 0.10};
  double node_size = 8.0;

  bool show_patches = true;
  Rgb patch_colour{0.35, 0.58, 0.90};
  double patch_opacity = 0.35;

  Rgb text_colour{0.08, 0.08, 0.08};
  // Title font size in pixels at an image height of 900 (scaled with it);
  // the figures text is 70 % of it.
  int title_font_size = 26;
  // Thin line between side-by-side panels.
  Rgb separator_colour{0.80, 0.80, 0.80};

  // Offscreen pictures (render_png) only. Colour curves by their distance
  // to their input stroke (viridis, with a colour bar in mm) instead of by
  // layer; the scale's top is deviation_max_m, or when 0 the 95th
  // percentile over every panel's curves (one scale for the whole picture).
  bool colour_by_deviation = false;
  double deviation_max_m = 0.0;
  // A bar of round length (1, 2, 5 × 10^k m) at the focal distance, per panel.
  bool show_scale_bar = false;

  // Antialiasing samples (0 turns multisampling off: exact, reproducible
  // pixels, which the tests use).
  int multisamples = 8;
};

}  // namespace sketchlab::viewer
