// `sketchlab render`: sketches (JSON written by `run`) side by side in one
// PNG, all seen from the same camera.
#include <iostream>
#include <memory>
#include <regex>
#include <sstream>

#include "commands.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/viewer/camera.hpp"
#include "sketchlab/viewer/render_png.hpp"

namespace sketchlab::cli {
namespace {

struct RenderOptions {
  std::vector<std::string> sketches;
  std::vector<std::string> titles;
  std::string output;
  std::string size = "1600x900";
  std::string view = "iso";
};

// "1600x900" -> (1600, 900).
std::pair<int, int> parse_size(const std::string& text) {
  static const std::regex pattern(R"((\d{1,5})x(\d{1,5}))");
  std::smatch m;
  if (!std::regex_match(text, m, pattern))
    throw std::runtime_error("--size " + text + ": expected WIDTHxHEIGHT, e.g. 1600x900");
  return {std::stoi(m[1]), std::stoi(m[2])};
}

// runs/default/hat/cassie/sketch.json -> "hat/cassie"; other files: their stem.
std::string default_title(const std::filesystem::path& file) {
  if (file.filename() != "sketch.json") return file.stem().string();
  const auto stack = file.parent_path();
  const auto recording = stack.parent_path();
  if (stack.filename().empty()) return file.stem().string();
  if (recording.filename().empty()) return stack.filename().string();
  return recording.filename().string() + "/" + stack.filename().string();
}

std::string figures_of(const Sketch& sketch) {
  std::ostringstream out;
  out << sketch.network.curves().size() << " curves, " << sketch.network.nodes().size()
      << " nodes, " << sketch.network.patches().size() << " patches";
  return out.str();
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand(
      "render",
      "Render sketches (JSON written by `run`) side by side into a PNG, same camera for all "
      "(needs an X display: run under xvfb-run -a)");
  cmd->add_option("sketches", o->sketches, "sketch.json files, one panel each")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->output, "PNG to write")->required();
  cmd->add_option("--size", o->size, "Picture size WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  cmd->add_option("--view", o->view, "Camera direction")
      ->check(CLI::IsMember({"iso", "front", "top", "side"}))
      ->capture_default_str();
  cmd->add_option("--title", o->titles,
                  "Panel titles in order (default: <recording>/<stack> from the path)");
  cmd->callback([o, &exit_code] {
    const auto [width, height] = parse_size(o->size);
    if (!o->titles.empty() && o->titles.size() != o->sketches.size())
      throw std::runtime_error("--title given " + std::to_string(o->titles.size()) +
                               " times for " + std::to_string(o->sketches.size()) + " sketches");
    std::vector<Sketch> sketches;
    sketches.reserve(o->sketches.size());
    for (const auto& file : o->sketches) sketches.push_back(read_sketch_json(file));

    std::vector<const Sketch*> pointers;
    std::vector<viewer::Panel> panels;
    for (std::size_t i = 0; i < sketches.size(); ++i) {
      pointers.push_back(&sketches[i]);
      viewer::Panel panel;
      panel.title = o->titles.empty() ? default_title(o->sketches[i]) : o->titles[i];
      panel.sketch = &sketches[i];
      panel.figures = figures_of(sketches[i]);
      panels.push_back(std::move(panel));
    }
    const double panel_aspect =
        static_cast<double>(width) / static_cast<double>(panels.size()) / height;
    const viewer::Camera camera =
        viewer::fit_camera(pointers, viewer::view_direction_from_string(o->view), panel_aspect);
    viewer::render_png(panels, camera, width, height, o->output);
    std::cout << o->output << ": " << panels.size() << " panel(s), " << width << "x" << height
              << ", view " << o->view << "\n";
    exit_code = 0;
  });
}

}  // namespace sketchlab::cli
