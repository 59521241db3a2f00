#pragma once
// Offscreen rendering of sketches to PNG (reports, `sketchlab render`,
// tests): one viewport per panel, side by side, all with the same camera.
// Needs an X display (Debian's VTK has no OSMesa/EGL build): run under
// xvfb-run or with DISPLAY pointing at an Xvfb.
#include <filesystem>
#include <string>
#include <vector>

#include "sketchlab/sketch.hpp"
#include "sketchlab/viewer/camera.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::viewer {

struct Panel {
  std::string title;
  const Sketch* sketch = nullptr;  // null: an empty panel (title and figures only)
  // Raw strokes drawn faint (those with 3D samples; 2D pixel strokes are
  // skipped). Null: the sketch's own strokes (sketch->strokes).
  const std::vector<Stroke>* raw_strokes = nullptr;
  // Figures shown at the bottom left of the panel; lines split on '\n'.
  std::string figures;
};

// Renders the panels into one width x height picture and writes it as RGB
// PNG: in one row (columns 0: panel i occupies columns [i*width/n,
// (i+1)*width/n)), or in rows of `columns` panels, filled from the top left.
// The style may colour curves by deviation (with a colour bar in the last
// panel) and add a scale bar per panel (scene_style.hpp).
// Throws std::invalid_argument for no panels, negative columns or a size
// below 16 pixels per panel, std::runtime_error when there is no usable X
// display or the file cannot be written.
void render_png(const std::vector<Panel>& panels, const Camera& camera, int width, int height,
                const std::filesystem::path& png, const SceneStyle& style = {}, int columns = 0);

}  // namespace sketchlab::viewer
