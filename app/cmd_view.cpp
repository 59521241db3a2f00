// `sketchlab view`: the interactive desktop viewer (one viewport per stack,
// replay controls, live drawing with a tablet or mouse).
#include <iostream>
#include <memory>
#include <regex>

#include "commands.hpp"
#include "sketchlab/desktop/view_app.hpp"

namespace sketchlab::cli {

void add_view_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<desktop::ViewOptions>();
  auto positional = std::make_shared<std::vector<std::string>>();
  auto size = std::make_shared<std::string>("1280x720");
  auto at = std::make_shared<int>(-1);
  auto* cmd = app.add_subcommand(
      "view",
      "Interactive viewer: one viewport per stack of CONFIG, replay RECORDING (play, step, "
      "scrub) and draw new strokes with a tablet or mouse that every stack corrects live "
      "(press h in the window for the keys)");
  // Overrides are positional key.path=value, as for `run` and `vr`.
  cmd->add_option("files", *positional,
                  "An experiment or stack config (default: one freehand stack), a recording to replay "
                  "(.jsonl), and config overrides key.path=value, in any order")
      ->type_name("[CONFIG.yaml] [RECORDING.jsonl] [key.path=value ...]");
  cmd->add_option("--record", o->record,
                  "Live recording to write (append + flush per event; default "
                  "sketchlab-live-<UTC time>.jsonl)");
  cmd->add_flag("--overwrite", o->overwrite, "Replace an existing live recording file");
  cmd->add_option("--save", o->save, "Where `s` saves the events so far (default <record>-saved.jsonl)");
  cmd->add_option("--export-dir", o->export_dir,
                  "Directory for `j` (sketch JSON), `e` (PLY/OBJ/.mlp) and `p` (screenshots)")
      ->capture_default_str();
  cmd->add_option("--size", *size, "Window size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--multisamples", o->multisamples, "Antialiasing samples (0: off)")
      ->capture_default_str();
  cmd->add_flag("--play", o->play, "Start playing the recording");
  cmd->add_option("--play-interval", o->play_interval, "Seconds per stroke while playing")
      ->capture_default_str();
  cmd->add_option("--at", *at, "Start the replay after this many strokes");
  cmd->add_option("--plugin-dir", o->plugin_dirs, "Extra plugin directory (repeatable)");
  cmd->callback([o, positional, size, at, &exit_code] {
    static const std::regex pattern(R"((\d{2,5})x(\d{2,5}))");
    std::smatch m;
    if (!std::regex_match(*size, m, pattern))
      throw std::runtime_error("--size " + *size + ": expected WIDTHxHEIGHT, e.g. 1280x720");
    o->width = std::stoi(m[1]);
    o->height = std::stoi(m[2]);
    for (const std::string& f : *positional) {
      const std::filesystem::path p = f;
      if (f.find('=') != std::string::npos) {
        o->overrides.push_back(f);
        continue;
      }
      if (!std::filesystem::is_regular_file(p))
        throw std::runtime_error("view: " + f + ": no such file (expected CONFIG.yaml, RECORDING.jsonl or key.path=value)");
      if (p.extension() == ".jsonl") {
        if (o->recording) throw std::runtime_error("view: two recordings given");
        o->recording = p;
      } else {
        if (!o->config.empty()) throw std::runtime_error("view: two configs given");
        o->config = p;
      }
    }
    if (*at >= 0) o->at_stroke = static_cast<std::size_t>(*at);
    exit_code = desktop::run_view(*o);
  });
}

}  // namespace sketchlab::cli
