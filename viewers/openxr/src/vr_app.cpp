#include "sketchlab/vr/vr_app.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <iostream>
#include <thread>

#include "correction_worker.hpp"
#include "eye_renderer.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/lab/stop_signals.hpp"
#include "sketchlab/lab/utc_timestamp.hpp"
#include "sketchlab/viewer/display.hpp"
#include "sketchlab/viewer/viewer_stacks.hpp"
#include "vr_scene.hpp"
#include "xr_render_session.hpp"

namespace sketchlab::vr {
namespace {

std::filesystem::path default_recording() { return "vr-" + utc_timestamp() + ".jsonl"; }

// The controllers: the stack's input when it is a controller input plugin
// (with its parameters), else the first controller input loaded, with
// defaults. Its name goes to `name`.
std::shared_ptr<ControllerInput> controller_input(const StackConfig& stack, const PluginHost& host,
                                                  std::string& name, std::ostream& err) {
  const std::vector<std::string> names = host.controller_input_names();
  if (names.empty())
    throw std::runtime_error("no controller input plugin is loaded (the openxr input; built when libopenxr-dev is "
                             "installed)");
  name = names.front();
  std::map<std::string, ParamValue> given;
  if (stack.input) {
    if (std::find(names.begin(), names.end(), stack.input->plugin) == names.end()) {
      err << "sketchlab vr: " << stack.input->location.to_string() << ": input '" << stack.input->plugin
          << "' ignored: VR sessions read the controllers (the " << name << " input)\n";
    } else {
      name = stack.input->plugin;
      given = stack.input->params;
    }
  }
  try {
    return host.make_controller_input(name, given);
  } catch (const ParamError& e) {
    if (stack.input && !given.empty()) rethrow_param_error(e, *stack.input);
    throw ConfigError(e.what());
  } catch (const PluginError& e) {
    throw ConfigError((stack.input ? stack.input->location.to_string() + ": " : std::string()) + e.what());
  }
}

// A ControllerInput reports failures through error(); they end the command
// as an exception would.
void require_ok(const ControllerInput& input, const std::string& name) {
  if (const std::string e = input.error(); !e.empty()) throw std::runtime_error("input '" + name + "': " + e);
}

// The session is destroyed while its GL context is current (the runtime
// frees the swapchain textures in it).
struct CurrentOnExit {
  std::unique_ptr<EyeRenderer>& eyes;
  ~CurrentOnExit() {
    if (eyes) eyes->make_current();
  }
};

}  // namespace

int run_vr(const VrOptions& options, const PluginHost& host, std::ostream& out, std::ostream& err,
           VrStats* stats) {
  std::vector<Override> overrides;
  for (const auto& o : options.overrides) overrides.push_back(parse_override(o));
  // An experiment's stacks are switched and compared from the hand menu.
  const std::vector<StackConfig> configs = viewer::load_viewer_stacks(options.config, overrides);
  // The controllers are read as the first stack's input says.
  std::string input_name;
  std::shared_ptr<ControllerInput> made_input = controller_input(configs.front(), host, input_name, err);
  std::vector<StackInstance> instances;
  std::vector<std::string> names;
  for (const StackConfig& stack : configs) {
    instances.push_back(instantiate_stack(stack, host));
    names.push_back(stack.name);
    if (instances.back().corrector->stroke_space() == StrokeSpace::pixels)
      err << "sketchlab vr: warning: " << stack.corrector.location.to_string() << ": corrector '"
          << stack.corrector.plugin << "' corrects 2D (tablet) strokes only and will refuse every VR "
          << "stroke; the strokes are still recorded\n";
  }
  if (!(options.grid_spacing >= 0.0 && options.grid_spacing < 100.0))
    throw std::invalid_argument("--grid: spacing must be in [0, 100) m, got " + std::to_string(options.grid_spacing));
  const std::filesystem::path recording = options.recording.empty() ? default_recording() : options.recording;
  if (!options.overwrite && std::filesystem::exists(recording))
    throw std::runtime_error(recording.string() + ": already exists; pass --overwrite to replace it");

  viewer::require_display();
  const viewer::DisplayConnection display;
  std::unique_ptr<EyeRenderer> eyes;
  XrRenderSession xr;
  const CurrentOnExit current{eyes};
  eyes = std::make_unique<EyeRenderer>(xr.eye_width(), xr.eye_height());
  // The input's actions live on the instance and session: declared after
  // `xr`, it is destroyed before them.
  const std::shared_ptr<ControllerInput> input = std::move(made_input);
  input->create_actions(xr_handle_value(xr.instance()));
  require_ok(*input, input_name);
  xr.start(eyes->glx_handles());

  RecordingHeader header;
  header.units = "m";
  if (options.grid_spacing > 0.0) {
    header.workspace.grid_enabled = true;
    header.workspace.grid_spacing = options.grid_spacing;
  }
  header.workspace.mirror_enabled = options.mirror;
  header.source = {{"input", input_name}, {"runtime", xr.runtime_name()}, {"stack", names.front()},
                   {"config", std::filesystem::absolute(options.config).string()}};
  input->attach({xr_handle_value(xr.session()), xr_handle_value(xr.base_space()), xr_handle_value(xr.view_space())},
                header.workspace, names.size());
  require_ok(*input, input_name);
  auto live = std::make_unique<LiveSession>(header, std::move(instances), recording, options.overwrite);
  CorrectionWorker worker(std::move(live), geometry_preparer(vr_style()));
  VrScene scene(eyes->renderer(), vr_style(), names);
  std::size_t shown_stack = 0;
  bool comparing = false;

  std::string stack_list;
  for (const auto& n : names) stack_list += (stack_list.empty() ? "'" : ", '") + n + "'";
  out << "sketchlab vr: drawing with stack" << (names.size() > 1 ? "s " : " ") << stack_list << " on OpenXR runtime '"
      << xr.runtime_name()
      << "', recording to " << recording.string() << " (Ctrl-C ends the session)\n"
      << std::flush;
  // Ctrl-C or SIGTERM asks the runtime to end the session, so the loop
  // leaves through the normal STOPPING -> EXITING path, the recording is
  // closed and the figures printed.
  const StopSignals stop;
  XrTime start = 0;
  double seconds = 0.0;
  bool lost = false;
  std::vector<double> frame_ms;  // render-thread time per frame (input, scene, both eyes)
  for (;;) {
    if (StopSignals::stop_requested()) {
      if (!xr.running()) break;
      xr.request_exit();
    }
    if (!xr.poll(lost)) break;
    if (!xr.running()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      continue;
    }
    const auto frame_start = std::chrono::steady_clock::now();
    xr.frame(
        [&](XrTime time) {
          if (start == 0) start = time;
          seconds = static_cast<double>(time - start) * 1e-9;
          input->read_frame(time, seconds, xr.focused());
          require_ok(*input, input_name);
          for (NextEvent e = input->next(); e; e = input->next()) {
            if (const auto* stroke = std::get_if<StrokeEvent>(&e->payload)) scene.stroke_submitted(stroke->stroke);
            worker.submit(std::move(*e));
          }
          const ControllerState state = input->state();
          const ControllerView& view = state.view;
          if (view.stack != shown_stack || view.compare != comparing) {
            shown_stack = view.stack;
            comparing = view.compare;
            out << "sketchlab vr: showing stack '" << names[shown_stack] << "'"
                << (comparing ? " with '" + names[(shown_stack + 1) % names.size()] + "' overlaid" : std::string())
                << "\n"
                << std::flush;
          }
          // The latest finished correction; a slow stack shows it late.
          scene.show(*worker.latest(), view, seconds);
          scene.update(state, seconds);
        },
        [&](int, const EyeView& view, std::uint32_t texture) {
          eyes->render(view.position, view.orientation, view.fov, texture);
        });
    frame_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frame_start).count());
  }
  // What was being drawn when the session ended is kept.
  input->close();
  for (NextEvent e = input->next(); e; e = input->next()) worker.submit(std::move(*e));
  const auto final_sketch = worker.finish();
  for (const auto& p : worker.problems()) err << "sketchlab vr: " << p << "\n";
  if (!options.sketch.empty()) {
    std::ofstream file(options.sketch);
    file << sketch_to_json(final_sketch->stacks.front().sketch);
    if (!file) throw std::runtime_error(options.sketch.string() + ": cannot write the sketch");
  }
  out << "sketchlab vr: " << worker.live().events_recorded() << " events recorded in " << recording.string()
      << "\n";
  if (!frame_ms.empty()) {
    // Includes the runtime's xrWaitFrame (vsync on a headset).
    std::vector<double> sorted = frame_ms;
    std::sort(sorted.begin(), sorted.end());
    double sum = 0.0;
    for (double v : sorted) sum += v;
    VrStats figures;
    figures.frames = sorted.size();
    figures.eye_width = eyes->width();
    figures.eye_height = eyes->height();
    figures.frame_mean_ms = sum / static_cast<double>(sorted.size());
    figures.frame_p95_ms = sorted[std::min(sorted.size() - 1, sorted.size() * 95 / 100)];
    figures.frame_max_ms = sorted.back();
    figures.events = worker.live().events_recorded();
    out << "sketchlab vr: " << figures.frames << " frames, " << figures.eye_width << "x" << figures.eye_height
        << " per eye; frame time mean " << figures.frame_mean_ms << " ms, p95 " << figures.frame_p95_ms
        << " ms, max " << figures.frame_max_ms << " ms\n";
    if (stats) *stats = figures;
  }
  if (lost) {
    err << "sketchlab vr: the OpenXR runtime lost the session (headset disconnected or runtime stopped); "
           "everything drawn is in "
        << recording.string() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace sketchlab::vr
