// `sketchlab view`: loads the stacks and the recording, then runs the window.
#include "sketchlab/desktop/view_app.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <stdexcept>

#include "desktop_window.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/utc_timestamp.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/viewer/display.hpp"
#include "sketchlab/viewer/viewer_stacks.hpp"

namespace sketchlab::desktop {
namespace {

std::vector<StackConfig> load_stacks(const ViewOptions& o) {
  std::vector<Override> overrides;
  for (const auto& text : o.overrides) overrides.push_back(parse_override(text));
  if (o.config.empty()) {
    StackConfig freehand;
    freehand.name = "freehand";
    freehand.corrector.plugin = "freehand";
    return {freehand};
  }
  return viewer::load_viewer_stacks(o.config, overrides);
}

}  // namespace

std::string help_text() {
  return "Keys (h toggles this help)\n"
         "left drag    draw a stroke on the draw plane (every stack)\n"
         "right drag   orbit      middle / shift+right drag  pan\n"
         "wheel        zoom       f  fit the camera to the sketches\n"
         "1 2 3 4      mode: scaffold / shape / free / automatic\n"
         "u  r         undo / redo (also ctrl+z / ctrl+y)\n"
         "d            delete the curve nearest to the cursor\n"
         "a            add a patch at the cursor\n"
         "c            toggle correction\n"
         "k            show the constraints enforced on the last stroke\n"
         "v  x y z     draw plane: facing the view / normal along x, y, z\n"
         "[  ]         move the draw plane back / forward;  g hide it\n"
         "space        play / pause the recording\n"
         "right left   one stroke forward / back (also . ,)\n"
         "pgdn pgup    ten strokes forward / back;  home end  start / end\n"
         "click bar    scrub to a stroke (timeline at the bottom)\n"
         "s            save the recording (events so far)\n"
         "j            export each stack's sketch JSON\n"
         "e            export PLY / OBJ / MeshLab project\n"
         "p            screenshot (PNG)\n"
         "q  Esc       quit";
}

int run_view(const ViewOptions& o) {
  viewer::require_display();
  const std::vector<StackConfig> configs = load_stacks(o);
  PluginHost host;
  auto dirs = PluginHost::default_search_paths();
  dirs.insert(dirs.end(), o.plugin_dirs.begin(), o.plugin_dirs.end());
  host.load_directories(dirs);
  std::vector<StackInstance> stacks;
  for (const StackConfig& c : configs) stacks.push_back(instantiate_stack(c, host));

  // The live input: the first stack input that is a pointer input (with its
  // parameters), else the first pointer input plugin loaded, with defaults.
  const std::vector<std::string> pointer_inputs = host.pointer_input_names();
  if (pointer_inputs.empty()) throw std::runtime_error("no pointer input plugin is loaded (e.g. tablet)");
  std::string pointer_name = pointer_inputs.front();
  std::map<std::string, ParamValue> pointer_params;
  for (const StackConfig& c : configs)
    if (c.input && std::find(pointer_inputs.begin(), pointer_inputs.end(), c.input->plugin) != pointer_inputs.end()) {
      pointer_name = c.input->plugin;
      pointer_params = c.input->params;
      break;
    }
  const std::shared_ptr<PointerInput> pointer = host.make_pointer_input(pointer_name, pointer_params);
  const std::shared_ptr<Input> input = pointer;

  std::optional<Recording> replay;
  if (o.recording) replay = read_recording(*o.recording);
  WindowOptions w;
  w.options = o;
  if (w.options.record.empty())
    w.options.record = "sketchlab-live-" + utc_timestamp() + ".jsonl";
  if (w.options.save.empty()) {
    auto save = w.options.record;
    save.replace_filename(save.stem().string() + "-saved.jsonl");
    w.options.save = save;
  }
  RecordingHeader live_header = input->header();
  if (replay) live_header = replay->header;
  ViewerModel model(std::move(stacks), std::move(replay), live_header, w.options.record,
                    o.overwrite);
  DesktopWindow window(model, pointer, w);
  return window.run();
}

}  // namespace sketchlab::desktop
