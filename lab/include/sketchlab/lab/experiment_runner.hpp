#pragma once
// Runs an experiment: every (recording, stack, sweep point) is an independent
// case, run in parallel; outputs are deterministic (same config, same bytes,
// timings aside).
//
// Run folder <outputs.dir>/<experiment>[-<UTC timestamp>][-N]/ (-N when the
// name is taken: a run never writes into an existing folder) holds:
//   config.yaml                   the resolved experiment, recordings relative
//                                 to the folder (run it again to repeat)
//   provenance.yaml               build, commit, plugins, input hashes (provenance.hpp)
//   <recording>/<stack>/          per case: case.yaml (the resolved stack,
//                                 every parameter, defaults included, headed
//                                 by its provenance),
//                                 sketch.json, strokes.csv,
//                                 curves.ply, raw_strokes.ply, nodes.ply,
//                                 patches.ply, sketch.obj (as enabled)
//   <recording>/<recording>.mlp   MeshLab project with every layer of every stack
//   <recording>/side_by_side.png  the cases' final sketches side by side (when a
//                                 renderer is given; drawn from memory, so
//                                 also without sketch.json)
//   <recording>/<stack>/scene.gltf the case's final sketch as glTF 2.0 (when a
//                                 scene exporter is given and the report is on;
//                                 the report's 3D views show it)
//   metrics.csv, metrics.json, report.html
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/metrics.hpp"
#include "sketchlab/lab/provenance.hpp"
#include "sketchlab/lab/stack.hpp"

namespace sketchlab {

struct CaseResult {
  std::filesystem::path recording;
  SweepCase variant;  // its stack resolved (resolve_stack): every parameter
  std::filesystem::path dir;  // the case's output folder
  bool ok = false;
  std::string error;  // why the case failed
  CaseMetrics metrics;
  std::vector<double> stroke_latency_ms;  // per corrected stroke, in order
  double wall_ms = 0.0;
};

struct Progress {
  std::size_t done = 0, total = 0;
  std::string current;  // label of a case just started or finished
  double elapsed_s = 0.0;
};

// A picture of several sketches side by side, same camera: (title, sketch).
using Renderer = std::function<void(const std::filesystem::path& png,
                                    const std::vector<std::pair<std::string, const Sketch*>>& panels)>;

// A sketch as a glTF 2.0 document (JSON, buffers inline), for the report's
// 3D views; throws std::exception on failure (the case keeps its other files).
using SceneExporter = std::function<std::string(const Sketch& sketch)>;

struct RunOptions {
  int jobs = 0;         // worker threads; 0 = hardware concurrency
  bool timings = true;  // false: latencies written as 0 (byte-identical reruns)
  std::function<void(const Progress&)> progress;  // called from worker threads, serialised
  Renderer renderer;    // used when outputs.pictures is set; may be empty
  // Why pictures cannot be drawn (no viewer in this build, no X display), if
  // so: with outputs.pictures set, it becomes a note of the run (terminal,
  // report, provenance.yaml) and the renderer is not called.
  std::string pictures_unavailable;
  SceneExporter scene_exporter;  // used when outputs.report is set; may be empty
};

struct RunSummary {
  std::filesystem::path run_dir;
  std::vector<CaseResult> cases;  // recordings x variants, in config order
  double wall_s = 0.0;
  RunProvenance provenance;  // notes include pictures not drawn, and why
  std::size_t failed() const;
};

// Resolves and validates every case first (sweep, plugin names, parameter
// names and values: ConfigError naming file:line and the allowed values) and
// hashes the inputs; only then creates the run folder, so an experiment that
// cannot run writes nothing. Failures while a case runs (plugin errors, bad
// recordings) are reported in its CaseResult.
RunSummary run_experiment(const ExperimentConfig& config, const PluginHost& host,
                          const RunOptions& options);

}  // namespace sketchlab
