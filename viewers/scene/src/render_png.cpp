// Offscreen rendering to PNG: one renderer (viewport) per panel, side by
// side, each with the same camera.
#include "sketchlab/viewer/render_png.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include "picture_annotations.hpp"
#include "scene_actors.hpp"
#include "sketchlab/viewer/display.hpp"

namespace sketchlab::viewer {

void render_png(const std::vector<Panel>& panels, const Camera& camera, int width, int height,
                const std::filesystem::path& png, const SceneStyle& style, int columns) {
  if (panels.empty()) throw std::invalid_argument("render_png: no panels to render");
  const int n = static_cast<int>(panels.size());
  if (columns < 0) throw std::invalid_argument("render_png: columns must be >= 0 (0: one row)");
  const int cols = columns == 0 ? n : std::min(columns, n);
  const int rows = (n + cols - 1) / cols;
  if (width < 16 * cols || height < 16 * rows)
    throw std::invalid_argument("render_png: picture " + std::to_string(width) + "x" +
                                std::to_string(height) + " is too small for " +
                                std::to_string(n) + " panel(s) (16 pixels each at least)");
  if (width > 16384 || height > 16384)
    throw std::invalid_argument("render_png: picture larger than 16384 pixels on a side");
  if (!camera.position.allFinite() || !camera.focal_point.allFinite() ||
      !camera.view_up.allFinite() || (camera.position - camera.focal_point).norm() <= 0.0 ||
      camera.view_up.norm() <= 0.0 || !(camera.view_angle_deg > 0.0 && camera.view_angle_deg < 180.0))
    throw std::invalid_argument("render_png: camera is degenerate or not finite");
  const auto parent = png.parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent))
    throw std::runtime_error(png.string() + ": directory " + parent.string() + " does not exist");
  // Declared before the window so it outlives it.
  const DisplayConnection display;

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(std::max(style.multisamples, 0));
  window->SetSize(width, height);

  // Metres per pixel at the focal point (VTK's view angle is vertical: per
  // panel height).
  const int panel_height = height / rows;
  const double metres_per_pixel = 2.0 * (camera.position - camera.focal_point).norm() *
                                  std::tan(0.5 * camera.view_angle_deg * std::numbers::pi / 180.0) /
                                  panel_height;
  const double spacing = std::max(style.curve_spacing_pixels * metres_per_pixel, 1e-6);
  const double scale = panel_height / 900.0;
  const int title_size = static_cast<int>(std::lround(style.title_font_size * scale));
  const int figures_size = static_cast<int>(std::lround(0.7 * style.title_font_size * scale));
  std::vector<DeviationLines> deviations(panels.size());
  double deviation_max = style.deviation_max_m;
  if (style.colour_by_deviation) {
    std::vector<double> all;
    for (std::size_t i = 0; i < panels.size(); ++i)
      if (panels[i].sketch) {
        deviations[i] = curve_deviations(*panels[i].sketch, panels[i].raw_strokes, spacing);
        for (const auto& d : deviations[i].distances)
          for (double v : d)
            if (std::isfinite(v)) all.push_back(v);
      }
    if (!(deviation_max > 0.0) && !all.empty()) {
      const auto k = static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(all.size() - 1));
      std::nth_element(all.begin(), all.begin() + k, all.end());
      deviation_max = all[static_cast<std::size_t>(k)];
    }
    if (!(deviation_max > 0.0) || !std::isfinite(deviation_max)) deviation_max = 1e-3;
  }
  for (int i = 0; i < n; ++i) {
    const Panel& panel = panels[static_cast<std::size_t>(i)];
    // Integer pixel columns and rows, so equal panels render equal pixels;
    // row 0 at the top.
    const int c = i % cols, r = i / cols;
    const int x0 = c * width / cols, x1 = (c + 1) * width / cols;
    const int y0 = height - (r + 1) * height / rows, y1 = height - r * height / rows;
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(static_cast<double>(x0) / width, static_cast<double>(y0) / height,
                          static_cast<double>(x1) / width, static_cast<double>(y1) / height);
    renderer->SetBackground(style.background[0], style.background[1], style.background[2]);
    if (panel.sketch) {
      const SceneActors actors = add_sketch_actors(renderer, *panel.sketch, panel.raw_strokes, style, spacing);
      if (style.colour_by_deviation) {
        // The deviation colours replace the layer colours of the curves.
        for (const auto& a : {actors.scaffold_curves, actors.shape_curves, actors.other_curves})
          if (a) a->VisibilityOff();
        if (!deviations[static_cast<std::size_t>(i)].polylines.empty())
          renderer->AddActor(deviation_actor(deviations[static_cast<std::size_t>(i)], deviation_max, style));
      }
    }
    if (style.colour_by_deviation && i == n - 1)
      renderer->AddViewProp(deviation_colour_bar(deviation_max, figures_size, style));
    if (style.show_scale_bar)
      for (const auto& prop : scale_bar(metres_per_pixel, x1 - x0, figures_size, style)) renderer->AddViewProp(prop);
    apply_camera(renderer, camera);
    if (!panel.title.empty())
      renderer->AddActor2D(
          make_text(panel.title, 0.025, 0.975, true, title_size, style.text_colour, false));
    if (!panel.figures.empty())
      renderer->AddActor2D(
          make_text(panel.figures, 0.025, 0.02, false, figures_size, style.text_colour, true));
    if (c > 0) renderer->AddActor2D(make_left_separator(style.separator_colour));
    window->AddRenderer(renderer);
  }
  // The cells of the last row without a panel: background, not undefined.
  for (int i = n; i < rows * cols; ++i) {
    const int c = i % cols, r = i / cols;
    vtkNew<vtkRenderer> empty;
    empty->SetViewport(static_cast<double>(c * width / cols) / width,
                       static_cast<double>(height - (r + 1) * height / rows) / height,
                       static_cast<double>((c + 1) * width / cols) / width,
                       static_cast<double>(height - r * height / rows) / height);
    empty->SetBackground(style.background[0], style.background[1], style.background[2]);
    if (c > 0) empty->AddActor2D(make_left_separator(style.separator_colour));
    window->AddRenderer(empty);
  }
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(png.string().c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::is_regular_file(png))
    throw std::runtime_error(png.string() + ": cannot write the PNG");
}

}  // namespace sketchlab::viewer
