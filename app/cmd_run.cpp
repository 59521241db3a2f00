// `sketchlab run [EXPERIMENT.yaml] [key.path=value ...]`: replay each
// recording through each stack (and sweep point) and write the results.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "default_paths.hpp"
#include "plugin_arguments.hpp"
#include "progress_line.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/experiment_runner.hpp"
#include "mpi_run.hpp"
#ifdef SKETCHLAB_HAVE_VIEWER
#include "sketchlab/viewer/display.hpp"
#include "sketchlab/viewer/export_gltf.hpp"
#include "sketchlab/viewer/render_png.hpp"
#endif

namespace sketchlab::cli {
namespace {

struct RunCommandOptions {
  std::string experiment;
  std::vector<std::string> overrides;
  bool no_timings = false;
  int jobs = 0;
  std::string resume;
  double rank_timeout_s = 60.0;
};

Renderer make_renderer() {
#ifdef SKETCHLAB_HAVE_VIEWER
  return [](const std::filesystem::path& png,
            const std::vector<std::pair<std::string, const Sketch*>>& panels) {
    std::vector<viewer::Panel> vp;
    std::vector<const Sketch*> sketches;
    for (const auto& [title, sketch] : panels) {
      vp.push_back({title, sketch, nullptr,
                    std::to_string(sketch->network.curves().size()) + " curves, " +
                        std::to_string(sketch->network.nodes().size()) + " nodes, " +
                        std::to_string(sketch->network.patches().size()) + " patches"});
      sketches.push_back(sketch);
    }
    // Rows of at most three 720-pixel panels: readable at the report's full
    // width; curves coloured by their deviation from the input stroke, with
    // a colour bar and a scale bar.
    const int n = static_cast<int>(vp.size()), columns = std::min(n, 3);
    const int width = 720 * columns, height = 720 * ((n + columns - 1) / columns);
    const auto camera = viewer::fit_camera(sketches, viewer::ViewDirection::iso, 1.0);
    viewer::SceneStyle style;
    style.colour_by_deviation = true;
    style.show_scale_bar = true;
    viewer::render_png(vp, camera, width, height, png, style, columns);
  };
#else
  return {};
#endif
}

SceneExporter make_scene_exporter() {
#ifdef SKETCHLAB_HAVE_VIEWER
  return [](const Sketch& sketch) { return viewer::sketch_to_gltf(sketch); };
#else
  return {};
#endif
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "run", "Replay each recording of an experiment through each stack and sweep point, in "
             "parallel, and write sketches, statistics, meshes, pictures and a report");
  auto opts = std::make_shared<RunCommandOptions>();
  cmd->add_option("experiment", opts->experiment,
                  "Experiment YAML (default: the bundled configs/default.yaml)");
  cmd->add_option("overrides", opts->overrides,
                  "Overrides key.path=value, e.g. outputs.dir=/tmp/out "
                  "stacks.0.corrector.params.delta=0.03");
  cmd->add_flag("--no-timings", opts->no_timings,
                "Write latencies and times as 0 so repeated runs give byte-identical files");
  cmd->add_option("-j,--jobs", opts->jobs,
                  "Cases run in parallel (per rank under MPI; default: one per core the process may use)")
      ->check(CLI::Range(0, 256));
  cmd->add_option("--resume", opts->resume,
                  "Finish the run in this run folder: run only its cases without a result "
                  "(case_result.json); the experiment defaults to the folder's config.yaml")
      ->check(CLI::ExistingDirectory);
#ifdef SKETCHLAB_HAVE_MPI
  cmd->add_option("--rank-timeout", opts->rank_timeout_s,
                  "Under MPI: seconds without a word from a rank before it counts as dead (ranks on "
                  "rank 0's host are also checked directly)")
      ->check(CLI::Range(1.0, 1e6));
#endif
  cmd->callback([opts, &exit_code] {
    std::vector<Override> overrides;
    std::string experiment = opts->experiment;
    // CLI11 cannot tell an override from the experiment path: a first
    // positional containing '=' is an override.
    if (experiment.find('=') != std::string::npos) {
      opts->overrides.insert(opts->overrides.begin(), experiment);
      experiment.clear();
    }
    for (const auto& o : opts->overrides) overrides.push_back(parse_override(o));
    const auto path = !experiment.empty()      ? std::filesystem::path(experiment)
                      : !opts->resume.empty() ? std::filesystem::path(opts->resume) / "config.yaml"
                                              : default_experiment();
    const ExperimentConfig config = load_experiment(path, overrides);

    PluginHost host;
    load_plugins(host);

    ProgressLine progress(std::cerr, isatty(fileno(stderr)) != 0);
    RunOptions options;
    options.jobs = opts->jobs;
    options.timings = !opts->no_timings;
    options.progress = [&progress](const Progress& p) { progress.update(p); };
    options.renderer = make_renderer();
    // Debian's VTK 9.1 is built for X alone (no EGL, no OSMesa): its
    // offscreen windows still need a display, so without one there are no
    // pictures, and the run says so up front instead of after the cases.
#ifdef SKETCHLAB_HAVE_VIEWER
    if (config.outputs.pictures) options.pictures_unavailable = viewer::display_problem();
#else
    options.pictures_unavailable = "this build has no viewer (VTK)";
#endif
    if (config.outputs.pictures && !options.pictures_unavailable.empty())
      std::cerr << "warning: no pictures: " << options.pictures_unavailable << "\n";
    options.scene_exporter = make_scene_exporter();
    options.resume_dir = opts->resume;
    std::vector<std::string> lost;  // ranks that died or could not run
#ifdef SKETCHLAB_HAVE_MPI
    std::optional<RunSummary> result;
    if (launched_by_mpi()) {
      result = run_over_mpi(config, host, options, {opts->rank_timeout_s}, progress, lost);
      if (!result) return;  // not rank 0: rank 0 reports
    } else {
      result = run_experiment(config, host, options);
    }
    const RunSummary& summary = *result;
#else
    if (launched_by_mpi())
      std::cerr << "warning: this sketchlab was built without MPI (SKETCHLAB_WITH_MPI): each rank runs the "
                   "whole experiment into a folder of its own\n";
    const RunSummary summary = run_experiment(config, host, options);
#endif
    progress.finish();
    // Pictures that failed while drawing (noted in the report too).
    for (const auto& note : summary.provenance.notes)
      if (note.rfind("no pictures:", 0) != 0) std::cerr << "warning: " << note << "\n";

    for (const auto& c : summary.cases)
      if (!c.ok)
        std::cerr << ("FAILED " + c.recording.stem().string() + " x " + c.variant.stack.name + ": " + c.error + "\n");
    std::cout << (summary.cases.size() - summary.failed()) << " of " << summary.cases.size()
              << " cases done";
    if (summary.failed()) std::cout << ", " << summary.failed() << " failed";
    std::cout << "; results in " << summary.run_dir.string() << "\n";
    if (config.outputs.report)
      std::cout << "report: " << (summary.run_dir / "report.html").string() << "\n";
    // One write per line: under mpirun, stderr is forwarded write by write,
    // so a line written in pieces could be split by the stdout lines above.
    for (const auto& l : lost) std::cerr << ("LOST " + l + "\n");
    exit_code = summary.failed() || !lost.empty() ? 1 : 0;
#ifdef SKETCHLAB_HAVE_MPI
    end_mpi_job(lost, exit_code);
#endif
  });
}

}  // namespace sketchlab::cli
