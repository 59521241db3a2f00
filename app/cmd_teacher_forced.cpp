// `sketchlab teacher-forced RECORDING --corrector NAME [--param k=v ...]
// [--track cassie] [--csv out.csv] [--cassie-logs DIR [--no-patches]]`: corrects every stroke of a recording on
// the sketch rebuilt from a reference track and compares with the reference.
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <stdexcept>
#include <iostream>

#include "commands.hpp"
#include "plugin_arguments.hpp"
#include "reference_patches.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/teacher_forced.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording_reader.hpp"

namespace sketchlab::cli {
namespace {

struct TeacherForcedCliOptions {
  std::string recording;
  std::string corrector;
  std::vector<std::string> params;
  std::string track = "cassie";
  std::string csv;
  double snap_tolerance = 1e-4;
  std::string cassie_logs;
  bool no_patches = false;
};

void print_distribution(const std::string& name, const Distribution& d, double unit, const char* u) {
  std::cout << name << "_median " << d.median * unit << " " << u << "\n"
            << name << "_p90 " << d.p90 * unit << " " << u << "\n"
            << name << "_max " << d.max * unit << " " << u << "\n";
}

}  // namespace

void add_teacher_forced_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "teacher-forced",
      "Correct each stroke of a recording on the sketch rebuilt from a reference track and compare "
      "with the reference curve (endpoint distance, deviation, endpoint snaps)");
  auto o = std::make_shared<TeacherForcedCliOptions>();
  cmd->add_option("recording", o->recording, "Recording (.jsonl) with a reference track")->required();
  cmd->add_option("--corrector", o->corrector, "Corrector plugin name")->required();
  cmd->add_option("--param", o->params, "Corrector parameter key=value (repeatable)");
  cmd->add_option("--track", o->track, "Reference track (default cassie)");
  cmd->add_option("--csv", o->csv, "Write one row per stroke to this CSV file");
  cmd->add_option("--snap-tolerance", o->snap_tolerance,
                  "Distance (m) under which an endpoint counts as snapped (default 1e-4)");
  cmd->add_option("--cassie-logs", o->cassie_logs,
                  "CASSIE's raw_data directory: the patches CASSIE had at each stroke (allCreatedPatches, "
                  "meshed by the soapfilm surfacer) are rebuilt too");
  cmd->add_flag("--no-patches", o->no_patches, "With --cassie-logs: do not rebuild CASSIE's patches");
  cmd->callback([o, &exit_code] {
    std::map<std::string, ParamValue> params;
    PluginHost host;
    load_plugins(host);
    const LoadedPlugin* plugin = host.find(PluginKind::corrector, o->corrector);
    if (plugin) params = parse_param_arguments(*plugin, o->params);
    const auto corrector = host.make_corrector(o->corrector, params);
    const Recording rec = read_recording(o->recording);
    TeacherForcedOptions opt;
    opt.track = o->track;
    opt.snap_tolerance = o->snap_tolerance;
    std::shared_ptr<Surfacer> surfacer;
    if (!o->cassie_logs.empty() && !o->no_patches) surfacer = reference_patch_surfacer(host, "soapfilm");
    const std::string session = std::filesystem::path(o->recording).stem().string();
    if (surfacer) {
      opt.surfacer = surfacer.get();
      opt.patches = cassie_reference_patches(rec, o->cassie_logs, session);
      // No patch: a session without any, or another export given by mistake
      // (the stroke logs tell them apart; read only then).
      if (opt.patches.empty()) cassie_constraint_logs(rec, o->cassie_logs, session, "CASSIE's patches");
    }
    std::vector<TeacherForcedStroke> strokes;
    std::vector<std::string> warnings;
    try {
      strokes = teacher_forced(rec, *corrector, opt, &warnings);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(o->recording + ": " + e.what() + " (--track chooses one)");
    }
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    if (!o->csv.empty()) write_text_file(o->csv, teacher_forced_csv(strokes));
    const TeacherForcedSummary s = summarize(strokes);
    std::cout << "strokes " << s.strokes << "\ncompared " << s.compared << "\nerrors " << s.errors << "\n";
    if (surfacer) std::cout << "patches " << opt.patches.size() << "\npatches_left_out " << warnings.size() << "\n";
    print_distribution("endpoint_distance", s.endpoint_distance, 1000.0, "mm");
    print_distribution("mean_deviation", s.mean_deviation, 1000.0, "mm");
    print_distribution("max_deviation", s.max_deviation, 1000.0, "mm");
    // Curve to the stroke's samples, both ways: not measured on strokes of pixels.
    if (s.output_stroke_distance.count) {
      print_distribution("output_stroke_distance", s.output_stroke_distance, 1000.0, "mm");
      print_distribution("reference_stroke_distance", s.reference_stroke_distance, 1000.0, "mm");
    }
    std::cout << "snap_agreement " << 100.0 * s.snap_agreement() << " %\n"
              << "snap_kind_agreement " << 100.0 * s.snap_kind_agreement() << " %\n"
              << "reference_snaps " << s.reference_snaps << " of " << s.endpoints << " endpoints\n"
              << "output_snaps " << s.output_snaps << "\nboth_snaps " << s.both_snaps << "\n"
              << "snap_recall " << 100.0 * s.snap_recall() << " %\n"
              << "snap_precision " << 100.0 * s.snap_precision() << " %\n"
              << "kind_agreement " << 100.0 * s.line_agreement() << " %\n";
    print_distribution("latency", s.latency_ms, 1.0, "ms");
    print_distribution("cpu", s.cpu_ms, 1.0, "ms");
    exit_code = 0;
  });
}

}  // namespace sketchlab::cli
