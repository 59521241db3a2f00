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
//   <recording>/<stack>/case_result.json  the case's record, written last
//                                 (case_result_json.hpp): a case with one is
//                                 finished, and --resume keeps it
//   metrics.csv, metrics.json, report.html
//
// The work is split in three so that a distributed run (app/mpi_run.cpp) can
// put the cases on other processes: plan_run, run_case for each pending
// case (thread-safe), finish_run. run_experiment does all three with threads.
#include <filesystem>
#include <functional>
#include <optional>
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
  std::size_t done = 0, total = 0;  // done counts failed cases too
  std::size_t failed = 0;
  std::size_t resumed = 0;  // of `done`, finished before this run (--resume): not in the ETA
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
  // Set: resume this existing run folder instead of creating one. Its cases
  // with a case_result.json are kept as they are; the others are run. The
  // experiment must be the one the folder was made from (its config.yaml),
  // or be that config.yaml itself.
  std::filesystem::path resume_dir;
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

// A run resolved and validated, its folder made, and what is left to do.
struct RunPlan {
  ExperimentConfig config;
  RunSummary summary;  // run_dir, provenance, every case (finished ones with their results)
  std::vector<std::size_t> pending;  // indices into summary.cases still to run, in order
  bool pictures = false;  // side_by_side.png per recording (outputs.pictures and a renderer)
  bool scenes = false;    // scene.gltf per case (outputs.report and a scene exporter)
};

// Validates as run_experiment does, then, when `create` is true, creates the
// run folder (or takes options.resume_dir, reading its finished cases) and
// writes config.yaml. With `create` false it only reads what it needs:
// `run_dir` must be the folder another process created for the same
// experiment (ranks of a distributed run), and `pending` lists every case.
// Throws ConfigError / std::runtime_error naming the file or folder at fault.
RunPlan plan_run(const ExperimentConfig& config, const PluginHost& host, const RunOptions& options,
                 bool create = true, const std::filesystem::path& run_dir = {});

// Runs case `index` of `plan` and writes its files (scene.gltf included),
// case_result.json last (written whole or not at all). Thread-safe.
// Failures are in the result. `final_sketch`, when not null, receives what
// the pictures show of the final sketch (when plan.pictures; else left
// empty).
CaseResult run_case(const RunPlan& plan, std::size_t index, const PluginHost& host,
                    const RunOptions& options, std::optional<Sketch>* final_sketch = nullptr);

// Stores `result` (from run_case, maybe on another process) as case `index`.
void set_case_result(RunPlan& plan, std::size_t index, CaseResult result);

// Once every case has its result: the MeshLab projects, the pictures
// (`sketches[i]` of case i; for finished cases of a resumed run without one,
// read back from their sketch.json, without raw strokes), the report and
// provenance.yaml. Call on the main thread (the renderer uses VTK).
RunSummary finish_run(RunPlan plan, std::vector<std::optional<Sketch>> sketches, const PluginHost& host,
                      const RunOptions& options, double wall_s);

}  // namespace sketchlab
