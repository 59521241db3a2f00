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

#include "scene_actors.hpp"
#include "sketchlab/viewer/display.hpp"

namespace sketchlab::viewer {

void render_png(const std::vector<Panel>& panels, const Camera& camera, int width, int height,
                const std::filesystem::path& png, const SceneStyle& style) {
  if (panels.empty()) throw std::invalid_argument("render_png: no panels to render");
  const int n = static_cast<int>(panels.size());
  if (width < 16 * n || height < 16)
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

  // Metres per pixel at the focal point.
  const double metres_per_pixel = 2.0 * (camera.position - camera.focal_point).norm() *
                                  std::tan(0.5 * camera.view_angle_deg * std::numbers::pi / 180.0) /
                                  height;
  const double spacing = std::max(style.curve_spacing_pixels * metres_per_pixel, 1e-6);
  const double scale = height / 900.0;
  const int title_size = static_cast<int>(std::lround(style.title_font_size * scale));
  const int figures_size = static_cast<int>(std::lround(0.7 * style.title_font_size * scale));
  for (int i = 0; i < n; ++i) {
    const Panel& panel = panels[static_cast<std::size_t>(i)];
    // Integer pixel columns, so equal panels render equal pixels.
    const int x0 = i * width / n, x1 = (i + 1) * width / n;
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(static_cast<double>(x0) / width, 0.0, static_cast<double>(x1) / width,
                          1.0);
    renderer->SetBackground(style.background[0], style.background[1], style.background[2]);
    if (panel.sketch)
      add_sketch_actors(renderer, *panel.sketch, panel.raw_strokes, style, spacing);
    apply_camera(renderer, camera);
    if (!panel.title.empty())
      renderer->AddActor2D(
          make_text(panel.title, 0.025, 0.975, true, title_size, style.text_colour, false));
    if (!panel.figures.empty())
      renderer->AddActor2D(
          make_text(panel.figures, 0.025, 0.02, false, figures_size, style.text_colour, true));
    if (i > 0) renderer->AddActor2D(make_left_separator(style.separator_colour));
    window->AddRenderer(renderer);
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
