// `sketchlab convert`: import CASSIE sessions as recordings, export sketches
// to PLY/OBJ for MeshLab.
#include <iostream>
#include <string>

#include "commands.hpp"
#include "sketchlab/io/mesh_export.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/recording/recording_writer.hpp"

namespace sketchlab::cli {
namespace {

struct CassieOptions {
  std::string history, raw, output;
  bool overwrite = false;
};

struct ExportOptions {
  std::string sketch, output;
  double spacing = 0.005;
};

// <dataset>/sketch_history/<name>.json -> <dataset>/raw_data/<name>.json
std::filesystem::path raw_data_beside(const std::filesystem::path& history) {
  return history.parent_path().parent_path() / "raw_data" / history.filename();
}

}  // namespace

void add_convert_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("convert", "Import recordings and export sketches");
  cmd->require_subcommand(1);

  auto co = std::make_shared<CassieOptions>();
  auto* cassie = cmd->add_subcommand(
      "cassie", "Import a CASSIE dataset session (sketch_history + raw_data JSON) as a recording");
  cassie->add_option("sketch_history", co->history, "CASSIE sketch_history/<session>.json")
      ->required()
      ->check(CLI::ExistingFile);
  cassie->add_option("--raw", co->raw,
                     "CASSIE raw_data/<session>.json (default: ../raw_data/ beside sketch_history)");
  cassie->add_option("-o,--output", co->output, "Recording to write (.jsonl)")->required();
  cassie->add_flag("--overwrite", co->overwrite, "Replace the output if it exists");
  cassie->callback([co, &exit_code] {
    if (!co->overwrite && std::filesystem::exists(co->output))
      throw std::runtime_error(co->output + ": already exists; pass --overwrite to replace it");
    const std::filesystem::path history(co->history);
    const auto raw = co->raw.empty() ? raw_data_beside(history) : std::filesystem::path(co->raw);
    std::vector<std::string> warnings;
    const Recording rec = import_cassie(history, raw, history.stem().string(), &warnings);
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    write_recording(co->output, rec, co->overwrite);
    std::size_t strokes = 0;
    for (const auto& e : rec.events) strokes += std::holds_alternative<StrokeEvent>(e.payload);
    std::cout << co->output << ": " << rec.events.size() << " events, " << strokes << " strokes\n";
    exit_code = 0;
  });

  auto eo = std::make_shared<ExportOptions>();
  auto* exp = cmd->add_subcommand(
      "export", "Export a sketch (JSON written by `run`) as PLY or OBJ: curves as polylines, patches as faces");
  exp->add_option("sketch", eo->sketch, "sketch.json")->required()->check(CLI::ExistingFile);
  exp->add_option("-o,--output", eo->output, "Output file, .ply or .obj")->required();
  exp->add_option("--spacing", eo->spacing,
                  "Polyline sample spacing along curves (m); at most " +
                      std::to_string(kMaxPointsPerExportedCurve) + " points per curve (spread evenly over a longer one)")
      ->check(CLI::Range(1e-5, 1.0));
  exp->callback([eo, &exit_code] {
    const std::filesystem::path out(eo->output);
    const std::string ext = out.extension().string();
    if (ext != ".ply" && ext != ".obj")
      throw std::runtime_error("--output " + eo->output + ": extension must be .ply or .obj");
    const Sketch sketch = read_sketch_json(eo->sketch);
    write_text_file(out, ext == ".ply" ? network_to_ply(sketch.network, eo->spacing)
                                       : network_to_obj(sketch.network, eo->spacing));
    std::cout << eo->output << ": " << sketch.network.curves().size() << " curves, "
              << sketch.network.patches().size() << " patches\n";
    exit_code = 0;
  });
}

}  // namespace sketchlab::cli
